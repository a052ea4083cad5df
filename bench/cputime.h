// SPDX-License-Identifier: MIT
#pragma once

#include <sys/resource.h>

/// CPU seconds this process has used so far, user and system, all threads.
inline double processCpuSeconds()
{
    rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval &t) { return double(t.tv_sec) + double(t.tv_usec) / 1e6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}
