// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace Runtime {

/**
 * A component's configuration sets as OpenRTM keeps them: named sets of parameter → string value,
 * one active set ("default" at first), parameters bound to the component's variables through
 * setters. Sets whose id starts with "__" (`__widget__`, `__constraints__`, …) are hidden metadata:
 * listed, editable, never activated. Changes to the active set reach the variables at the next
 * update() (the runtime calls it in the execution context's thread). Thread-safe.
 *
 * As in OpenRTM-aist, adding, writing or removing a set leaves the configuration inactive until a
 * set is activated: update() then applies nothing, and the SDO interface reports no active set
 * (tools write, then activate, as rtshell does).
 */
class ConfigAdmin
{
public:
    /// Parses the text into the component's variable; false when the text does not fit.
    using Setter = std::function<bool(const std::string &)>;
    /// What changed, for observers (the SDK's configuration listeners).
    enum class Event { SetValuesChanged, SetAdded, SetRemoved, SetActivated, Updated };
    using Observer = std::function<void(Event event, const std::string &setId)>;

    /// @p observer is called after each change, without the lock held.
    void setObserver(Observer observer);

    /// Declares @p name with @p defaultValue in the "default" set and binds @p setter to it.
    void bindParameter(const std::string &name, const std::string &defaultValue, Setter setter);
    /// Forgets parameter @p name's setter (the sets keep its values); false when it is not bound.
    bool unbindParameter(const std::string &name);
    /// Applies `conf.<set>.<param>` properties: new sets start as a copy of "default".
    void applyProperties(const Properties &properties);

    std::vector<std::string> setIds() const;
    bool hasSet(const std::string &id) const;
    /// Parameter → value of set @p id (empty when absent).
    Properties set(const std::string &id) const;
    std::string activeSetId() const;
    /// False from a change of the sets (add, write, remove) until the next activate().
    bool isActive() const;

    bool addSet(const std::string &id, const Properties &values);
    /// Replaces values of an existing set (adds missing parameters).
    bool setValues(const std::string &id, const Properties &values);
    bool removeSet(const std::string &id);
    bool activate(const std::string &id);
    /// Sets one parameter of the active set.
    bool setParameter(const std::string &name, const std::string &value);

    /// Pushes the active set's values through the setters if anything changed since the last update
    /// and the configuration is active.
    void update();
    /// Order of declaration, for listings.
    std::vector<std::string> parameterNames() const;

private:
    static bool isHidden(const std::string &id) { return id.compare(0, 2, "__") == 0; }

    mutable std::mutex m_mutex;
    std::map<std::string, Properties> m_sets{{"default", {}}};
    std::vector<std::pair<std::string, Setter>> m_parameters;
    std::string m_active = "default";
    bool m_dirty = true;
    bool m_activated = true;
    Observer m_observer;

    void notify(Event event, const std::string &setId) const;
};

} // namespace Runtime
