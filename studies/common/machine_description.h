#pragma once

#include <string>

namespace raystep {

// What a measurement's header says about where and when it ran.

/// The processor's name from /proc/cpuinfo, where there is one; empty elsewhere.
std::string processor_name();

/// The one-minute load average from /proc/loadavg, where there is one: above 0, other programs
/// share the processors with the bench. Empty elsewhere.
std::string load_average();

/// Now, as "2026-11-21 14:05 UTC".
std::string local_time();

/// "2 hardware threads (AMD EPYC)": the machine in a few words.
std::string machine_description();

}  // namespace raystep
