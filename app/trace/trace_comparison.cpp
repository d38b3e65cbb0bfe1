#include "app/trace/trace_comparison.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "app/compare/reference_trace.h"
#include "renderer/render_scene.h"

namespace raystep {

namespace {

// The one tolerance of the comparison. Two values of a quantity are the same when they are apart
// by no more than the rounding the reference trace stored the reference's value with
// (stored_roundoff: about 2^-13 for the camera ray, 2^-17 for t, 2^-11 for the normal and the
// barycentrics, 2^-9 for a colour), relative to `scale`, the magnitude of the whole quantity: the
// largest component of a vector, so that a component near 0 of a unit vector is held to the
// vector's precision, not its own. A difference below that is no difference: the reference's own
// value could be anywhere within it.
bool same_within(double ours, double reference, TraceQuantity quantity, double scale) {
    return std::abs(ours - reference) <= stored_roundoff(quantity) * scale;
}

double largest(const std::vector<double>& a, const std::vector<double>& b) {
    double most = 0.0;
    for (const double v : a)
        most = std::max(most, std::abs(v));
    for (const double v : b)
        most = std::max(most, std::abs(v));
    return most;
}

// Numbers as the reference trace stores them, with `digits` significant digits.
std::string numbers(const std::vector<double>& values, TraceQuantity quantity, int digits) {
    std::string text;
    for (const double v : values) {
        std::ostringstream number;
        number << std::setprecision(digits) << stored_value(v, quantity);
        text += (text.empty() ? "" : ", ") + number.str();
    }
    return values.size() == 1 ? text : "(" + text + ")";
}

// The digits the stored bits carry, a digit for each 3.3 bits: a student's 3.6 and the
// reference's 3.6 stored in 12 bits (3.60010) both print 3.6. Where the values differ, more
// digits, until the two texts differ too.
int digits_kept(TraceQuantity quantity) {
    return 1 + stored_bits(quantity) * 3 / 10;
}

std::vector<double> components(const Vec3& v) {
    return {v.x, v.y, v.z};
}

std::string primitive_text(const std::optional<PrimitiveHit>& hit) {
    if (!hit) return "miss";
    return std::string(kind_name(hit->kind)) + " " + std::to_string(hit->index);
}

const char* reach_text(LightReach reach) {
    switch (reach) {
        case LightReach::behind:
            return "behind the surface";
        case LightReach::blocked:
            return "blocked";
        case LightReach::reaches:
            return "reaches the point";
    }
    return "";
}

// What a step is, on one side: not reached (a stub stopped it), reached without this quantity
// (no hit to shade), or its values.
struct Side {
    bool reached = true;
    std::optional<std::vector<double>> values;
};

class Rows {
  public:
    explicit Rows(TraceComparison& comparison) : comparison_(comparison) {}

    // A numeric quantity; false when `ours` did not reach it, so no later row can be compared.
    bool add(const std::string& quantity, TraceQuantity kind, const Side& ours,
             const Side& reference) {
        const auto text = [&](const Side& side, int digits) {
            return side.values ? numbers(*side.values, kind, digits) : "-";
        };
        if (!ours.reached) return stop(quantity, text(reference, digits_kept(kind)));
        bool same = ours.values.has_value() == reference.values.has_value();
        if (same && ours.values) {
            const double scale = largest(*ours.values, *reference.values);
            for (std::size_t c = 0; c < ours.values->size(); ++c)
                same = same && same_within((*ours.values)[c], (*reference.values)[c], kind, scale);
        }
        int digits = digits_kept(kind);
        while (!same && digits < 17 && text(ours, digits) == text(reference, digits))
            ++digits;
        push(quantity, text(ours, digits), text(reference, digits), same);
        return true;
    }

    // A quantity compared exactly, as text.
    bool add_exact(const std::string& quantity, bool reached, const std::string& ours,
                   const std::string& reference) {
        if (!reached) return stop(quantity, reference);
        push(quantity, ours, reference, ours == reference);
        return true;
    }

  private:
    bool stop(const std::string& quantity, const std::string& reference) {
        comparison_.rows.push_back({quantity, "(not reached)", reference, false});
        comparison_.stopped = true;
        return false;
    }

    void push(const std::string& quantity, const std::string& ours, const std::string& reference,
              bool same) {
        if (!same && !comparison_.first_difference)
            comparison_.first_difference = comparison_.rows.size();
        comparison_.rows.push_back({quantity, ours, reference, same});
    }

