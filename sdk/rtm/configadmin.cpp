// SPDX-License-Identifier: MIT
#include <rtm/ConfigAdmin.h>

#include "listenerarrays.h"
#include "listenerset.h"
#include "sdkinternal.h"

#include <configadmin.h>

#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace RTC {

const char *ConfigurationParamListener::toString(ConfigurationParamListenerType type)
{
    return type == ConfigurationParamListenerType::ON_UPDATE_CONFIG_PARAM ? "ON_UPDATE_CONFIG_PARAM" : "";
}
ConfigurationParamListener::~ConfigurationParamListener() = default;

const char *ConfigurationSetListener::toString(ConfigurationSetListenerType type)
{
    static const char *const names[] = {"ON_SET_CONFIG_SET", "ON_ADD_CONFIG_SET"};
    return size_t(type) < std::size(names) ? names[size_t(type)] : "";
}
ConfigurationSetListener::~ConfigurationSetListener() = default;

const char *ConfigurationSetNameListener::toString(ConfigurationSetNameListenerType type)
{
    static const char *const names[] = {"ON_UPDATE_CONFIG_SET", "ON_REMOVE_CONFIG_SET", "ON_ACTIVATE_CONFIG_SET"};
    return size_t(type) < std::size(names) ? names[size_t(type)] : "";
}
ConfigurationSetNameListener::~ConfigurationSetNameListener() = default;

ConfigurationParamListenerHolder::ConfigurationParamListenerHolder() = default;
ConfigurationParamListenerHolder::~ConfigurationParamListenerHolder() = default;
void ConfigurationParamListenerHolder::notify(const char *config_set_name, const char *config_param_name)
{
    LISTENERHOLDER_CALLBACK(operator(), (config_set_name, config_param_name));
}

ConfigurationSetListenerHolder::ConfigurationSetListenerHolder() = default;
ConfigurationSetListenerHolder::~ConfigurationSetListenerHolder() = default;
void ConfigurationSetListenerHolder::notify(const coil::Properties &config_set)
{
    LISTENERHOLDER_CALLBACK(operator(), (config_set));
}

ConfigurationSetNameListenerHolder::ConfigurationSetNameListenerHolder() = default;
ConfigurationSetNameListenerHolder::~ConfigurationSetNameListenerHolder() = default;
void ConfigurationSetNameListenerHolder::notify(const char *config_set_name)
{
    LISTENERHOLDER_CALLBACK(operator(), (config_set_name));
}

ConfigurationListeners::ConfigurationListeners() = default;
ConfigurationListeners::~ConfigurationListeners() = default;

bool ConfigurationListeners::addListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener,
                                         bool autoclean)
{
    return Sdk::addTo(configparam_, type, listener, autoclean);
}

bool ConfigurationListeners::addListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener,
                                         bool autoclean)
{
    return Sdk::addTo(configset_, type, listener, autoclean);
}

bool ConfigurationListeners::addListener(ConfigurationSetNameListenerType type,
                                         ConfigurationSetNameListener *listener, bool autoclean)
{
    return Sdk::addTo(configsetname_, type, listener, autoclean);
}

bool ConfigurationListeners::removeListener(ConfigurationParamListenerType type, ConfigurationParamListener *listener)
{
    return Sdk::removeFrom(configparam_, type, listener);
}

bool ConfigurationListeners::removeListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener)
{
    return Sdk::removeFrom(configset_, type, listener);
}

bool ConfigurationListeners::removeListener(ConfigurationSetNameListenerType type,
                                            ConfigurationSetNameListener *listener)
{
    return Sdk::removeFrom(configsetname_, type, listener);
}

bool ConfigurationListeners::notify(ConfigurationParamListenerType type, const char *config_set_name,
                                    const char *config_param_name)
{
    return Sdk::notifyIn(configparam_, type, config_set_name, config_param_name);
}

bool ConfigurationListeners::notify(ConfigurationSetListenerType type, const coil::Properties &config_set)
{
    return Sdk::notifyIn(configset_, type, config_set);
}

