// SPDX-License-Identifier: MIT
// Listeners of a component's configuration: parameter updates and configuration-set changes.
#ifndef RTM_CONFIGURATIONLISTENER_H
#define RTM_CONFIGURATIONLISTENER_H

#include <coil/Properties.h>
#include <rtm/ListenerHolder.h>

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

class ConfigurationParamListenerHolder : public ::RTM::util::ListenerHolder<ConfigurationParamListener>
{
public:
    ConfigurationParamListenerHolder();
    ~ConfigurationParamListenerHolder() override;
    void notify(const char *config_set_name, const char *config_param_name);
};

class ConfigurationSetListenerHolder : public ::RTM::util::ListenerHolder<ConfigurationSetListener>
{
public:
    ConfigurationSetListenerHolder();
    ~ConfigurationSetListenerHolder() override;
    void notify(const coil::Properties &config_set);
};

class ConfigurationSetNameListenerHolder : public ::RTM::util::ListenerHolder<ConfigurationSetNameListener>
{
public:
    ConfigurationSetNameListenerHolder();
    ~ConfigurationSetNameListenerHolder() override;
    void notify(const char *config_set_name);
};

/// A configuration's listeners, one holder per event; a type out of range answers false.
class ConfigurationListeners
{
public:
    ConfigurationListeners();
    ~ConfigurationListeners();
    bool addListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener,
                     bool autoclean = true);
    bool addListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener, bool autoclean = true);
    bool addListener(ConfigurationSetNameListenerType type, ConfigurationSetNameListener *listener,
                     bool autoclean = true);
    bool removeListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener);
    bool removeListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener);
    bool removeListener(ConfigurationSetNameListenerType type, ConfigurationSetNameListener *listener);
    bool notify(ConfigurationParamListenerType type, const char *config_set_name, const char *config_param_name);
    bool notify(ConfigurationSetListenerType type, const coil::Properties &config_set);
    bool notify(ConfigurationSetNameListenerType type, const char *config_set_name);

private:
    std::array<ConfigurationParamListenerHolder,
               static_cast<uint8_t>(ConfigurationParamListenerType::CONFIG_PARAM_LISTENER_NUM)>
        configparam_;
    std::array<ConfigurationSetListenerHolder,
               static_cast<uint8_t>(ConfigurationSetListenerType::CONFIG_SET_LISTENER_NUM)>
        configset_;
    std::array<ConfigurationSetNameListenerHolder,
               static_cast<uint8_t>(ConfigurationSetNameListenerType::CONFIG_SET_NAME_LISTENER_NUM)>
        configsetname_;
};
} // namespace RTC

#endif // RTM_CONFIGURATIONLISTENER_H
