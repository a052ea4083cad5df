// SPDX-License-Identifier: MIT
// Listeners of a component's configuration: parameter updates and configuration-set changes.
#ifndef RTM_CONFIGURATIONLISTENER_H
#define RTM_CONFIGURATIONLISTENER_H

#include <coil/Properties.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace RTC
{
enum class ConfigurationParamListenerType : uint8_t
{
    ON_UPDATE_CONFIG_PARAM,
    CONFIG_PARAM_LISTENER_NUM
};

/// Called when a bound variable took a new value (in the execution context's thread).
class ConfigurationParamListener
{
public:
    static const char *toString(ConfigurationParamListenerType type);
    virtual ~ConfigurationParamListener();
    virtual void operator()(const char *config_set_name, const char *config_param_name) = 0;
};

enum class ConfigurationSetListenerType : uint8_t
{
    ON_SET_CONFIG_SET,
    ON_ADD_CONFIG_SET,
    CONFIG_SET_LISTENER_NUM
};

/// Called with a configuration set whose values were set, or that was added.
class ConfigurationSetListener
{
public:
    static const char *toString(ConfigurationSetListenerType type);
    virtual ~ConfigurationSetListener();
    virtual void operator()(const coil::Properties &config_set) = 0;
};

enum class ConfigurationSetNameListenerType : uint8_t
{
    ON_UPDATE_CONFIG_SET,
    ON_REMOVE_CONFIG_SET,
    ON_ACTIVATE_CONFIG_SET,
    CONFIG_SET_NAME_LISTENER_NUM
};

/// Called with the name of a configuration set that was applied, removed or activated.
class ConfigurationSetNameListener
{
public:
    static const char *toString(ConfigurationSetNameListenerType type);
    virtual ~ConfigurationSetNameListener();
    virtual void operator()(const char *config_set_name) = 0;
};

// The unqualified names of OpenRTM-aist 1.x.
static const ConfigurationParamListenerType ON_UPDATE_CONFIG_PARAM = ConfigurationParamListenerType::ON_UPDATE_CONFIG_PARAM;
static const ConfigurationSetListenerType ON_SET_CONFIG_SET = ConfigurationSetListenerType::ON_SET_CONFIG_SET;
static const ConfigurationSetListenerType ON_ADD_CONFIG_SET = ConfigurationSetListenerType::ON_ADD_CONFIG_SET;
static const ConfigurationSetNameListenerType ON_UPDATE_CONFIG_SET = ConfigurationSetNameListenerType::ON_UPDATE_CONFIG_SET;
static const ConfigurationSetNameListenerType ON_REMOVE_CONFIG_SET = ConfigurationSetNameListenerType::ON_REMOVE_CONFIG_SET;
static const ConfigurationSetNameListenerType ON_ACTIVATE_CONFIG_SET =
    ConfigurationSetNameListenerType::ON_ACTIVATE_CONFIG_SET;
} // namespace RTC

#endif // RTM_CONFIGURATIONLISTENER_H
