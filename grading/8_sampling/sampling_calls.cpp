#include "grading/8_sampling/sampling_calls.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace raystep::probe {

namespace {

// One answer per stream of the question, each from RandomStream(seed, stream).
template <class Question, class PerStream>
auto per_stream(const Question& q, PerStream answer) {
    std::vector<decltype(answer(std::declval<RandomStream&>()))> answers;
    for (const std::uint64_t stream : q.streams) {
        RandomStream random(q.seed, stream);
        answers.push_back(answer(random));
    }
    return answers;
}

// `occluded` that also writes each ray it is asked about, and its answer, into `traced`.
OccludedFunction recording(const OccludedFunction& occluded, std::vector<TracedShadowRay>& traced) {
    return [&occluded, &traced](const Ray& shadow) {
        const bool blocked = occluded(shadow);
        traced.push_back({shadow, blocked});
        return blocked;
    };
}

}  // namespace

std::vector<Vec2> regular_samples_of(const RegularSamplesQuestion& q) {
    return regular_samples(q.strata);
}

StreamPoints jittered_samples_of(const JitteredSamplesQuestion& q) {
    return per_stream(q, [&](RandomStream& r) { return jittered_samples(q.strata, r); });
}

StreamPoints random_samples_of(const RandomSamplesQuestion& q) {
    return per_stream(q, [&](RandomStream& r) { return random_samples(q.count, r); });
}

StreamPoints samples_of(const SamplesQuestion& q) {
    return per_stream(q, [&](RandomStream& r) { return samples(q.pattern, q.count, r); });
}

std::vector<Ray> perspective_rays_through(const RaysThroughQuestion<PerspectiveCamera>& q) {
    std::vector<Ray> rays;
    for (const Vec2& film : q.films)
        rays.push_back(perspective_ray_through(q.camera, film));
    return rays;
}

std::vector<Ray> orthographic_rays_through(const RaysThroughQuestion<OrthographicCamera>& q) {
    std::vector<Ray> rays;
    for (const Vec2& film : q.films)
        rays.push_back(orthographic_ray_through(q.camera, film));
    return rays;
}

std::vector<PixelColourAnswer> pixel_colour_of(const PixelColourQuestion& q) {
    const FilmRadiance radiance = film_radiance(q.radiance);
    return per_stream(q, [&](RandomStream& r) {
        PixelColourAnswer answer;
        const FilmRadiance recorded = [&](const Vec2& film) {
            answer.films.push_back(film);
            return radiance(film);
        };
        answer.colour = pixel_colour(recorded, q.i, q.j, q.pattern, q.count, r);
        return answer;
    });
}

LightSample sample_quad_light_of(const SampleQuadLightQuestion& q) {
    return sample_quad_light(q.light, q.point, q.u, q.sample_count);
}

std::vector<QuadLightShadingAnswer> quad_light_shading_of(const QuadLightShadingQuestion& q) {
    const OccludedFunction blocked = [&](const Ray& ray) { return crosses_any(q.blockers, ray); };
    return per_stream(q, [&](RandomStream& r) {
        QuadLightShadingAnswer answer;
        answer.colour = quad_light_shading(q.material, q.point, q.light, q.pattern, q.count, r,
                                           recording(blocked, answer.shadow_rays), q.offset);
        return answer;
    });
}

std::vector<LitPixelAnswer> lit_pixel_of(const LitPixelQuestion& q) {
    const OccludedFunction nothing = [](const Ray&) { return false; };
    return per_stream(q, [&](RandomStream& r) {
        LitPixelAnswer answer;
        const FilmRadiance radiance = [&](const Vec2& film) {
            LitFilmSample sample{film, {}};
            const Color colour = quad_light_shading(
                q.material, floor_point_under(q, film), q.light, q.light_pattern, q.light_count, r,
                recording(nothing, sample.shadow_rays), q.offset);
            answer.films.push_back(std::move(sample));
            return colour;
        };
        answer.colour = pixel_colour(radiance, q.i, q.j, q.pattern, q.count, r);
        return answer;
    });
}

}  // namespace raystep::probe
