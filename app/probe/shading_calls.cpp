// Stage 6 calls: lights, the local model, and rays that leave a surface.

#include "app/probe/call_table.h"
#include "stages/6_shading/shading.h"

namespace raystep::probe {

void add_shading_calls(CallTable& table) {
    table["attenuation"] = [](const Json& a) {
        return number(attenuation(attenuation_from(a.at(0)), number_from(a.at(1))));
    };
    table["sample_point_light"] = [](const Json& a) {
        return light_sample(sample_light(point_light_from(a.at(0)), vec3_from(a.at(1))));
    };
    table["sample_directional_light"] = [](const Json& a) {
        return light_sample(sample_light(directional_light_from(a.at(0))));
    };
    table["blinn_phong"] = [](const Json& a) {
        return vec3(blinn_phong(material_from(a.at(0)), surface_point_from(a.at(1)),
                                light_sample_from(a.at(2))));
    };
    table["local_shading"] = [](const Json& a) {
        std::vector<LightSample> lights;
        for (const Json& l : a.at(2))
            lights.push_back(light_sample_from(l));
        return vec3(local_shading(material_from(a.at(0)), surface_point_from(a.at(1)), lights));
    };
    table["spawn_ray"] = [](const Json& a) {
        return ray(spawn_ray(surface_point_from(a.at(0)), vec3_from(a.at(1)), number_from(a.at(2)),
                             ray_offset_from(a.at(3))));
    };
    table["shadow_ray"] = [](const Json& a) {
        return ray(shadow_ray(surface_point_from(a.at(0)), light_sample_from(a.at(1)),
                              ray_offset_from(a.at(2))));
    };
}

}  // namespace raystep::probe
