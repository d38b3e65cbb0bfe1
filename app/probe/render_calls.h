#pragma once

// Whole images: a scene rendered in one view through every stage the view needs, at most
// `max_width` pixels wide (the scene's own size scaled down, aspect kept), on one thread so that
// a probe's CPU time is its own work; its camera rays cut to [camera_t_min, camera_t_max], its
// random numbers seeded by `seed`, its eye moved to `lookfrom` and its samples per pixel
// `samples_per_pixel` when they are given.

#include <cstdint>
#include <optional>
#include <string>

#include "app/probe/probe_call.h"
#include "app/protocol/image_json.h"

namespace raystep::probe {

struct RenderQuestion {
    std::string scene;  ///< the scene file's path
    std::string view;   ///< a view's name, as `raystep render --view` takes it
    int max_width = 0;
    std::optional<std::uint64_t> seed;
    std::optional<double> camera_t_min;
    std::optional<double> camera_t_max;
    std::optional<Vec3> lookfrom;          ///< in place of the scene's eye
    std::optional<int> samples_per_pixel;  ///< in place of the scene's `spp`
};

template <>
struct JsonFields<RenderQuestion> {
    using Q = RenderQuestion;
    static constexpr auto list = std::make_tuple(
        json_field("scene", &Q::scene), json_field("view", &Q::view),
        json_field("max_width", &Q::max_width), json_field("seed", &Q::seed),
        json_field("camera_t_min", &Q::camera_t_min), json_field("camera_t_max", &Q::camera_t_max),
        json_field("lookfrom", &Q::lookfrom),
        json_field("samples_per_pixel", &Q::samples_per_pixel));
};

/// The render the question asks for, by the renderer over this build's stages.
Image render_for_probe(const RenderQuestion& question);

inline constexpr ProbeCall<RenderQuestion, Image> render_call{"render", &render_for_probe};

}  // namespace raystep::probe
