// SPDX-License-Identifier: MIT
#include "executioncontextfactory.h"

#include "triggeredexecutioncontext.h"

#include <algorithm>
#include <set>

namespace Runtime {

namespace {

/// A number from @p properties; an unreadable one keeps @p fallback (OpenRTM's defaults).
double number(const Properties &properties, const std::string &key, double fallback)
{
    try {
        return std::stod(properties.value(key, std::to_string(fallback)));
    } catch (...) {
        return fallback;
    }
}

double rateOf(const Properties &p) { return number(p, "exec_cxt.periodic.rate", 1000.0); }
double timeoutOf(const Properties &p) { return number(p, "exec_cxt.transition_timeout", 0.5); }

ExecutionContextFactory::Create triggered(const std::string &type, TriggeredExecutionContext::Tick mode)
{
    return [type, mode](const Properties &p, std::string *) -> ExecutionContext * {
        return new TriggeredExecutionContext(type, mode, rateOf(p), timeoutOf(p));
    };
}

} // namespace

ExecutionContextFactory::ExecutionContextFactory()
{
    m_creators["PeriodicExecutionContext"] = [](const Properties &p, std::string *) -> ExecutionContext * {
        return new PeriodicExecutionContext(rateOf(p), timeoutOf(p));
    };
    using Tick = TriggeredExecutionContext::Tick;
    m_creators["ExtTrigExecutionContext"] = triggered("ExtTrigExecutionContext", Tick::Asynchronous);
    m_creators["OpenHRPExecutionContext"] = triggered("OpenHRPExecutionContext", Tick::Synchronous);
    m_creators["SimulatorExecutionContext"] = triggered("SimulatorExecutionContext", Tick::Synchronous);
}

ExecutionContextFactory &ExecutionContextFactory::instance()
{
    static ExecutionContextFactory factory;
    return factory;
}

bool ExecutionContextFactory::add(const std::string &type, Create create)
{
    if (type.empty() || !create)
        return false;
    std::lock_guard lock(m_mutex);
    return m_creators.emplace(type, std::move(create)).second;
}

void ExecutionContextFactory::replace(const std::string &type, Create create)
{
    if (type.empty() || !create)
        return;
    std::lock_guard lock(m_mutex);
    m_creators[type] = std::move(create);
}

bool ExecutionContextFactory::remove(const std::string &type)
{
    std::lock_guard lock(m_mutex);
    return m_creators.erase(type) > 0;
}

void ExecutionContextFactory::setExternal(ExternalTypes types, ExternalCreate create)
{
    std::lock_guard lock(m_mutex);
    m_externalTypes = std::move(types);
    m_externalCreate = std::move(create);
}

bool ExecutionContextFactory::contains(const std::string &type)
{
    const std::vector<std::string> names = types();
    return std::find(names.begin(), names.end(), type) != names.end();
}

std::vector<std::string> ExecutionContextFactory::types()
{
    std::set<std::string> names;
    ExternalTypes external;
    {
        std::lock_guard lock(m_mutex);
        for (const auto &entry : m_creators)
            names.insert(entry.first);
        external = m_externalTypes;
    }
    // Outside the lock: the external table has a lock of its own.
    if (external) {
        for (const std::string &name : external())
            names.insert(name);
    }
    return {names.begin(), names.end()};
}

std::string ExecutionContextFactory::typeOf(const Properties &properties)
{
    const std::string type = properties.value("exec_cxt.periodic.type");
    return type.empty() ? std::string("PeriodicExecutionContext") : type;
}

std::string ExecutionContextFactory::check(const std::string &type)
{
    if (contains(type))
        return {};
    std::string known;
    for (const std::string &name : types())
        known += (known.empty() ? "" : ", ") + name;
    return "unknown execution context type '" + type + "' (exec_cxt.periodic.type); known types: " + known;
}

ExecutionContext *ExecutionContextFactory::create(const std::string &type, const Properties &properties,
                                                  std::string *error)
{
    Create create;
    ExternalCreate external;
    {
        std::lock_guard lock(m_mutex);
        auto it = m_creators.find(type);
        if (it != m_creators.end())
            create = it->second;
        external = m_externalCreate;
    }
    if (!create && external && contains(type))
        create = [&external, &type](const Properties &p, std::string *e) { return external(type, p, e); };
    if (!create) {
        if (error)
            *error = check(type);
        return nullptr;
    }
    std::string problem;
    ExecutionContext *context = create(properties, &problem);
    if (!context && error)
        *error = problem.empty() ? "execution context type '" + type + "' could not be created" : problem;
    return context;
}

} // namespace Runtime
