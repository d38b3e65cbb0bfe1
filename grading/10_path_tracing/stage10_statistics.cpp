// Stage 10's checks by distribution and by mean. The samplers take the grader's random numbers,
// so what they answer is decided; but sample_brdf turns its lobe into the world by the student's
// own frame, and path_radiance draws from its own RandomStream, so these are judged as
// distributions, and so, besides their values, are the others:
//
// - each sampler's directions, binned where the contract's density puts equal mass, against
//   that density integrated over each bin (a chi-square test, as Nori's warptest does), the
//   directions of unit length and, for the hemisphere's samplers, above it;
// - each density integrated over the sphere by the same bins: 1, and 0 below the surface;
// - a quad light's samples, mapped back to the light's square, uniform over it (chi-square),
//   each one's density that of its direction;
// - Russian roulette's weight, averaged over u on a fine grid, the throughput it was handed;
// - the mean of many paths against a closed form: the white furnace's L_e (1 + a + ... + a^d)
//   and L_e / (1 - a), and a floor under a quad light, whose radiance the grader integrates by
//   quadrature (Lambert's form factor for a diffuse floor), by every sampling and light rule.
//
// A check's false-fail rate is kCheckAlpha (stage 8's): each of its m random tests runs at
// kCheckAlpha / m; its deterministic tests never fail a right submission. The rates measured on
// the reference over many seeds, each check's power against the corpus's mutants, and the
// commands that rerun them: docs/measurements/stage10-checks.md.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/grade/data_judge.h"
#include "app/grade/value_judges.h"
#include "app/grade/value_text.h"
#include "base/math/portable_random.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/checks/statistics_seed.h"
#include "grading/10_path_tracing/path_tracing_calls.h"
#include "grading/10_path_tracing/path_tracing_oracle.h"
#include "grading/8_sampling/sample_statistics.h"
#include "grading/8_sampling/stage8_statistics.h"

