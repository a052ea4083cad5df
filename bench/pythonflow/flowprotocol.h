// SPDX-License-Identifier: MIT
#pragma once

// What bench_python's sources send and its sinks report, in C++ (the Python modules beside this
// file follow the same): RTC::TimedDoubleSeq samples over a flush connection; the first element of
// a sample is its index when measured, or one of the marks below.

#include <chrono>

namespace FlowBench {

/// The sample sizes in elements, each sent warmUpSamples times unmeasured, then samplesFor() times.
constexpr unsigned sizes[] = {1, 1024, 65536};
constexpr int warmUpSamples = 5;
constexpr double warmUpMark = -1;
/// Ends a size: the sink prints its line (element 1 holds the size).
constexpr double endOfSizeMark = -2;

inline int samplesFor(unsigned elements)
{
    return elements > 10000 ? 50 : 500;
}

/// Seconds since the epoch on the system clock, which both languages read alike.
inline double now()
{
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

} // namespace FlowBench