bool ConfigurationListeners::notify(ConfigurationSetNameListenerType type, const char *config_set_name)
{
    return Sdk::notifyIn(configsetname_, type, config_set_name);
}

struct ConfigAdmin::Private
{
    explicit Private(Runtime::ConfigAdmin &admin)
        : admin(admin)
    {
    }

    void onEvent(Runtime::ConfigAdmin::Event event, const std::string &setId);
    void notifyName(ConfigurationSetNameListenerType type, const std::string &setId)
    {
        nameListeners[size_t(type)].forEach([&setId](ConfigurationSetNameListener &l) { l(setId.c_str()); });
    }
    void onParameter(const std::string &name);
    coil::Properties &cachedSet(const std::string &id);

    Runtime::ConfigAdmin &admin;
    std::recursive_mutex mutex;
    Sdk::ListenerSet<ConfigurationParamListener> paramListeners;
    Sdk::ListenerSet<ConfigurationSetListener> setListeners[size_t(ConfigurationSetListenerType::CONFIG_SET_LISTENER_NUM)];
    Sdk::ListenerSet<ConfigurationSetNameListener>
        nameListeners[size_t(ConfigurationSetNameListenerType::CONFIG_SET_NAME_LISTENER_NUM)];
    /// The text each bound variable was last set from: listeners hear of real changes only.
    std::map<std::string, std::string> applied;
    std::map<std::string, coil::Properties> sets;
    std::string activeId;
    bool changed = false;
    /// Parameters changed by the update under way, and by the last one over.
    coil::vstring pending;
    coil::vstring changedParams;
    std::vector<coil::Properties *> setList;
};

coil::Properties &ConfigAdmin::Private::cachedSet(const std::string &id)
{
    coil::Properties node(id.c_str());
    const Runtime::Properties values = admin.set(id);
    for (const auto &[key, value] : values.entries())
        node.setProperty(key, value);
    return sets[id] = node;
}

void ConfigAdmin::Private::onEvent(Runtime::ConfigAdmin::Event event, const std::string &setId)
{
    using Event = Runtime::ConfigAdmin::Event;
    std::lock_guard lock(mutex);
    switch (event) {
    case Event::SetValuesChanged:
    case Event::SetAdded: {
        changed = changed || event == Event::SetValuesChanged;
        const coil::Properties &set = cachedSet(setId);
        const auto type = event == Event::SetAdded ? ConfigurationSetListenerType::ON_ADD_CONFIG_SET
                                                   : ConfigurationSetListenerType::ON_SET_CONFIG_SET;
        setListeners[size_t(type)].forEach([&set](ConfigurationSetListener &listener) { listener(set); });
        return;
    }
    case Event::SetRemoved:
        notifyName(ConfigurationSetNameListenerType::ON_REMOVE_CONFIG_SET, setId);
        return;
    case Event::SetActivated:
        changed = true;
        notifyName(ConfigurationSetNameListenerType::ON_ACTIVATE_CONFIG_SET, setId);
        return;
    case Event::Updated:
        changed = false;
        changedParams.swap(pending);
        pending.clear();
        notifyName(ConfigurationSetNameListenerType::ON_UPDATE_CONFIG_SET, setId);
        return;
    }
}

ConfigAdmin::ConfigAdmin(Runtime::ConfigAdmin &admin)
    : d(new Private(admin))
{
    Private *self = d;
    admin.setObserver([self](Runtime::ConfigAdmin::Event event, const std::string &setId) { self->onEvent(event, setId); });
}

ConfigAdmin::~ConfigAdmin()
{
    d->admin.setObserver({});
    delete d;
}