namespace raystep::grade {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string p_text(double p, double alpha) {
    return "p = " + full_text(p) + " (fails below " + full_text(alpha) + ")";
}

// --- the samplers against their densities

// Bins over the sphere about an axis: bands of cos(theta) between the edges given, each cut into
// kAzimuths equal sectors. A bin's mass is integrated by `subpoints` x `subpoints` midpoints in
// (cos(theta), phi), over which solid angle is uniform; where the bands are the contract's
// quantiles, z(u) for u = k / n, the midpoints are taken in u too (z(u) at the middle of each
// step of u, weighted by |z'(u)| du there), so that a density peaked within a band (z^60 in the
// lowest of a Phong lobe's) is integrated as finely as a flat one.
constexpr int kAzimuths = 8;

struct SphereBins {
    Frame frame;                           // w the axis
    std::vector<double> edges;             // cos(theta), increasing, from -1 or 0 to 1
    std::function<double(double)> z_of_u;  // the quantile function, where the edges are its
    int subpoints = 6;
};

int bin_count(const SphereBins& bins) {
    return static_cast<int>(bins.edges.size() - 1) * kAzimuths;
}

// The bin of a unit direction, or -1 outside the bands.
int bin_of(const SphereBins& bins, const Vec3& d) {
    const double z = glm::dot(d, bins.frame.w);
    const auto band = std::upper_bound(bins.edges.begin(), bins.edges.end(), z);
    if (band == bins.edges.begin()) return -1;
    int b = static_cast<int>(band - bins.edges.begin()) - 1;
    if (b == static_cast<int>(bins.edges.size()) - 1) {
        if (z > bins.edges.back()) return -1;
        --b;  // z exactly 1
    }
    double phi = std::atan2(glm::dot(d, bins.frame.v), glm::dot(d, bins.frame.u));
    if (phi < 0) phi += 2 * kPi;
    const int sector = std::min(kAzimuths - 1, static_cast<int>(phi / (2 * kPi) * kAzimuths));
    return b * kAzimuths + sector;
}

// The midpoints of every bin, bin by bin, and the solid angle each stands for.
struct BinPoints {
    std::vector<Vec3> directions;
    std::vector<double> solid_angles;
};

// A band's cos(theta) midpoints and their widths.
std::vector<Vec2> band_steps(const SphereBins& bins, std::size_t band) {
    const int n = bins.subpoints;
    const double z0 = bins.edges[band];
    const double z1 = bins.edges[band + 1];
    std::vector<Vec2> steps;  // (z, dz)
    if (!bins.z_of_u) {
        for (int i = 0; i < n; ++i)
            steps.push_back({z0 + (i + 0.5) * (z1 - z0) / n, (z1 - z0) / n});
        return steps;
    }
    // The band's u range: its edges are z(k / bands) in some order.
    const int bands = static_cast<int>(bins.edges.size()) - 1;
    const bool rising = bins.z_of_u(0.25) < bins.z_of_u(0.75);
    const double u0 = static_cast<double>(rising ? band : bands - 1 - band) / bands;
    const double du = 1.0 / bands / n;
    for (int i = 0; i < n; ++i) {
        // dz = |z'(u)| du at the step's middle, z' by a central difference.
        const double u = u0 + (i + 0.5) * du;
        const double h = du * 1e-3;
        const double slope = (bins.z_of_u(u + h) - bins.z_of_u(u - h)) / (2 * h);
        steps.push_back({bins.z_of_u(u), std::abs(slope) * du});
    }
    return steps;
}

BinPoints bin_points(const SphereBins& bins) {
    BinPoints points;
    const int n = bins.subpoints;
    const double dphi = 2 * kPi / kAzimuths / n;
    for (std::size_t band = 0; band + 1 < bins.edges.size(); ++band) {
        const std::vector<Vec2> steps = band_steps(bins, band);
        for (int sector = 0; sector < kAzimuths; ++sector) {
            for (const Vec2& step : steps) {
                for (int j = 0; j < n; ++j) {
                    const double z = step.x;
                    const double phi = (sector * n + j + 0.5) * dphi;
                    const double r = std::sqrt(std::max(0.0, 1 - z * z));
                    points.directions.push_back(r * std::cos(phi) * bins.frame.u +
                                                r * std::sin(phi) * bins.frame.v +
                                                z * bins.frame.w);
                    points.solid_angles.push_back(step.y * dphi);
                }
            }
        }
    }
    return points;
}

// Each bin's probability under `densities` at its midpoints.
std::vector<double> bin_masses(const SphereBins& bins, const BinPoints& points,
                               const std::vector<double>& densities) {
    const int per_bin = bins.subpoints * bins.subpoints;
    std::vector<double> masses(static_cast<std::size_t>(bin_count(bins)), 0.0);
    for (std::size_t k = 0; k < densities.size(); ++k)
        masses[k / per_bin] += densities[k] * points.solid_angles[k];
    return masses;
}

// One sampler as the checks ask it: its setting, the bins its directions are counted in, the
// contract's density, and whether its directions stay above the surface (z >= 0 about w).
struct SamplerCase {
    std::string name;
    probe::SamplerSetting setting;
    SphereBins bins;
    std::function<double(const Vec3&)> density;
    bool hemisphere = true;
};

// Bands from `from` to `to` in n equal steps of cos(theta).
std::vector<double> even_edges(double from, double to, int n) {
    std::vector<double> edges;
    for (int k = 0; k <= n; ++k)
        edges.push_back(k == n ? to : from + (to - from) * k / n);
    return edges;
}

const Frame kZFrame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

// Bands over the hemisphere about z at equal steps of the contract's cumulative distribution:
// z(u) for u = k / n.
SphereBins quantile_bins(std::function<double(double)> z_of_u, int n) {
    std::vector<double> edges;
    for (int k = 0; k <= n; ++k)
        edges.push_back(z_of_u(static_cast<double>(k) / n));
    std::sort(edges.begin(), edges.end());
    edges.front() = 0.0;
    edges.back() = 1.0;
    return {kZFrame, edges, std::move(z_of_u), 6};
}

probe::SamplerSetting local_sampler(probe::Sampler sampler, double parameter = 0) {
    probe::SamplerSetting setting;
    setting.sampler = sampler;
    setting.parameter = parameter;
    return setting;
}

std::vector<SamplerCase> sampler_cases() {
    using probe::Sampler;
    constexpr int kBands = 10;
    std::vector<SamplerCase> cases;
    cases.push_back({"uniform_hemisphere", local_sampler(Sampler::uniform_hemisphere),
                     quantile_bins([](double u) { return u; }, kBands),
                     expected_uniform_hemisphere_pdf});
    cases.push_back({"cosine_hemisphere", local_sampler(Sampler::cosine_hemisphere),
                     quantile_bins([](double u) { return std::sqrt(1 - u); }, kBands),
                     expected_cosine_hemisphere_pdf});
    for (const double s : {1.0, 12.0, 60.0}) {
        cases.push_back({"phong_lobe(s " + full_text(s) + ")",
                         local_sampler(Sampler::phong_lobe, s),
                         quantile_bins([s](double u) { return std::pow(u, 1 / (s + 1)); }, kBands),
                         [s](const Vec3& d) { return expected_phong_lobe_pdf(d, s); }});
    }
    for (const double alpha : {0.15, 0.6}) {
        cases.push_back(
            {"ggx_half_vector(alpha " + full_text(alpha) + ")",
             local_sampler(Sampler::ggx_half_vector, alpha),
             quantile_bins(
                 [alpha](double u) {
                     return u >= 1 ? 0.0 : 1 / std::sqrt(1 + alpha * alpha * u / (1 - u));
                 },
                 kBands),
             [alpha](const Vec3& d) { return expected_ggx_half_vector_pdf(d, alpha); }});
    }
    // sample_brdf about a tilted normal, its directions binned over the whole sphere (they may
    // fall below the surface) about the mirror direction, the specular lobe's axis.
    const Vec3 n = glm::normalize(Vec3{0.2, -0.3, 1});
    const Vec3 wo = glm::normalize(Vec3{-1, 0.4, 0.9});
    const Vec3 mirror = 2 * glm::dot(n, wo) * n - wo;
    const Frame around_mirror = [&] {
        const Vec3 u = glm::normalize(glm::cross(Vec3{0, 1, 0}, mirror));
        return Frame{u, glm::cross(mirror, u), mirror};
    }();
    const SurfaceBrdf brdfs[] = {
        {BrdfModel::phong, Color(0.4), Color(0.4), 8.0, 0.0},
        {BrdfModel::phong, Color(0.0), Color(0.6, 0.5, 0.4), 30.0, 0.0},
        {BrdfModel::ggx, Color(0.3), Color(0.5), 0.0, 0.3},
        {BrdfModel::ggx, Color(0.0), Color(0.9), 0.0, 0.7},
    };
    for (const SurfaceBrdf& brdf : brdfs) {
        const std::string model = brdf.model == BrdfModel::phong ? "phong s " : "ggx alpha ";
        const double shape = brdf.model == BrdfModel::phong ? brdf.shininess : brdf.roughness;
        cases.push_back({"sample_brdf(" + model + full_text(shape) + ", Kd " +
                             full_text(brdf.diffuse) + ", Ks " + full_text(brdf.specular) + ")",
                         {Sampler::brdf, 0.0, brdf, n, wo},
                         {around_mirror, even_edges(-1, 1, 40), nullptr, 12},
                         [brdf, n, wo](const Vec3& d) { return expected_brdf_pdf(brdf, n, wo, d); },
                         false});
    }
    return cases;
}

constexpr int kDirections = 20000;

ProbeCase sampler_distribution_case(const SamplerCase& c, std::uint64_t seed, int index,
                                    double alpha) {
    probe::DirectionsQuestion question{c.setting, {}, {}};
    PortableRandom random(seed, static_cast<std::uint64_t>(index));
    for (int k = 0; k < kDirections; ++k) {
        question.us.push_back({random.unit(), random.unit()});
        question.choices.push_back(random.unit());
    }
    const BinPoints points = bin_points(c.bins);
    std::vector<double> densities;
    for (const Vec3& d : points.directions)
        densities.push_back(c.density(d));
    const std::vector<double> masses = bin_masses(c.bins, points, densities);
    return {c.name + ": " + std::to_string(kDirections) +
                " directions against the contract's density, chi-square",
            probe::query(probe::directions_call, question),
            [c, masses, alpha](const ProbeAnswer& answer) {
                const std::string want =
                    std::string("unit directions") + (c.hemisphere ? " above the surface" : "") +
                    " distributed by the density, chi-square p >= " + full_text(alpha);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                const auto directions = probe::JsonCodec<std::vector<Vec3>>::read(answer.value);
                if (directions.size() != static_cast<std::size_t>(kDirections))
                    return wrong(want, std::to_string(directions.size()) + " directions");
                std::vector<double> counts(masses.size(), 0.0);
                for (const Vec3& d : directions) {
                    if (!(std::abs(glm::length(d) - 1) <= 1e-9))
                        return wrong(want,
                                     "the direction " + full_text(d) + ", not of unit length");
                    if (c.hemisphere && !(d.z >= 0))
                        return wrong(want, "the direction " + full_text(d) + ", below the surface");
                    const int bin = bin_of(c.bins, d);
                    if (bin >= 0) counts[static_cast<std::size_t>(bin)] += 1;
                }
                std::vector<double> expected;
                for (const double m : masses)
                    expected.push_back(m * kDirections);
                const PooledChiSquare pooled = pooled_chi_square(counts, expected);
                const double p = chi_square_p_value(pooled.statistic, pooled.degrees);
                return p >= alpha ? right() : wrong(want, p_text(p, alpha));
            },
            ""};
}

// The student's density over the same bins: it integrates to 1 over the sphere, within the
// midpoint rule's error on these bins (under 2e-3 for the cases' lobes), and a hemisphere's
// sampler's is 0 below.
ProbeCase density_integral_case(const SamplerCase& c) {
    BinPoints points = bin_points(c.bins);
    if (c.hemisphere) {
        const BinPoints below = bin_points({c.bins.frame, even_edges(-1, 0, 10), nullptr, 6});
        points.directions.insert(points.directions.end(), below.directions.begin(),
                                 below.directions.end());
        points.solid_angles.insert(points.solid_angles.end(), below.solid_angles.begin(),
                                   below.solid_angles.end());
    }
    probe::DensitiesQuestion question{c.setting, points.directions};
    return {c.name + ": its density integrated over the sphere",
            probe::query(probe::densities_call, question),
            [c, points](const ProbeAnswer& answer) {
                const std::string want = std::string("a density integrating to 1 (within 1e-2)") +
                                         (c.hemisphere ? ", 0 below the surface" : "");
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                const auto densities = probe::JsonCodec<std::vector<double>>::read(answer.value);
                if (densities.size() != points.directions.size())
                    return wrong(want, std::to_string(densities.size()) + " densities");
                double above = 0;
                double below = 0;
                for (std::size_t k = 0; k < densities.size(); ++k) {
                    if (!(densities[k] >= 0))
                        return wrong(want, "the density " + full_text(densities[k]) + " at " +
                                               full_text(points.directions[k]));
                    const bool under = c.hemisphere && points.directions[k].z < 0;
                    (under ? below : above) += densities[k] * points.solid_angles[k];
                }
                if (std::abs(above + below - 1) <= 1e-2 && below == 0) return right();
                return wrong(want, "the integral " + full_text(above + below) +
                                       (c.hemisphere ? ", below the surface " + full_text(below)
                                                     : std::string()));
            },
            ""};
}

std::vector<ProbeCase> sampling_cases() {
    const std::vector<SamplerCase> samplers = sampler_cases();
    const double alpha = kCheckAlpha / static_cast<double>(samplers.size());
    std::vector<ProbeCase> cases;
    int index = 0;
    for (const SamplerCase& c : samplers) {
        cases.push_back(sampler_distribution_case(c, statistics_seed() + 10, index++, alpha));
        cases.push_back(density_integral_case(c));
    }
    return cases;
}

// --- a quad light's samples

constexpr int kLightSamples = 10000;
constexpr int kLightBins = 10;

ProbeCase light_samples_case(const QuadLight& light, const Vec3& point, std::uint64_t seed,
                             int index, double alpha) {
    probe::LightDirectionsQuestion question{light, point, {}};
    PortableRandom random(seed, static_cast<std::uint64_t>(index));
    for (int k = 0; k < kLightSamples; ++k)
        question.us.push_back({random.unit(), random.unit()});
    return {"sample_light_direction from " + full_text(point) + ": " +
                std::to_string(kLightSamples) +
                " samples uniform over the light, each with its direction's density",
            probe::query(probe::light_directions_call, question),
            [light, point, alpha](const ProbeAnswer& answer) {
                const std::string want =
                    "points uniform over the light (chi-square p >= " + full_text(alpha) +
                    "), each sample's pdf and radiance its direction's";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                const auto samples =
                    probe::JsonCodec<std::vector<LightDirectionSample>>::read(answer.value);
                if (samples.size() != static_cast<std::size_t>(kLightSamples))
                    return wrong(want, std::to_string(samples.size()) + " samples");
                const Vec3 normal = glm::cross(light.edge1, light.edge2);
                const double n2 = glm::dot(normal, normal);
                std::vector<Vec2> places;
                for (const LightDirectionSample& s : samples) {
                    const Vec3 q = point + s.distance * s.direction - light.corner;
                    const Vec2 place{glm::dot(glm::cross(q, light.edge2), normal) / n2,
                                     glm::dot(glm::cross(light.edge1, q), normal) / n2};
                    const double pdf = expected_light_direction_pdf(light, point, s.direction);
                    const bool lit = glm::dot(normal, s.direction) > 0;
                    const Color radiance = lit ? light.radiance : Color(0.0);
                    if (!(std::abs(s.pdf - pdf) <= 1e-8 * pdf) ||
                        !(glm::length(s.radiance - radiance) <= 1e-12 * glm::length(radiance)) ||
                        !(std::abs(glm::dot(q, normal)) <= 1e-9 * std::sqrt(n2) * s.distance)) {
                        return wrong(want, "direction " + full_text(s.direction) + ", distance " +
                                               full_text(s.distance) + ", pdf " + full_text(s.pdf) +
                                               " (its direction's " + full_text(pdf) +
                                               "), radiance " + full_text(s.radiance));
                    }
                    places.push_back({std::clamp(place.x, 0.0, std::nextafter(1.0, 0.0)),
                                      std::clamp(place.y, 0.0, std::nextafter(1.0, 0.0))});
                }
                const double p = chi_square_p_value(uniform_square_chi_square(places, kLightBins),
                                                    kLightBins * kLightBins - 1);
                return p >= alpha ? right() : wrong(want, p_text(p, alpha));
            },
            ""};
}

std::vector<ProbeCase> light_cases() {
    const QuadLight square{{-1, -1, 2}, {2, 0, 0}, {0, 2, 0}, {3, 2, 1}, 0};
    const QuadLight slanted{{0.5, 1, 0.2}, {1, 0.3, 0.5}, {-0.2, 0.4, 0.1}, {1, 1, 1}, 0};
    const double alpha = kCheckAlpha / 3;
    const std::uint64_t seed = statistics_seed() + 11;
    return {
        light_samples_case(square, {0, 0, 0}, seed, 0, alpha),
        light_samples_case(square, {3, 0.5, 1.5}, seed, 1, alpha),
        light_samples_case(slanted, {-1, -1, -1}, seed, 2, alpha),
    };
}

// --- the roulette's weight, on average the throughput

constexpr int kRouletteGrid = 4000;

ProbeCase roulette_mean_case(const Color& throughput) {
    probe::RouletteQuestion question{throughput, {}};
    for (int k = 0; k < kRouletteGrid; ++k)
        question.us.push_back((k + 0.5) / kRouletteGrid);
    return {"russian_roulette(" + full_text(throughput) + "): the weight averaged over u on a " +
                std::to_string(kRouletteGrid) + "-point grid is the throughput",
            probe::query(probe::roulette_call, question),
            [throughput](const ProbeAnswer& answer) {
                // u on the grid's midpoints: the share of u below q is q within 1 / grid, so a
                // right roulette's mean is the throughput within throughput / (q grid); q may be
                // any probability a roulette chooses, so that bound is taken from the answer.
                const std::string want = "a mean weight of " + full_text(throughput);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                const auto weights =
                    probe::JsonCodec<std::vector<std::optional<Color>>>::read(answer.value);
                if (weights.size() != static_cast<std::size_t>(kRouletteGrid))
                    return wrong(want, std::to_string(weights.size()) + " answers");
                Color sum(0.0);
                int went_on = 0;
                for (const auto& w : weights) {
                    if (!w) continue;
                    sum += *w;
                    ++went_on;
                }
                const Color mean = sum / static_cast<double>(kRouletteGrid);
                const double q = static_cast<double>(went_on) / kRouletteGrid;
                const double bound = q > 0 ? 1.5 / (q * kRouletteGrid) : 1.0;
                for (int c = 0; c < 3; ++c) {
                    if (!(std::abs(mean[c] - throughput[c]) <= bound * throughput[c] + 1e-12))
                        return wrong(want, "a mean weight of " + full_text(mean) +
                                               ", going on for " + std::to_string(went_on) +
                                               " of " + std::to_string(kRouletteGrid) + " u");
                }
                return right();
            },
            ""};
}

std::vector<ProbeCase> roulette_cases() {
    return {roulette_mean_case({0.5, 0.25, 0.1}), roulette_mean_case({0.05, 0.02, 0.04}),
            roulette_mean_case({0.9, 0.9, 0.9}), roulette_mean_case({3, 0.5, 0.2})};
}

// --- paths against closed forms

constexpr int kPaths = 8000;

// The most a mean's standard error may be, relative to the brightest channel of its exact value:
// the z-test takes the spread from the answers themselves, so an estimator that only adds noise
// (a colour of 1e12 (u - 0.5)) would pass every mean without a ceiling. A right path tracer's
// standard error on these cases is at most 2.3% of the value (the diffuse floor by hemisphere
// sampling without next event estimation; docs/measurements/stage10-checks.md); the ceiling is
// three times it.
constexpr double kPathsErrorCeiling = 0.07;

const RayOffset kPathOffset{OffsetRule::along_normal, 1e-7};

PathSettings settings_of(int depth, DirectionSampling sampling, NextEvent next_event,
                         bool roulette = false) {
    return {depth, roulette, sampling, next_event};
}

std::string settings_text(const PathSettings& s) {
    const char* samplings[] = {"hemisphere", "cosine", "brdf"};
    const char* events[] = {"off", "on", "mis"};
    return "maxdepth " + std::to_string(s.max_depth) + ", importancesampling " +
           samplings[static_cast<int>(s.sampling)] + ", nexteventestimation " +
           events[static_cast<int>(s.next_event)] +
           (s.russian_roulette ? ", russianroulette on" : "");
}

ProbeCase paths_case(std::string scene, const probe::PathSceneQuestion& question, const Ray& ray,
                     const PathSettings& settings, const Color& exact, std::uint64_t seed,
                     std::uint64_t first_stream, double alpha) {
    probe::PathsQuestion q{question, ray, settings, seed, first_stream, kPaths};
    return {scene + ", " + settings_text(settings) + ": the mean of " + std::to_string(kPaths) +
                " paths is " + full_text(exact),
            probe::query(probe::path_radiance_call, q),
            [exact, alpha](const ProbeAnswer& answer) {
                const double bound = two_sided_normal_bound(alpha);
                const double brightest = std::max({exact.x, exact.y, exact.z});
                const double ceiling = kPathsErrorCeiling * brightest + kDeviationFloor;
                const std::string want = full_text(exact) + " within " + full_text(bound) +
                                         " standard errors, each at most " + full_text(ceiling) +
                                         ", every path's colour finite and not negative";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                const auto colours = probe::JsonCodec<std::vector<Color>>::read(answer.value);
                if (colours.size() != static_cast<std::size_t>(kPaths))
                    return wrong(want, std::to_string(colours.size()) + " paths");
                for (const Color& colour : colours) {
                    if (!(colour.x >= 0 && colour.y >= 0 && colour.z >= 0) ||
                        !std::isfinite(colour.x + colour.y + colour.z))
                        return wrong(want, "a path of colour " + full_text(colour));
                }
                std::string got;
                bool right_mean = true;
                for (int c = 0; c < 3; ++c) {
                    std::vector<double> channel;
                    for (const Color& colour : colours)
                        channel.push_back(colour[c]);
                    const MeanEstimate estimate = estimate_mean(channel, kDeviationFloor);
                    right_mean = right_mean && mean_consistent(estimate, exact[c], bound) &&
                                 estimate.standard_error <= ceiling;
                    got += (got.empty() ? "" : "; ") + full_text(estimate.mean) + " +- " +
                           full_text(estimate.standard_error);
                }
                return right_mean ? right() : wrong(want, got);
            },
            ""};
}

Ray ray_from_to(const Vec3& from, const Vec3& to) {
    return {from, glm::normalize(to - from), 0.0, std::numeric_limits<double>::infinity()};
}

probe::PathSceneQuestion furnace(const Color& albedo, const Color& emission) {
    probe::PathSceneQuestion q;
    q.enclosure =
        probe::Enclosure{{0.5, -1, 2}, 3, {BrdfModel::phong, albedo, Color(0.0), 0, 0}, emission};
    q.offset = kPathOffset;
    return q;
}

const QuadLight kFloorLight{{-1, 1.5, -1}, {0, 0, 2}, {2, 0, 0}, {2, 1.5, 1}, 0};

probe::PathSceneQuestion floor_under_light(const SurfaceBrdf& brdf) {
    probe::PathSceneQuestion q;
    q.floor = probe::Floor{{0, 0, 0}, {0, 1, 0}, brdf};
    q.lights = {kFloorLight};
    q.offset = kPathOffset;
    return q;
}

std::vector<ProbeCase> path_cases() {
    using S = DirectionSampling;
    using N = NextEvent;
    struct Planned {
        std::string scene;
        probe::PathSceneQuestion question;
        Ray ray;
        PathSettings settings;
        Color exact;
    };
    std::vector<Planned> planned;
    const Ray in_furnace = ray_from_to({0.7, -0.8, 2.1}, {2, 1, 0});
    const auto furnace_case = [&](const Color& albedo, const Color& emission, int depth, S s,
                                  bool roulette) {
        planned.push_back(
            {"a furnace of albedo " + full_text(albedo) + " emitting " + full_text(emission),
             furnace(albedo, emission), in_furnace, settings_of(depth, s, N::off, roulette),
             furnace_radiance(emission, albedo, depth)});
    };
    furnace_case(Color(0.5), Color(1.0), 3, S::cosine, false);
    furnace_case({0.7, 0.5, 0.3}, {1, 2, 3}, 4, S::hemisphere, false);
    furnace_case(Color(0.6), Color(1.0), 2, S::brdf, false);
    furnace_case(Color(0.5), Color(1.0), -1, S::cosine, true);
    furnace_case({0.8, 0.6, 0.4}, Color(1.0), 5, S::hemisphere, true);

    // A floor point seen from above, under a 2 x 2 light 1.5 over it facing down.
    const Vec3 at{0.3, 0, -0.2};
    const Vec3 eye{1.5, 1, 0.8};
    const Ray to_floor = ray_from_to(eye, at);
    const Vec3 up{0, 1, 0};
    const SurfaceBrdf diffuse{BrdfModel::phong, {0.6, 0.5, 0.4}, Color(0.0), 0, 0};
    for (const N n : {N::off, N::on, N::mis}) {
        for (const S s : {S::hemisphere, S::cosine, S::brdf}) {
            planned.push_back({"a diffuse floor under a light", floor_under_light(diffuse),
                               to_floor, settings_of(2, s, n),
                               floor_radiance(diffuse, at, up, -to_floor.direction, kFloorLight)});
        }
    }
    const SurfaceBrdf glossy{BrdfModel::phong, Color(0.2), {0.6, 0.6, 0.5}, 20, 0};
    const SurfaceBrdf rough{BrdfModel::ggx, Color(0.2), {0.5, 0.5, 0.5}, 0, 0.3};
    // The view whose mirror direction runs to the light's centre: the lobes' peaks lie on it.
    const Vec3 mirror_eye = at + 0.8 * Vec3{0.3, 1.5, -0.2};
    const Ray glancing = ray_from_to(mirror_eye, at);
    for (const SurfaceBrdf& brdf : {glossy, rough}) {
        const std::string name =
            brdf.model == BrdfModel::phong ? "a Phong floor (s 20)" : "a GGX floor (alpha 0.3)";
        const Color exact = floor_radiance(brdf, at, up, -glancing.direction, kFloorLight);
        for (const auto& [s, n] :
             {std::pair{S::brdf, N::off}, std::pair{S::brdf, N::mis}, std::pair{S::cosine, N::mis},
              std::pair{S::hemisphere, N::mis}, std::pair{S::brdf, N::on}}) {
            planned.push_back({name + " under a light", floor_under_light(brdf), glancing,
                               settings_of(1, s, n), exact});
        }
    }
    probe::PathSceneQuestion blocked = floor_under_light(diffuse);
    blocked.shadows_blocked = true;
    planned.push_back({"a diffuse floor whose every shadow ray is blocked", blocked, to_floor,
                       settings_of(3, S::cosine, N::on), Color(0.0)});
    planned.push_back({"the light seen directly", floor_under_light(diffuse),
                       ray_from_to({0, 0.2, 0}, {0.1, 2, 0.1}), settings_of(0, S::cosine, N::mis),
                       kFloorLight.radiance});

    const double alpha = kCheckAlpha / (3.0 * static_cast<double>(planned.size()));
    const std::uint64_t seed = statistics_seed() + 12;
    std::vector<ProbeCase> cases;
    std::uint64_t first_stream = 0;
    for (const Planned& p : planned) {
        cases.push_back(
            paths_case(p.scene, p.question, p.ray, p.settings, p.exact, seed, first_stream, alpha));
        first_stream += kPaths;
    }
    // A path with no depth limit and no roulette need not end: the contract's domain_error.
    const Judge threw = build_judge(threw_judge("domain_error"));
    cases.push_back({"a furnace, maxdepth -1 without Russian roulette: std::domain_error",
                     probe::query(probe::path_radiance_call,
                                  probe::PathsQuestion{furnace(Color(0.5), Color(1.0)), in_furnace,
                                                       settings_of(-1, S::cosine, N::off), seed,
                                                       first_stream, 1}),
                     [threw](const ProbeAnswer& answer) {
                         const Verdict v = threw(answer);
                         return Judgement{v.passed, v.expected, v.got, v.not_implemented};
                     },
                     ""});
    return cases;
}

}  // namespace

std::vector<CheckDefinition> stage10_statistical_checks() {
    const std::string rate = " (false-fail rate 1e-4)";
    return {
        case_check("stage10.statistics.sampling", 10, "oracle",
                   "each sampler's directions against its density (chi-square) and each density "
                   "integrating to 1" +
                       rate,
                   sampling_cases),
        case_check("stage10.statistics.light", 10, "oracle",
                   "a quad light's samples uniform over its area, each with its direction's "
                   "density" +
                       rate,
                   light_cases),
        case_check("stage10.statistics.roulette", 10, "oracle",
                   "Russian roulette's weight on average the throughput", roulette_cases),
        case_check("stage10.statistics.paths", 10, "oracle",
                   "paths' means against the white furnace and a floor under a light, by every "
                   "sampling and light rule, and with Russian roulette" +
                       rate,
                   path_cases),
    };
}

}  // namespace raystep::grade
