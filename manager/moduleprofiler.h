// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <ctime>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace Runtime {

/**
 * The component types loadable modules register, as get_loadable_modules lists them: each module
 * is loaded by a process of its own (`rtmanager --module-profile FILE`, as OpenRTM-aist's manager
 * runs rtcprof), so that a module never runs in the manager before it is asked to load it. What a
 * file registers is kept until the file changes. Set the program before profiles() is called.
 */
class ModuleProfiler
{
public:
    /// The program that answers `--module-profile FILE` (rtmanager); none: nothing is profiled.
    void setProgram(std::string program) { m_program = std::move(program); }
    bool hasProgram() const { return !m_program.empty(); }

    /// The factory profiles each of @p paths registers, in order: none for a file that does not
    /// load, registers nothing or takes longer than @p timeoutMs.
    std::vector<std::vector<Properties>> profiles(const std::vector<std::string> &paths,
                                                  int timeoutMs);

    /// What `rtmanager --module-profile FILE` prints of @p factories, and reading it back.
    static std::string format(const std::vector<Properties> &factories);
    static std::vector<Properties> parse(const std::string &text);

private:
    struct Entry
    {
        timespec modified {};
        long long size = -1;
        std::vector<Properties> factories;
    };
    /// std::nullopt when the process did not end in time (asked again next time).
    std::optional<std::vector<Properties>> profileInProcess(const std::string &path,
                                                            int timeoutMs) const;

    std::string m_program;
    std::mutex m_mutex;
    std::map<std::string, Entry> m_known;
};

} // namespace Runtime
