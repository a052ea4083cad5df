// SPDX-License-Identifier: MIT
// A component's configuration sets and the variables bound to their parameters.
#ifndef RTM_CONFIGADMIN_H
#define RTM_CONFIGADMIN_H

#include <rtm/ConfigurationListener.h>
#include <rtm/RTC.h>

#include <coil/Properties.h>
#include <coil/stringutil.h>

#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace Runtime
{
class ConfigAdmin;
}

namespace RTC
{
/**
 * The configuration of one component: named sets of parameter values, one of them active, and
 * the component's variables bound to the parameters. A variable changes only when the
 * configuration is applied (update(), done by the framework before onExecute and in
 * on_state_update as in OpenRTM-aist), never in the middle of the component's own code.
 */
class ConfigAdmin
{
public:
    explicit ConfigAdmin(::Runtime::ConfigAdmin &admin);
    ~ConfigAdmin();
    ConfigAdmin(const ConfigAdmin &) = delete;
    ConfigAdmin &operator=(const ConfigAdmin &) = delete;

    /**
     * Binds @p var to parameter @p param_name with default @p def_val; @p trans converts text to
     * the variable (coil::stringTo by default; a `std::vector<T>` needs an `operator>>` for it,
     * which generated components bring in VectorConvert.h). False when the name is taken or the
     * default does not convert.
     */
    template <typename VarType>
    bool bindParameter(const char *param_name, VarType &var, const char *def_val,
                       bool (*trans)(VarType &, const char *) = coil::stringTo)
    {
        if (param_name == nullptr || def_val == nullptr || isExist(param_name) || !trans(var, def_val))
            return false;
        VarType *target = &var;
        bindSetter(param_name, def_val, [target, trans](const char *text) { return trans(*target, text); });
        return true;
    }

    /// Applies the active set if it changed since the last time.
    void update();
    /// Applies @p config_set when it is the active set.
    void update(const char *config_set);
    /// Applies one parameter of @p config_set when it is the active set.
    void update(const char *config_set, const char *config_param);

    bool isExist(const char *param_name);
    /// True when a set was changed and not applied yet.
    bool isChanged();
    const char *getActiveId();
    bool haveConfig(const char *config_id);
    /// False after a set was added, written or removed, until one is activated.
    bool isActive();

    /// Set @p config_id as a node whose name is the id and whose children are the parameters.
    const coil::Properties &getConfigurationSet(const char *config_id);
    const coil::Properties &getActiveConfigurationSet();
    /// Sets values of the set named by config_set.getName(); false when it does not exist.
    bool setConfigurationSetValues(const coil::Properties &config_set);
    bool addConfigurationSet(const coil::Properties &config_set);
    bool removeConfigurationSet(const char *config_id);
    bool activateConfigurationSet(const char *config_id);

    void addConfigurationParamListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener,
                                       bool autoclean = true);
    void removeConfigurationParamListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener);
    void addConfigurationSetListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener,
                                     bool autoclean = true);
    void removeConfigurationSetListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener);
    void addConfigurationSetNameListener(ConfigurationSetNameListenerType type, ConfigurationSetNameListener *listener,
                                         bool autoclean = true);
    void removeConfigurationSetNameListener(ConfigurationSetNameListenerType type,
                                            ConfigurationSetNameListener *listener);

    /// RT Studio: the runtime's configuration underneath (what SDOPackage::Configuration_impl serves).
    ::Runtime::ConfigAdmin &engine();

private:
    void bindSetter(const char *name, const char *defaultValue, std::function<bool(const char *)> setter);

    struct Private;
    Private *d;
};
} // namespace RTC

#endif // RTM_CONFIGADMIN_H
