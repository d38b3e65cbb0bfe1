#include "studies/structures/embree/embree_device.h"

#include <mutex>
#include <stdexcept>
#include <string>

namespace raystep {

std::shared_ptr<RTCDeviceTy> embree_device(int threads, const std::string& max_isa) {
    static std::mutex mutex;
    static std::shared_ptr<RTCDeviceTy> current;
    static int current_threads = -1;
    static std::string current_isa;

    std::lock_guard<std::mutex> lock(mutex);
    if (current && current_threads == threads && current_isa == max_isa) return current;
    current.reset();

    std::string config;
    if (threads != 0) config = "threads=" + std::to_string(threads);
    if (!max_isa.empty()) config += (config.empty() ? "" : ",") + ("max_isa=" + max_isa);
    RTCDevice device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
    if (!device) {
        throw std::runtime_error("Embree could not make a device (error " +
                                 std::to_string(rtcGetDeviceError(nullptr)) + ")");
    }
    current = std::shared_ptr<RTCDeviceTy>(device, rtcReleaseDevice);
    current_threads = threads;
    current_isa = max_isa;
    return current;
}

}  // namespace raystep
