// Stage 2 calls: points along rays, cameras and their rays. A camera call makes the camera and
// the rays of the pixels asked for, so that one call covers a whole image's worth of checks.

#include "app/probe/call_table.h"
#include "stages/2_rays/camera.h"

namespace raystep::probe {

namespace {

// The rays of the pixels listed in "pixels" ([[i, j], ...]).
template <class Camera, class MakeRay>
Json pixel_rays(const Camera& camera, const Json& pixels, MakeRay make_ray) {
    Json rays = Json::array();
    for (const Json& pixel : pixels) {
        rays.push_back(ray(make_ray(camera, integer_from(pixel.at(0)), integer_from(pixel.at(1)))));
    }
    return rays;
}

}  // namespace

void add_ray_calls(CallTable& table) {
    table["ray_at"] = [](const Json& a) {
        return vec3(ray_from(a.at("ray")).at(number_from(a.at("t"))));
    };
    table["perspective_rays"] = [](const Json& a) {
        const PerspectiveCamera camera = make_perspective_camera(
            vec3_from(a.at("lookfrom")), vec3_from(a.at("lookat")), vec3_from(a.at("up")),
            number_from(a.at("fovy")), integer_from(a.at("width")), integer_from(a.at("height")));
        return pixel_rays(camera, a.at("pixels"), perspective_ray);
    };
    table["orthographic_rays"] = [](const Json& a) {
        const OrthographicCamera camera = make_orthographic_camera(
            vec3_from(a.at("lookfrom")), vec3_from(a.at("lookat")), vec3_from(a.at("up")),
            number_from(a.at("left")), number_from(a.at("right")), number_from(a.at("bottom")),
            number_from(a.at("top")), integer_from(a.at("width")), integer_from(a.at("height")));
        return pixel_rays(camera, a.at("pixels"), orthographic_ray);
    };
}

}  // namespace raystep::probe