void ConfigAdmin::bindSetter(const char *name, const char *defaultValue, std::function<bool(const char *)> setter)
{
    const std::string parameter(name);
    {
        std::lock_guard lock(d->mutex);
        d->applied[parameter] = defaultValue;
    }
    Private *self = d;
    d->admin.bindParameter(parameter, defaultValue, [self, parameter, setter](const std::string &text) {
        {
            std::lock_guard lock(self->mutex);
            auto it = self->applied.find(parameter);
            if (it != self->applied.end() && it->second == text)
                return true;
        }
        if (!setter(text.c_str()))
            return false;
        std::lock_guard lock(self->mutex);
        self->applied[parameter] = text;
        self->pending.push_back(parameter);
        const std::string active = self->admin.activeSetId();
        self->paramListeners.forEach(
            [&](ConfigurationParamListener &listener) { listener(active.c_str(), parameter.c_str()); });
        return true;
    });
}

Runtime::ConfigAdmin &ConfigAdmin::engine()
{
    return d->admin;
}

void ConfigAdmin::update()
{
    d->admin.update();
}

void ConfigAdmin::update(const char *config_set)
{
    if (config_set != nullptr && d->admin.activeSetId() == config_set)
        d->admin.update();
}

void ConfigAdmin::update(const char *config_set, const char *config_param)
{
    // The runtime applies a set as a whole; unchanged parameters are skipped by their setters.
    if (config_param != nullptr && isExist(config_param))
        update(config_set);
}

bool ConfigAdmin::unbindParameter(const char *param_name)
{
    if (param_name == nullptr || !d->admin.unbindParameter(param_name))
        return false;
    std::lock_guard lock(d->mutex);
    d->applied.erase(param_name);
    return true;
}

coil::vstring &ConfigAdmin::changedParameters()
{
    std::lock_guard lock(d->mutex);
    return d->changedParams;
}

const std::vector<coil::Properties *> &ConfigAdmin::getConfigurationSets()
{
    std::lock_guard lock(d->mutex);
    d->setList.clear();
    for (const std::string &id : d->admin.setIds())
        d->setList.push_back(&d->cachedSet(id));
    return d->setList;
}

void ConfigAdmin::onUpdateParam(const char *config_param, const char *config_value)
{
    (void)config_value; // the listeners are told the set and the parameter, as for bound variables
    if (config_param == nullptr)
        return;
    std::lock_guard lock(d->mutex);
    d->changedParams.push_back(config_param);
    const std::string active = d->admin.activeSetId();
    d->paramListeners.forEach([&](ConfigurationParamListener &listener) { listener(active.c_str(), config_param); });
}

void ConfigAdmin::setOnUpdate(OnUpdateCallback *cb)
{
    addConfigurationSetNameListener(ConfigurationSetNameListenerType::ON_UPDATE_CONFIG_SET, cb, false);
}

void ConfigAdmin::setOnUpdateParam(OnUpdateParamCallback *cb)
{
    addConfigurationParamListener(ConfigurationParamListenerType::ON_UPDATE_CONFIG_PARAM, cb, false);
}

void ConfigAdmin::setOnSetConfigurationSet(OnSetConfigurationSetCallback *cb)
{
    addConfigurationSetListener(ConfigurationSetListenerType::ON_SET_CONFIG_SET, cb, false);
}

void ConfigAdmin::setOnAddConfigurationSet(OnAddConfigurationAddCallback *cb)
{
    addConfigurationSetListener(ConfigurationSetListenerType::ON_ADD_CONFIG_SET, cb, false);
}

void ConfigAdmin::setOnRemoveConfigurationSet(OnRemoveConfigurationSetCallback *cb)
{
    addConfigurationSetNameListener(ConfigurationSetNameListenerType::ON_REMOVE_CONFIG_SET, cb, false);
}

void ConfigAdmin::setOnActivateSet(OnActivateSetCallback *cb)
{
    addConfigurationSetNameListener(ConfigurationSetNameListenerType::ON_ACTIVATE_CONFIG_SET, cb, false);
}

bool ConfigAdmin::isExist(const char *param_name)
{
    if (param_name == nullptr)
        return false;
    for (const std::string &name : d->admin.parameterNames()) {
        if (name == param_name)
            return true;
    }
    return false;
}

