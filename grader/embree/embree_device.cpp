#include "grader/embree/embree_device.h"

#include <mutex>
#include <stdexcept>
#include <string>

namespace raystep {

std::shared_ptr<RTCDeviceTy> embree_device(int threads) {
    static std::mutex mutex;
    static std::shared_ptr<RTCDeviceTy> current;
    static int current_threads = -1;

    std::lock_guard<std::mutex> lock(mutex);
    if (current && current_threads == threads) return current;
    current.reset();

    const std::string config = "threads=" + std::to_string(threads);
    RTCDevice device = rtcNewDevice(threads == 0 ? nullptr : config.c_str());
    if (!device) {
        throw std::runtime_error("Embree could not make a device (error " +
                                 std::to_string(rtcGetDeviceError(nullptr)) + ")");
    }
    current = std::shared_ptr<RTCDeviceTy>(device, rtcReleaseDevice);
    current_threads = threads;
    return current;
}

}  // namespace raystep
