#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/pixel_observer.h"
#include "renderer/render_scene.h"

namespace raystep {

/// A light as a trace names it: "point light (line 12)".
std::string light_name(const char* kind, std::uint32_t line);

/// The lines `raystep trace` prints for one pixel: each step the renderer tells (pixel_observer.h)
/// as one line, in the order it took them, numbers as base/math/to_text.h prints them, so that the
/// traces of two builds can be compared line by line. Around the steps the printer adds what a
/// reader needs to see why a pixel is wrong, worked out here from the scene so that a render never
/// pays for it: every primitive the eye ray is tested against, what blocks a shadow ray, each
/// light's diffuse and specular parts, and the path through transmitting surfaces.
class TracePrinter final : public PixelObserver {
  public:
    /// Prints the steps of a pixel of `render_scene` at the end of `lines`, which outlives the
    /// printer: a stub that stops the render leaves the lines it reached.
    TracePrinter(const RenderScene& render_scene, std::vector<std::string>& lines)
        : render_scene_(render_scene), lines_(lines) {}

    bool sample_starts(int index, const Vec2& film_point) override;
    void sample_ends(int index, const Color& colour) override;
    void pixel_mean(int samples, const Color& colour) override;
    void camera_ray(const Ray& ray) override;
    void hit_search_starts(const Ray& ray) override;
    void closest_hit(const Ray& ray, const std::optional<PrimitiveHit>& hit,
                     const TraversalStats& cost) override;
    void quad_light_seen(const SeenQuadLight& seen) override;
    void surface(const SurfacePoint& point, const Material& material) override;
    void light(const LightStep& step) override;
    void spot_light_outside_cone(std::uint32_t line) override;
    void quad_light_starts(const QuadLight& light) override;
    void quad_light_sample(int index, const Ray& shadow_ray, bool blocked) override;
    void quad_light_ends(const QuadLight& light, const Color& term, int shadow_rays) override;
    void local_colour(const std::vector<LightSample>& reaching, const Color& colour) override;
    void later_ray(int index, const Ray& ray, const std::optional<PrimitiveHit>& hit) override;
    void path_ray(int index, const Ray& ray, const std::optional<PrimitiveHit>& hit,
                  const SeenQuadLight* light) override;
    void path_shadow_ray(const Ray& ray, bool blocked) override;
    void recursion_colour(const Ray& eye_ray, const Color& colour) override;

  private:
    void add(std::string line) { lines_.push_back(std::move(line)); }

    const RenderScene& render_scene_;
    std::vector<std::string>& lines_;
    // The hit being shaded, and the names of its lights that reach it, in order
    SurfacePoint point_{};
    std::optional<Material> material_;  ///< a copy: shading may hand in a mapped one
    std::vector<std::string> reaching_;
};

}  // namespace raystep
