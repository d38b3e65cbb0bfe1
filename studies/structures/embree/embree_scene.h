#pragma once

#include <cstddef>
#include <memory>

#include <embree3/rtcore.h>

#include "studies/structures/bench_structure.h"

namespace raystep {

/// Embree 3 as a benchmarked structure: the list's triangles as one RTC_GEOMETRY_TYPE_TRIANGLE
/// (float3 vertices, uint3 indices) and its spheres as one RTC_GEOMETRY_TYPE_SPHERE_POINT (float4
/// centre and radius), both and the scene at RTC_BUILD_QUALITY_HIGH; queried one ray at a time
/// with rtcIntersect1. Embree works in float, so its hits are timed, never compared with ours.
class EmbreeScene final : public BenchStructure {
  public:
    /// Copies the list into Embree's buffers, in float, on `device` (untimed).
    EmbreeScene(std::shared_ptr<RTCDeviceTy> device, const PrimitiveList& primitives);
    ~EmbreeScene() override;
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    /// rtcCommitScene: Embree's build. Throws std::runtime_error when Embree reports an error.
    void build() override;

    /// Each ray converted to float and traced by rtcIntersect1; primitives numbered as closest_hit
    /// orders them, t the float tfar.
    void closest_hits(const Ray* rays, std::size_t count, BenchHit* answers,
                      TraversalStats* stats) const override;

    /// Embree counts nothing that we can read.
    StatsCoverage coverage() const override { return {}; }

  private:
    std::shared_ptr<RTCDeviceTy> device_;
    RTCScene scene_ = nullptr;
    unsigned sphere_geometry_ = RTC_INVALID_GEOMETRY_ID;
    unsigned triangle_geometry_ = RTC_INVALID_GEOMETRY_ID;
    std::size_t sphere_count_ = 0;
};

}  // namespace raystep
