// SPDX-License-Identifier: MIT
#pragma once

#include "pyinterpreter.h"

#include <rtm/ConfigurationListener.h>

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * Python configuration listeners (OpenRTM_aist.ConfigurationParamListener, …SetListener,
 * …SetNameListener) behind the SDK's listener interfaces. The configuration calls them from the
 * thread that applies a change; they take the GIL, and an exception is printed, never thrown into
 * the runtime. The component deletes them (autoclean), from threads that may not hold the GIL.
 */
template <typename Listener>
class PyConfigurationListener : public Listener
{
public:
    explicit PyConfigurationListener(pybind11::object listener)
        : m_listener(std::move(listener))
    {
    }
    ~PyConfigurationListener() override { releasePython(m_listener); }

protected:
    template <typename... Arguments>
    void call(Arguments &&...arguments)
    {
        if (!interpreterAlive())
            return;
        Gil gil;
        try {
            m_listener(std::forward<Arguments>(arguments)...);
        } catch (pybind11::error_already_set &error) {
            printError("a configuration listener raised an exception:", error);
        }
    }

private:
    pybind11::object m_listener;
};

/// `listener(config_set_name, config_param_name)` when a bound parameter takes a new value.
class PyConfigurationParamListener : public PyConfigurationListener<RTC::ConfigurationParamListener>
{
public:
    using PyConfigurationListener::PyConfigurationListener;
    void operator()(const char *config_set_name, const char *config_param_name) override
    {
        call(std::string(config_set_name), std::string(config_param_name));
    }
};

/// `listener(config_set)` with the set's Properties when a set is changed or added.
class PyConfigurationSetListener : public PyConfigurationListener<RTC::ConfigurationSetListener>
{
public:
    using PyConfigurationListener::PyConfigurationListener;
    void operator()(const coil::Properties &config_set) override { call(coil::Properties(config_set)); }
};

/// `listener(config_set_name)` when a set is updated, removed or activated.
class PyConfigurationSetNameListener : public PyConfigurationListener<RTC::ConfigurationSetNameListener>
{
public:
    using PyConfigurationListener::PyConfigurationListener;
    void operator()(const char *config_set_name) override { call(std::string(config_set_name)); }
};

} // namespace RtPython
