#include "app/probe/call_table.h"

#include "app/probe/render_calls.h"
#include "grading/10_path_tracing/path_tracing_calls.h"
#include "grading/11_surface_detail/surface_detail_calls.h"
#include "grading/1_vectors/vector_calls.h"
#include "grading/2_rays/ray_calls.h"
#include "grading/3_intersect/intersect_calls.h"
#include "grading/4_accel/accel_calls.h"
#include "grading/5_transforms/transform_calls.h"
#include "grading/6_shading/shading_calls.h"
#include "grading/7_recursion/recursion_calls.h"
#include "grading/8_sampling/sampling_calls.h"
#include "grading/9_refraction/refraction_calls.h"

namespace raystep::probe {

CallTable stage_calls() {
    CallTable table;
    add_calls(table, vector_calls);          // stage 1
    add_calls(table, ray_calls);             // stage 2
    add_calls(table, intersect_calls);       // stage 3
    add_calls(table, accel_calls);           // stage 4: a structure's answers, no work counted
    add_calls(table, transform_calls);       // stage 5
    add_calls(table, shading_calls);         // stage 6
    add_calls(table, recursion_calls);       // stage 7
    add_calls(table, sampling_calls);        // stage 8
    add_calls(table, refraction_calls);      // stage 9
    add_calls(table, path_tracing_calls);    // stage 10
    add_calls(table, surface_detail_calls);  // stage 11
    add_call(table, render_call);            // whole images, through every stage a view needs
    return table;
}

}  // namespace raystep::probe
