#pragma once

// The BVH's inner loop: which of a node's eight children a ray enters, and where. Run in float on
// the nodes' outward-rounded float boxes, with everything float rounding could take away given
// back, so that a box that holds a hit is never missed.
//
// Each slab time (plane - origin) / D is computed as plane * scale - offset: a multiply and a
// subtract, with scale = 1 / D and offset = origin * scale prepared once per ray. The walk waits
// on this arithmetic at every node, so two dependent operations beat a subtract, a multiply and a
// correction (`raystep-reference bench --workload bunny --threads 1`;
// docs/measurements/stage4-bench.md has the runs). Its rounding error does not shrink with t, as
// (plane - origin) * scale's does: it grows with the size of the numbers, |plane| |scale| and
// |origin| |scale|. The sizes are known before the walk starts: no plane is larger than the
// scene's box (the node ray's `plane_magnitude`), so one slack per axis covers every node:
// - scale is 1 / D rounded twice (double, then float): within 1.01 u of it, u = 2^-24;
// - plane * scale rounds once more, so it is within 2.02 u |plane| |1 / D| of plane / D;
// - the offset, computed in double and rounded to float once, is off by at most u |offset|;
// - the subtraction rounds once, by at most u (|plane * scale| + |offset|).
// So moving the near plane's offset up and the far plane's down by 4 u (P + |origin|) |1 / D|,
// P the plane magnitude, makes each near time no later, and each far time no earlier, than the
// exact one: the comparisons need no widening. (Below 2^-126 float rounds by up to 2^-150
// whatever the size; kSubnormalError covers that.)
//
// A zero direction component has no finite 1 / D. Its axis gets a stand-in scale of 2^64, the
// slab test of a ray tilted by 2^-64 on that axis. Up to t = t_end (where the ray leaves the
// scene's box: no hit lies beyond) the tilted ray is within t_end 2^-64 of the true one, which
// is t_end in slab time: adding t_end to that axis's slack keeps every box the true ray enters.
// It still rejects a box the origin is outside of by more than 2^-63 t_end + 2^-21 (P + |origin|),
// so an axis-parallel ray prunes as well as any other.
//
// All of this stays finite in float when the ray's numbers are of sane size: coordinates and
// t_end below 2^60, direction components 0 or between 2^-60 and 2^60 in size. A ray beyond that
// (`fits_float` false) is not walked: the BVH tests its every primitive.
//
// Two implementations compute the same floats, operation for operation: SSE2, which every
// x86-64 processor has and which tests one plane of four children in one instruction, and
// plain C++ for other processors; ChildTest is the one this build uses.
// grading/4_accel/tests/accel_agreement_test.cpp checks that they agree bit for bit.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "solutions/4_accel/bvh_layout.h"
#include "stages/2_rays/ray.h"

#if defined(__SSE2__) || defined(_M_X64)
#define RAYSTEP_BVH_SSE2 1
#include <emmintrin.h>
#endif

namespace raystep {

/// x rounded to a float no smaller than it, for |x| below float's largest. Rounding to nearest
/// is off by at most 2^-24 of the value, or by 2^-150 below 2^-126, so adding 2^-23 of x and
/// 2^-149 first is enough. Inline arithmetic, not std::nextafter: this runs for each ray and
/// each hit.
inline float rounded_up(double x) {
    return static_cast<float>(x + std::abs(x) * 0x1p-23 + 0x1p-149);
}

/// x rounded to a float no larger than it.
inline float rounded_down(double x) {
    return -rounded_up(-x);
}

/// A ray prepared for node tests, once per query.
struct NodeRay {
    static constexpr double kLargest = 0x1p60;        ///< the sizes a fitting ray stays below
    static constexpr double kZeroAxisScale = 0x1p64;  ///< the stand-in 1 / D of a zero component
    /// What the three float roundings (offset, multiply, subtract) can be off by below 2^-126,
    /// where rounding is absolute, not relative, with room to spare.
    static constexpr double kSubnormalError = 0x1p-140;

    float scale[3];
    float near_offset[3];
    float far_offset[3];
    bool negative[3];  ///< scale < 0 on this axis: the maximum plane is met first
    float t_min;       ///< rounded down
    bool fits_float;   ///< false: the ray's numbers are too large or too small for the test

