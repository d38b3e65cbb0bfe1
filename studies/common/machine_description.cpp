#include "studies/common/machine_description.h"

#include <algorithm>
#include <ctime>
#include <fstream>
#include <thread>

namespace raystep {

std::string processor_name() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);) {
        if (line.rfind("model name", 0) != 0) continue;
        const std::size_t colon = line.find(':');
        if (colon != std::string::npos && colon + 2 <= line.size()) return line.substr(colon + 2);
    }
    return "";
}

std::string load_average() {
    std::ifstream loadavg("/proc/loadavg");
    std::string one_minute;
    loadavg >> one_minute;
    return one_minute;
}

std::string local_time() {
    const std::time_t now = std::time(nullptr);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M %Z", std::localtime(&now));
    return text;
}

std::string machine_description() {
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    const std::string processor = processor_name();
    return std::to_string(hardware) + " hardware threads" +
           (processor.empty() ? "" : " (" + processor + ")");
}

}  // namespace raystep