    TraceComparison& comparison_;
};

Side ray_side(const PixelRecord& record, bool direction) {
    if (!record.camera_ray) return {false, std::nullopt};
    return {true, components(direction ? record.camera_ray->direction : record.camera_ray->origin)};
}

// One value of the hit, or none on a miss.
template <class Get>
Side hit_side(const PixelRecord& record, Get get) {
    if (!record.hit_searched) return {false, std::nullopt};
    if (!record.hit) return {true, std::nullopt};
    return {true, get(record.hit->hit)};
}

std::vector<double> barycentrics(const Hit& hit) {
    return {hit.beta, hit.gamma};
}

// The shading steps: each light's reach and term, then the local colour unless it is random.
bool add_shading(Rows& rows, const PixelRecord& ours, const PixelRecord& reference,
                 const std::vector<std::string>& light_names, bool random_colours) {
    if (!ours.hit && !reference.hit) return true;
    const bool reached = !ours.hit || ours.local.has_value();
    for (std::size_t k = 0; k < light_names.size(); ++k) {
        const auto light = [&](const PixelRecord& record) -> std::optional<LightRecord> {
            if (k < record.lights.size()) return record.lights[k];
            return std::nullopt;
        };
        const std::optional<LightRecord> mine = light(ours), theirs = light(reference);
        const bool reached_light = reached || mine.has_value();
        if (!rows.add_exact(light_names[k] + ": reach", reached_light,
                            mine ? reach_text(mine->reach) : "-",
                            theirs ? reach_text(theirs->reach) : "-")) {
            return false;
        }
        const auto term = [](const std::optional<LightRecord>& record) {
            return record ? std::optional<std::vector<double>>(components(record->term))
                          : std::nullopt;
        };
        if (!rows.add(light_names[k] + ": term", TraceQuantity::light_term,
                      {reached_light, term(mine)}, {true, term(theirs)})) {
            return false;
        }
    }
    if (random_colours) return true;
    const auto local = [](const PixelRecord& record) {
        return record.local ? std::optional<std::vector<double>>(components(*record.local))
                            : std::nullopt;
    };
    return rows.add("the local colour", TraceQuantity::local_colour, {reached, local(ours)},
                    {true, local(reference)});
}

}  // namespace

TraceComparison compare_pixel(const PixelRecord& ours, const PixelRecord& reference, View view,
                              const std::vector<std::string>& light_names, bool random_colours) {
    TraceComparison comparison;
    Rows rows(comparison);
    const PipelineReach reach = pipeline_reach(view);
    if (!rows.add("the camera ray's origin", TraceQuantity::camera_origin, ray_side(ours, false),
                  ray_side(reference, false)) ||
        !rows.add("the camera ray's direction", TraceQuantity::camera_direction,
                  ray_side(ours, true), ray_side(reference, true)) ||
        reach == PipelineReach::camera_ray) {
        return comparison;
    }

    if (!rows.add_exact("the hit primitive", ours.hit_searched, primitive_text(ours.hit),
                        primitive_text(reference.hit)) ||
        !rows.add("the hit's t", TraceQuantity::t,
                  hit_side(ours, [](const Hit& h) { return std::vector<double>{h.t}; }),
                  hit_side(reference, [](const Hit& h) { return std::vector<double>{h.t}; })) ||
        !rows.add("the hit's normal", TraceQuantity::normal,
                  hit_side(ours, [](const Hit& h) { return components(h.normal); }),
                  hit_side(reference, [](const Hit& h) { return components(h.normal); })) ||
        !rows.add("the hit's barycentrics (beta, gamma)", TraceQuantity::barycentrics,
                  hit_side(ours, barycentrics), hit_side(reference, barycentrics)) ||
        reach == PipelineReach::closest_hit) {
        return comparison;
    }

    if (!add_shading(rows, ours, reference, light_names, random_colours) ||
        reach == PipelineReach::shading || random_colours) {
        return comparison;
    }
    const auto full = [](const PixelRecord& record) {
        return record.full ? std::optional<std::vector<double>>(components(*record.full))
                           : std::nullopt;
    };
    rows.add("the full colour", TraceQuantity::full_colour, {ours.full.has_value(), full(ours)},
             {true, full(reference)});
    return comparison;
}

}  // namespace raystep
