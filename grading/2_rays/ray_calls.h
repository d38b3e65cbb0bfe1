#pragma once

// Stage 2 calls: points along rays, cameras and their rays. A camera call makes the camera and
// the rays of the pixels asked for, so that one call covers a whole image's worth of checks.

#include <tuple>
#include <vector>

#include "app/probe/probe_call.h"
#include "stages/2_rays/camera.h"

namespace raystep::probe {

/// A pixel (i, j), [i, j] in JSON.
using PixelIndex = std::tuple<int, int>;

struct RayAtQuestion {
    Ray ray;
    double t = 0.0;
};

struct PerspectiveRaysQuestion {
    Vec3 lookfrom, lookat, up;
    double fovy = 0.0;
    int width = 0, height = 0;
    std::vector<PixelIndex> pixels;
};

struct OrthographicRaysQuestion {
    Vec3 lookfrom, lookat, up;
    double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
    int width = 0, height = 0;
    std::vector<PixelIndex> pixels;
};

template <>
struct JsonFields<RayAtQuestion> {
    static constexpr auto list =
        std::make_tuple(json_field("ray", &RayAtQuestion::ray), json_field("t", &RayAtQuestion::t));
};

template <>
struct JsonFields<PerspectiveRaysQuestion> {
    using Q = PerspectiveRaysQuestion;
    static constexpr auto list = std::make_tuple(
        json_field("lookfrom", &Q::lookfrom), json_field("lookat", &Q::lookat),
        json_field("up", &Q::up), json_field("fovy", &Q::fovy), json_field("width", &Q::width),
        json_field("height", &Q::height), json_field("pixels", &Q::pixels));
};

template <>
struct JsonFields<OrthographicRaysQuestion> {
    using Q = OrthographicRaysQuestion;
    static constexpr auto list =
        std::make_tuple(json_field("lookfrom", &Q::lookfrom), json_field("lookat", &Q::lookat),
                        json_field("up", &Q::up), json_field("left", &Q::left),
                        json_field("right", &Q::right), json_field("bottom", &Q::bottom),
                        json_field("top", &Q::top), json_field("width", &Q::width),
                        json_field("height", &Q::height), json_field("pixels", &Q::pixels));
};

/// The rays of the pixels asked for, made after the camera, so that a camera that cannot be
/// made throws even when no pixel is asked.
template <class Camera, class MakeRay>
std::vector<Ray> pixel_rays(const Camera& camera, const std::vector<PixelIndex>& pixels,
                            MakeRay make_ray) {
    std::vector<Ray> rays;
    for (const auto& [i, j] : pixels)
        rays.push_back(make_ray(camera, i, j));
    return rays;
}

inline constexpr ProbeCall<RayAtQuestion, Vec3> ray_at_call{
    "ray_at", [](const RayAtQuestion& q) { return q.ray.at(q.t); }};

inline constexpr ProbeCall<PerspectiveRaysQuestion, std::vector<Ray>> perspective_rays_call{
    "perspective_rays", [](const PerspectiveRaysQuestion& q) {
        const PerspectiveCamera camera =
            make_perspective_camera(q.lookfrom, q.lookat, q.up, q.fovy, q.width, q.height);
        return pixel_rays(camera, q.pixels, perspective_ray);
    }};

inline constexpr ProbeCall<OrthographicRaysQuestion, std::vector<Ray>> orthographic_rays_call{
    "orthographic_rays", [](const OrthographicRaysQuestion& q) {
        const OrthographicCamera camera = make_orthographic_camera(
            q.lookfrom, q.lookat, q.up, q.left, q.right, q.bottom, q.top, q.width, q.height);
        return pixel_rays(camera, q.pixels, orthographic_ray);
    }};

inline constexpr auto ray_calls =
    std::make_tuple(ray_at_call, perspective_rays_call, orthographic_rays_call);

}  // namespace raystep::probe
