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
class ConfigAdmin;

// OpenRTM-aist 1.0's callback classes, now the configuration listeners.
using OnUpdateCallback = ConfigurationSetNameListener;
using OnUpdateParamCallback = ConfigurationParamListener;
using OnSetConfigurationSetCallback = ConfigurationSetListener;
using OnAddConfigurationAddCallback = ConfigurationSetListener;
using OnRemoveConfigurationSetCallback = ConfigurationSetNameListener;
using OnActivateSetCallback = ConfigurationSetNameListener;

/**
 * One configuration parameter bound to a variable: its name, its default and the text it was
 * last set from. update() converts a new text into the variable and tells the ConfigAdmin set
 * with setCallback(). The strings are not copied: @p name_ and @p def_val must outlive it.
 */
struct ConfigBase
{
    ConfigBase(const char *name_, const char *def_val)
        : name(name_)
        , default_value(def_val)
        , string_value("")
        , m_admin(nullptr)
        , m_callback(nullptr)
    {
    }
    virtual ~ConfigBase() = default;

    using CallbackFunc = void (ConfigAdmin::*)(const char *, const char *);

    void setCallback(ConfigAdmin *cadmin, CallbackFunc cbf)
    {
        m_admin = cadmin;
        m_callback = cbf;
    }
    /// Tells the ConfigAdmin set with setCallback() that @p key now has @p val.
    void notifyUpdate(const char *key, const char *val)
    {
        if (m_admin != nullptr && m_callback != nullptr)
            (m_admin->*m_callback)(key, val);
    }
    /// Sets the variable from @p val; false (the variable takes the default) when it does not convert.
    virtual bool update(const char *val) = 0;

    const char *name;
    const char *default_value;

protected:
    std::string string_value;
    ConfigAdmin *m_admin;
    CallbackFunc m_callback;
};

/// A parameter bound to a variable of type @p VarType, converted by @p TransFunc.
template <typename VarType, typename TransFunc = bool (*)(VarType &, const char *)>
class Config : public ConfigBase
{
public:
    Config(const char *conf_name, VarType &var, const char *def_val, TransFunc trans = coil::stringTo)
        : ConfigBase(conf_name, def_val)
        , m_var(var)
        , m_trans(trans)
    {
    }
    ~Config() override = default;

    bool update(const char *val) override
    {
        if (string_value == val)
            return true;
        string_value = val;
        const bool converted = (*m_trans)(m_var, val);
        if (!converted)
            (*m_trans)(m_var, default_value);
        notifyUpdate(name, val);
        return converted;
    }

protected:
    VarType &m_var;
    TransFunc m_trans;
};

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

    /// Unbinds @p param_name: its variable no longer changes. False when it is not bound.
    bool unbindParameter(const char *param_name);
    /// The parameters whose variables the last update changed.
    coil::vstring &changedParameters();
    /// Every configuration set, as a node named by its id (the pointers stay the admin's).
    const std::vector<coil::Properties *> &getConfigurationSets();

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

    // OpenRTM-aist 1.0's callbacks: each adds a listener that stays the caller's.
    void setOnUpdate(OnUpdateCallback *cb);
    void setOnUpdateParam(OnUpdateParamCallback *cb);
    void setOnSetConfigurationSet(OnSetConfigurationSetCallback *cb);
    void setOnAddConfigurationSet(OnAddConfigurationAddCallback *cb);
    void setOnRemoveConfigurationSet(OnRemoveConfigurationSetCallback *cb);
    void setOnActivateSet(OnActivateSetCallback *cb);

    /// RT Studio: the runtime's configuration underneath (what SDOPackage::Configuration_impl serves).
    ::Runtime::ConfigAdmin &engine();

    /**
     * RT Studio: binds parameter @p name (default @p defaultValue, which the caller has applied
     * already) to @p setter, called with each new value when the configuration is applied; the
     * setter answers whether the text converted. What bindParameter() uses, and language bindings
     * whose variables are not C++ ones.
     */
    void bindSetter(const char *name, const char *defaultValue, std::function<bool(const char *)> setter);

protected:
    /// Called by a parameter (ConfigBase) whose variable changed: the parameter listeners hear of it.
    void onUpdateParam(const char *config_param, const char *config_value);

private:
    struct Private;
    Private *d;
};
} // namespace RTC

#endif // RTM_CONFIGADMIN_H
