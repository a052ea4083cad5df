// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace Runtime {

class ExecutionContext;

/**
 * The one place execution contexts are made, keyed by their type name as OpenRTM's ECFactory:
 * `PeriodicExecutionContext`, `ExtTrigExecutionContext`, `OpenHRPExecutionContext`,
 * `SimulatorExecutionContext`, plus whatever a program registers here or in the external table
 * (setExternal()). A component's owned context is
 * of the type its `exec_cxt.periodic.type` names, at `exec_cxt.periodic.rate`.
 */
class ExecutionContextFactory
{
public:
    /// Makes a context from the component's properties (`exec_cxt.*`); null with @p error on failure.
    using Create = std::function<ExecutionContext *(const Properties &properties, std::string *error)>;

    static ExecutionContextFactory &instance();

    /// Registers @p create for @p type; false when the type is known already.
    bool add(const std::string &type, Create create);
    /**
     * A second table of types the factory consults after its own (the component SDK's
     * RTC::ExecutionContextFactory): @p types lists them, @p create makes one by type name.
     */
    using ExternalTypes = std::function<std::vector<std::string>()>;
    using ExternalCreate =
        std::function<ExecutionContext *(const std::string &type, const Properties &properties, std::string *error)>;
    void setExternal(ExternalTypes types, ExternalCreate create);
    /// Registers @p create for @p type, in place of the one it had if any.
    void replace(const std::string &type, Create create);
    bool remove(const std::string &type);
    bool contains(const std::string &type);
    /// The known type names, sorted.
    std::vector<std::string> types();
    /// The type @p properties ask for (`exec_cxt.periodic.type`, PeriodicExecutionContext by default).
    static std::string typeOf(const Properties &properties);
    /// Empty when @p type is known, else the message refusing it (naming it and the known types).
    std::string check(const std::string &type);
    /// A new context of @p type; null with @p error naming the type and the known ones when unknown.
    ExecutionContext *create(const std::string &type, const Properties &properties, std::string *error);

private:
    ExecutionContextFactory();

    std::mutex m_mutex;
    std::map<std::string, Create> m_creators;
    ExternalTypes m_externalTypes;
    ExternalCreate m_externalCreate;
};

} // namespace Runtime
