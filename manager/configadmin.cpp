// SPDX-License-Identifier: MIT
#include "configadmin.h"

namespace Runtime {

void ConfigAdmin::bindParameter(const std::string &name, const std::string &defaultValue, Setter setter)
{
    std::lock_guard lock(m_mutex);
    m_parameters.emplace_back(name, std::move(setter));
    if (!m_sets["default"].contains(name))
        m_sets["default"].set(name, defaultValue);
    m_dirty = true;
}

bool ConfigAdmin::unbindParameter(const std::string &name)
{
    std::lock_guard lock(m_mutex);
    for (auto it = m_parameters.begin(); it != m_parameters.end(); ++it) {
        if (it->first == name) {
            m_parameters.erase(it);
            return true;
        }
    }
    return false;
}

void ConfigAdmin::applyProperties(const Properties &properties)
{
    std::lock_guard lock(m_mutex);
    const Properties conf = properties.subtree("conf");
    for (const auto &[key, value] : conf.entries()) {
        const size_t dot = key.find('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == key.size())
            continue;
        const std::string setId = key.substr(0, dot);
        if (!m_sets.count(setId))
            m_sets[setId] = isHidden(setId) ? Properties() : m_sets["default"];
        m_sets[setId].set(key.substr(dot + 1), value);
    }
    m_dirty = true;
}

void ConfigAdmin::setObserver(Observer observer)
{
    std::lock_guard lock(m_mutex);
    m_observer = std::move(observer);
}

void ConfigAdmin::notify(Event event, const std::string &setId) const
{
    Observer observer;
    {
        std::lock_guard lock(m_mutex);
        observer = m_observer;
    }
    if (observer)
        observer(event, setId);
}

std::vector<std::string> ConfigAdmin::setIds() const
{
    std::lock_guard lock(m_mutex);
    std::vector<std::string> ids;
    for (const auto &entry : m_sets)
        ids.push_back(entry.first);
    return ids;
}

bool ConfigAdmin::hasSet(const std::string &id) const
{
    std::lock_guard lock(m_mutex);
    return m_sets.count(id) != 0;
}

Properties ConfigAdmin::set(const std::string &id) const
{
    std::lock_guard lock(m_mutex);
    auto it = m_sets.find(id);
    return it == m_sets.end() ? Properties() : it->second;
}

std::string ConfigAdmin::activeSetId() const
{
    std::lock_guard lock(m_mutex);
    return m_active;
}

bool ConfigAdmin::isActive() const
{
    std::lock_guard lock(m_mutex);
    return m_activated;
}

bool ConfigAdmin::addSet(const std::string &id, const Properties &values)
{
    {
        std::lock_guard lock(m_mutex);
        if (id.empty() || m_sets.count(id))
            return false;
        m_sets[id] = values;
        m_activated = false;
    }
    notify(Event::SetAdded, id);
    return true;
}

bool ConfigAdmin::setValues(const std::string &id, const Properties &values)
{
    {
        std::lock_guard lock(m_mutex);
        auto it = m_sets.find(id);
        if (it == m_sets.end())
            return false;
        it->second.merge(values);
        m_dirty = true;
        m_activated = false;
    }
    notify(Event::SetValuesChanged, id);
    return true;
}

bool ConfigAdmin::removeSet(const std::string &id)
{
    {
        std::lock_guard lock(m_mutex);
        // OpenRTM refuses to remove the default and the active set.
        if (id == "default" || id == m_active || m_sets.erase(id) == 0)
            return false;
        m_activated = false;
    }
    notify(Event::SetRemoved, id);
    return true;
}

bool ConfigAdmin::activate(const std::string &id)
{
    {
        std::lock_guard lock(m_mutex);
        if (!m_sets.count(id) || isHidden(id))
            return false;
        m_active = id;
        m_dirty = true;
        m_activated = true;
    }
    notify(Event::SetActivated, id);
    return true;
}

bool ConfigAdmin::setParameter(const std::string &name, const std::string &value)
{
    std::lock_guard lock(m_mutex);
    m_sets[m_active].set(name, value);
    m_dirty = true;
    return true;
}

void ConfigAdmin::update()
{
    std::vector<std::pair<Setter, std::string>> calls;
    std::string activeId;
    {
        std::lock_guard lock(m_mutex);
        if (!m_dirty || !m_activated)
            return;
        activeId = m_active;
        m_dirty = false;
        const Properties &active = m_sets[m_active];
        const Properties &defaults = m_sets["default"];
        for (const auto &[name, setter] : m_parameters)
            calls.emplace_back(setter, active.value(name, defaults.value(name)));
    }
    // Setters run unlocked: they may read the configuration themselves.
    for (const auto &[setter, value] : calls)
        setter(value);
    notify(Event::Updated, activeId);
}

std::vector<std::string> ConfigAdmin::parameterNames() const
{
    std::lock_guard lock(m_mutex);
    std::vector<std::string> names;
    for (const auto &entry : m_parameters)
        names.push_back(entry.first);
    return names;
}

} // namespace Runtime