bool ConfigAdmin::isChanged()
{
    std::lock_guard lock(d->mutex);
    return d->changed;
}

bool ConfigAdmin::isActive()
{
    return d->admin.isActive();
}

const char *ConfigAdmin::getActiveId()
{
    std::lock_guard lock(d->mutex);
    d->activeId = d->admin.activeSetId();
    return d->activeId.c_str();
}

bool ConfigAdmin::haveConfig(const char *config_id)
{
    return config_id != nullptr && d->admin.hasSet(config_id);
}

const coil::Properties &ConfigAdmin::getConfigurationSet(const char *config_id)
{
    std::lock_guard lock(d->mutex);
    return d->cachedSet(config_id ? config_id : "");
}

const coil::Properties &ConfigAdmin::getActiveConfigurationSet()
{
    std::lock_guard lock(d->mutex);
    return d->cachedSet(d->admin.activeSetId());
}

bool ConfigAdmin::setConfigurationSetValues(const coil::Properties &config_set)
{
    Runtime::Properties values;
    for (const std::string &key : config_set.propertyNames())
        values.set(key, config_set.getProperty(key));
    return d->admin.setValues(config_set.getName(), values);
}

bool ConfigAdmin::addConfigurationSet(const coil::Properties &config_set)
{
    Runtime::Properties values;
    for (const std::string &key : config_set.propertyNames())
        values.set(key, config_set.getProperty(key));
    return d->admin.addSet(config_set.getName(), values);
}

bool ConfigAdmin::removeConfigurationSet(const char *config_id)
{
    return config_id != nullptr && d->admin.removeSet(config_id);
}

bool ConfigAdmin::activateConfigurationSet(const char *config_id)
{
    return config_id != nullptr && d->admin.activate(config_id);
}

void ConfigAdmin::addConfigurationParamListener(ConfigurationParamListenerType type,
                                                ConfigurationParamListener *listener, bool autoclean)
{
    std::lock_guard lock(d->mutex);
    if (type == ConfigurationParamListenerType::ON_UPDATE_CONFIG_PARAM)
        d->paramListeners.add(listener, autoclean);
}

void ConfigAdmin::removeConfigurationParamListener(ConfigurationParamListenerType type,
                                                   ConfigurationParamListener *listener)
{
    std::lock_guard lock(d->mutex);
    if (type == ConfigurationParamListenerType::ON_UPDATE_CONFIG_PARAM)
        d->paramListeners.remove(listener);
}

void ConfigAdmin::addConfigurationSetListener(ConfigurationSetListenerType type, ConfigurationSetListener *listener,
                                              bool autoclean)
{
    std::lock_guard lock(d->mutex);
    if (type < ConfigurationSetListenerType::CONFIG_SET_LISTENER_NUM)
        d->setListeners[size_t(type)].add(listener, autoclean);
}

void ConfigAdmin::removeConfigurationSetListener(ConfigurationSetListenerType type,
                                                 ConfigurationSetListener *listener)
{
    std::lock_guard lock(d->mutex);
    if (type < ConfigurationSetListenerType::CONFIG_SET_LISTENER_NUM)
        d->setListeners[size_t(type)].remove(listener);
}

void ConfigAdmin::addConfigurationSetNameListener(ConfigurationSetNameListenerType type,
                                                  ConfigurationSetNameListener *listener, bool autoclean)
{
    std::lock_guard lock(d->mutex);
    if (type < ConfigurationSetNameListenerType::CONFIG_SET_NAME_LISTENER_NUM)
        d->nameListeners[size_t(type)].add(listener, autoclean);
}

void ConfigAdmin::removeConfigurationSetNameListener(ConfigurationSetNameListenerType type,
                                                     ConfigurationSetNameListener *listener)
{
    std::lock_guard lock(d->mutex);
    if (type < ConfigurationSetNameListenerType::CONFIG_SET_NAME_LISTENER_NUM)
        d->nameListeners[size_t(type)].remove(listener);
}

} // namespace RTC
