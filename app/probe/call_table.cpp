#include "app/probe/call_table.h"

namespace raystep::probe {

CallTable stage_calls() {
    CallTable table;
    add_vector_calls(table);
    add_ray_calls(table);
    add_intersect_calls(table);
    add_accel_calls(table);
    add_transform_calls(table);
    add_shading_calls(table);
    add_recursion_calls(table);
    add_sampling_calls(table);
    add_refraction_calls(table);
    add_render_calls(table);
    return table;
}

}  // namespace raystep::probe
