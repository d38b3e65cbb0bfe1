#pragma once

// The BVH's inner loop: which of a node's eight children a ray enters, and where. Run in float on
// the nodes' outward-rounded float boxes, with everything float rounding could take away given
// back, so that a box the ray touches is never missed:
// - the origin, rounded to float, is off by less than |o - float(o)|, which moves a slab's t's
//   by that times |1 / D|: the `shift` each near plane is moved back and each far plane forward.
//   Where 1 / D is infinite no shift is needed: rounding is monotonic, so an origin inside a
//   slab rounds to a float inside its outward-rounded bounds;
// - (bound - origin) * inverse carries three float roundings, so each t is within
//   gamma(3) = 3 u / (1 - 3 u), u = 2^-24, of its exact value, and widening the exit by
//   2 gamma(3) of itself covers both ends (Ize 2013, "Robust BVH Ray Traversal", JCGT 2(2)).
// A NaN (0 * inf: the origin on a slab's plane, the ray in it) must leave a bound as it was.
//
// Two implementations compute the same floats, operation for operation: SSE2, which every
// x86-64 processor has and which tests one plane of four children in one instruction, and
// plain C++ for other processors; ChildTest is the one this build uses. grader/tests checks that
// they agree bit for bit.

#include <cmath>
#include <cstdint>

#include "solutions/4_accel/bvh_layout.h"
#include "stages/2_rays/ray.h"

#if defined(__SSE2__) || defined(_M_X64)
#define RAYSTEP_BVH_SSE2 1
#include <emmintrin.h>
#endif

namespace raystep {

inline constexpr float kFloatRounding = 0x1p-24f;
inline constexpr float kWidenExit =
    1.0f + 2.0f * (3.0f * kFloatRounding / (1.0f - 3.0f * kFloatRounding));

/// x rounded to a float no smaller than it: rounding to nearest is off by at most half an ulp,
/// 2^-24 of the value, so adding 2^-23 of it is enough (and infinity stays infinity).
inline float rounded_up(double x) {
    const float f = static_cast<float>(x);
    return f + std::abs(f) * 0x1p-23f;
}

/// A ray prepared for node tests, once per query.
struct NodeRay {
    float origin[3];
    float inverse[3];
    float shift[3];
    bool negative[3];  ///< 1 / D < 0 on this axis: the maximum plane is met first
    float t_min;       ///< rounded down

    explicit NodeRay(const Ray& ray) : NodeRay(ray, 1.0 / ray.direction) {}

    /// The same, from 1 / D already computed (in double) for the root box.
    NodeRay(const Ray& ray, const Vec3& inverse_direction) {
        for (int axis = 0; axis < 3; ++axis) {
            const double inverse_exact = inverse_direction[axis];
            origin[axis] = static_cast<float>(ray.origin[axis]);
            inverse[axis] = static_cast<float>(inverse_exact);
            negative[axis] = inverse_exact < 0.0;
            shift[axis] = std::isfinite(inverse_exact)
                              ? rounded_up(std::abs(ray.origin[axis] - origin[axis]) *
                                           std::abs(inverse_exact))
                              : 0.0f;
        }
        t_min = static_cast<float>(ray.t_min);
        t_min -= std::abs(t_min) * 0x1p-23f;
    }
};

/// The node test in plain C++.
class ChildTestScalar {
  public:
    explicit ChildTestScalar(const NodeRay& ray) : ray_(ray) {}

    /// Where the ray enters each child (`entry`) and whether it does before `limit` (bit c of
    /// the result).
    int enter_children(const BvhNode& node, float limit, float entry[BvhNode::kWidth]) const {
        int hits = 0;
        for (int c = 0; c < BvhNode::kWidth; ++c) {
            float in = ray_.t_min;
            float out = limit;
            for (int axis = 0; axis < 3; ++axis) {
                const int near = 2 * axis + (ray_.negative[axis] ? 1 : 0);
                const int far = 2 * axis + (ray_.negative[axis] ? 0 : 1);
                const float t_near =
                    (node.planes[near][c] - ray_.origin[axis]) * ray_.inverse[axis] -
                    ray_.shift[axis];
                const float t_far = (node.planes[far][c] - ray_.origin[axis]) * ray_.inverse[axis] +
                                    ray_.shift[axis];
                in = t_near > in ? t_near : in;
                out = t_far < out ? t_far : out;
            }
            entry[c] = in;
            if (in <= out * kWidenExit) hits |= 1 << c;
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
            origin_[axis] = _mm_set1_ps(ray.origin[axis]);
            inverse_[axis] = _mm_set1_ps(ray.inverse[axis]);
            shift_[axis] = _mm_set1_ps(ray.shift[axis]);
            near_[axis] = 2 * axis + (ray.negative[axis] ? 1 : 0);
            far_[axis] = 2 * axis + (ray.negative[axis] ? 0 : 1);
        }
        t_min_ = _mm_set1_ps(ray.t_min);
    }

    int enter_children(const BvhNode& node, float limit, float entry[BvhNode::kWidth]) const {
        const __m128 limit4 = _mm_set1_ps(limit);
        int hits = 0;
        for (int first = 0; first < BvhNode::kWidth; first += 4) {
            __m128 in = t_min_;
            __m128 out = limit4;
            for (int axis = 0; axis < 3; ++axis) {
                const __m128 near = _mm_load_ps(node.planes[near_[axis]] + first);
                const __m128 far = _mm_load_ps(node.planes[far_[axis]] + first);
                const __m128 t_near = _mm_sub_ps(
                    _mm_mul_ps(_mm_sub_ps(near, origin_[axis]), inverse_[axis]), shift_[axis]);
                const __m128 t_far = _mm_add_ps(
                    _mm_mul_ps(_mm_sub_ps(far, origin_[axis]), inverse_[axis]), shift_[axis]);
                // maxps and minps return their second operand when either is NaN: the bound
                // stays.
                in = _mm_max_ps(t_near, in);
                out = _mm_min_ps(t_far, out);
            }
            _mm_storeu_ps(entry + first, in);
            const __m128 enters = _mm_cmple_ps(in, _mm_mul_ps(out, _mm_set1_ps(kWidenExit)));
            hits |= _mm_movemask_ps(enters) << first;
        }
        return hits;
    }

  private:
    __m128 origin_[3];
    __m128 inverse_[3];
    __m128 shift_[3];
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
