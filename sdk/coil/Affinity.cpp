// SPDX-License-Identifier: MIT
#include <coil/Affinity.h>

#include <coil/stringutil.h>

#include <pthread.h>
#include <sched.h>

namespace coil {
namespace {
CpuMask toMask(const cpu_set_t &set)
{
    CpuMask mask;
    for (unsigned int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
        if (CPU_ISSET(cpu, &set))
            mask.push_back(cpu);
    }
    return mask;
}

bool toSet(const CpuMask &mask, cpu_set_t &set)
{
    CPU_ZERO(&set);
    for (unsigned int cpu : mask) {
        if (cpu >= CPU_SETSIZE)
            return false;
        CPU_SET(cpu, &set);
    }
    return !mask.empty();
}

// "0, 2,3" → {0, 2, 3}; false for anything that is not a list of CPU numbers.
bool parseMask(const std::string &text, CpuMask &mask)
{
    mask.clear();
    for (const std::string &item : coil::split(text, ",", true)) {
        unsigned int cpu = 0;
        if (!coil::stringTo(cpu, item.c_str()))
            return false;
        mask.push_back(cpu);
    }
    return !mask.empty();
}
} // namespace

bool getProcCpuAffinity(CpuMask &cpu_mask)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) != 0)
        return false;
    cpu_mask = toMask(set);
    return true;
}

bool setProcCpuAffinity(const CpuMask &cpu_mask)
{
    cpu_set_t set;
    return toSet(cpu_mask, set) && sched_setaffinity(0, sizeof(set), &set) == 0;
}

bool setProcCpuAffinity(const std::string &cpu_mask)
{
    CpuMask mask;
    return parseMask(cpu_mask, mask) && setProcCpuAffinity(mask);
}

bool getThreadCpuAffinity(CpuMask &cpu_mask)
{
    cpu_set_t set;
    CPU_ZERO(&set);
    if (pthread_getaffinity_np(pthread_self(), sizeof(set), &set) != 0)
        return false;
    cpu_mask = toMask(set);
    return true;
}

bool setThreadCpuAffinity(const CpuMask &cpu_mask)
{
    cpu_set_t set;
    return toSet(cpu_mask, set) && pthread_setaffinity_np(pthread_self(), sizeof(set), &set) == 0;
}

bool setThreadCpuAffinity(const std::string &cpu_mask)
{
    CpuMask mask;
    return parseMask(cpu_mask, mask) && setThreadCpuAffinity(mask);
}
} // namespace coil
