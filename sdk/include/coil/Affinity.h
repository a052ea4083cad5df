// SPDX-License-Identifier: MIT
/*!
 * @file Affinity.h
 * @brief CPU affinity of the process and of the calling thread.
 *
 * A mask is the list of CPU numbers allowed to run the process or thread, e.g. {0, 2}; the
 * text form is the same list separated by commas ("0,2"), as in `exec_cxt.periodic.cpu_affinity`.
 */
#ifndef COIL_AFFINITY_H
#define COIL_AFFINITY_H

#include <string>
#include <vector>

namespace coil {
/*! CPU numbers, ascending. */
using CpuMask = std::vector<unsigned int>;

/*! The CPUs the process may run on; false when the system refuses to tell. */
bool getProcCpuAffinity(CpuMask &cpu_mask);
/*! Restricts the process to @p cpu_mask; false for an empty or impossible mask. */
bool setProcCpuAffinity(const CpuMask &cpu_mask);
/*! Restricts the process to the CPUs listed in @p cpu_mask ("0,2"). */
bool setProcCpuAffinity(const std::string &cpu_mask);
/*! The CPUs the calling thread may run on. */
bool getThreadCpuAffinity(CpuMask &cpu_mask);
/*! Restricts the calling thread to @p cpu_mask; false for an empty or impossible mask. */
bool setThreadCpuAffinity(const CpuMask &cpu_mask);
/*! Restricts the calling thread to the CPUs listed in @p cpu_mask ("0,2"). */
bool setThreadCpuAffinity(const std::string &cpu_mask);
} // namespace coil

#endif // COIL_AFFINITY_H
