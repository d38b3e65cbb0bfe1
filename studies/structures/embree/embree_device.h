#pragma once

#include <memory>
#include <string>

#include <embree3/rtcore.h>

namespace raystep {

/// An Embree device whose builds run on `threads` threads, 0 for every hardware thread, and whose
/// kernels use instructions up to `max_isa` (Embree's device option: "sse2", "avx2", ...), empty
/// for the best the processor has; with 0 and empty, Embree's default, rtcNewDevice(nullptr).
/// Embree sets its thread count per process, the largest that any live device asked for, so one
/// setting lives at a time: asking for another lets go of the current device, which ends when
/// the last scene made with it is released. Throws std::runtime_error when Embree cannot make a
/// device.
std::shared_ptr<RTCDeviceTy> embree_device(int threads, const std::string& max_isa);

}  // namespace raystep
