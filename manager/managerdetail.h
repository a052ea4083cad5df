// SPDX-License-Identifier: MIT
// Records the Manager keeps about its components, slaves and modules (private to manager/*.cpp).
#pragma once

#include "manager.h"
#include "rtobject.h"

namespace Runtime {

struct Manager::Component
{
    RtObject *servant = nullptr;
    RTC::RTObject_var reference;
    std::string instanceName;
    std::vector<std::string> names; ///< Naming paths it was bound under.
    std::string modulePath; ///< The module its factory came from; empty for built-in types.
};

struct Manager::Slave
{
    RTM::Manager_var reference;
    std::string name;    ///< manager.instance_name of the slave.
    std::string address; ///< host:port it serves on.
    pid_t pid = 0;       ///< Its process id (from its profile).
};

struct Manager::Module
{
    std::string path;
    std::string initFunction;
    void *handle = nullptr;
};

/// The module file whose init function the calling thread runs; empty when none.
std::string moduleBeingLoaded();
/// `<dir>/<type>.so` (or `.py`) of the first of @p dirs that has it; empty when none does.
std::string moduleInDirs(const std::string &type, const std::vector<std::string> &dirs);

/// A manager's instance name from its `manager.instance_name` (`%p` is its process id).
std::string expandedInstanceName(std::string format, pid_t pid);

} // namespace Runtime