    /// `inverse` is 1 / D in double, `plane_magnitude` no node plane is larger in magnitude,
    /// `t_end` no hit lies beyond.
    NodeRay(const Ray& ray, const Vec3& inverse, double plane_magnitude, double t_end) {
        const double reach = std::max(std::abs(ray.t_min), t_end);
        // Each condition joins fits_float with & rather than &&: a branch each would cost more
        // than the comparisons.
        fits_float = reach < kLargest;
        for (int axis = 0; axis < 3; ++axis) {
            const double size = plane_magnitude + std::abs(ray.origin[axis]);
            const double d = std::abs(ray.direction[axis]);
            fits_float &= size < kLargest;
            double exact_scale = inverse[axis];
            double slack = kSubnormalError;
            // A branch, which the processor predicts, rather than a select on `reach`: the node
            // test would otherwise wait for the root box's exit.
            if (d == 0.0) {
                exact_scale = kZeroAxisScale;
                slack += reach * (1.0 + 0x1p-20);
            } else {
                fits_float &= (d >= 1.0 / kLargest) & (d <= kLargest);
            }
            slack += 4.0 * 0x1p-24 * size * std::abs(exact_scale);
            const double offset = ray.origin[axis] * exact_scale;
            scale[axis] = static_cast<float>(exact_scale);
            near_offset[axis] = static_cast<float>(offset + slack);
            far_offset[axis] = static_cast<float>(offset - slack);
            negative[axis] = exact_scale < 0.0;
        }
        t_min = rounded_down(ray.t_min);
    }
};

/// The node test in plain C++.
class ChildTestScalar {
    // As SSE2's maxps and minps: the second operand unless the first is larger (smaller).
    static float max_of(float a, float b) { return a > b ? a : b; }
    static float min_of(float a, float b) { return a < b ? a : b; }

  public:
    explicit ChildTestScalar(const NodeRay& ray) : ray_(ray) {}

    /// Where the ray enters each child (`entry`) and whether it does before `limit` (bit c of
    /// the result).
    int enter_children(const BvhNode& node, float limit, float entry[BvhNode::kWidth]) const {
        int hits = 0;
        for (int c = 0; c < BvhNode::kWidth; ++c) {
            float t_near[3];
            float t_far[3];
            for (int axis = 0; axis < 3; ++axis) {
                const int near = 2 * axis + (ray_.negative[axis] ? 1 : 0);
                const int far = 2 * axis + (ray_.negative[axis] ? 0 : 1);
                t_near[axis] = node.planes[near][c] * ray_.scale[axis] - ray_.near_offset[axis];
                t_far[axis] = node.planes[far][c] * ray_.scale[axis] - ray_.far_offset[axis];
            }
            // Paired as the SSE2 test pairs them, so both round alike.
            const float in = max_of(max_of(t_near[0], t_near[1]), max_of(t_near[2], ray_.t_min));
            const float out = min_of(min_of(t_far[0], t_far[1]), min_of(t_far[2], limit));
            entry[c] = in;
            if (in <= out) hits |= 1 << c;
        }
        return hits;
    }

  private:
    NodeRay ray_;
};

#ifdef RAYSTEP_BVH_SSE2

/// The same, in SSE2: one plane of four children at once, the node in two halves.
class ChildTestSse {
    static_assert(BvhNode::kWidth % 4 == 0, "a node's children come in whole SSE registers");

  public:
    explicit ChildTestSse(const NodeRay& ray) {
        for (int axis = 0; axis < 3; ++axis) {
            scale_[axis] = _mm_set1_ps(ray.scale[axis]);
            near_offset_[axis] = _mm_set1_ps(ray.near_offset[axis]);
            far_offset_[axis] = _mm_set1_ps(ray.far_offset[axis]);
            near_[axis] = 2 * axis + (ray.negative[axis] ? 1 : 0);
            far_[axis] = 2 * axis + (ray.negative[axis] ? 0 : 1);
        }
        t_min_ = _mm_set1_ps(ray.t_min);
    }

    int enter_children(const BvhNode& node, float limit, float entry[BvhNode::kWidth]) const {
        const __m128 limit4 = _mm_set1_ps(limit);
        int hits = 0;
        for (int first = 0; first < BvhNode::kWidth; first += 4) {
            __m128 t_near[3];
            __m128 t_far[3];
            for (int axis = 0; axis < 3; ++axis) {
                const __m128 near = _mm_load_ps(node.planes[near_[axis]] + first);
                const __m128 far = _mm_load_ps(node.planes[far_[axis]] + first);
                t_near[axis] = _mm_sub_ps(_mm_mul_ps(near, scale_[axis]), near_offset_[axis]);
                t_far[axis] = _mm_sub_ps(_mm_mul_ps(far, scale_[axis]), far_offset_[axis]);
            }
            // In pairs rather than in a chain: two steps of latency instead of three.
            const __m128 in =
                _mm_max_ps(_mm_max_ps(t_near[0], t_near[1]), _mm_max_ps(t_near[2], t_min_));
            const __m128 out =
                _mm_min_ps(_mm_min_ps(t_far[0], t_far[1]), _mm_min_ps(t_far[2], limit4));
            _mm_storeu_ps(entry + first, in);
            hits |= _mm_movemask_ps(_mm_cmple_ps(in, out)) << first;
        }
        return hits;
    }

  private:
    __m128 scale_[3];
    __m128 near_offset_[3];
    __m128 far_offset_[3];
    int near_[3];
    int far_[3];
    __m128 t_min_;
};

/// The node test this build uses.
using ChildTest = ChildTestSse;

#else

using ChildTest = ChildTestScalar;

#endif

}  // namespace raystep
