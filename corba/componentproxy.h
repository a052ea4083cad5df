// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QString>

#include <vector>

namespace Corba {

/**
 * A live RT-Component, addressed by its object reference. Holds only strings, so it can be copied
 * into worker threads; every method is one or more remote calls under the configured timeout and
 * throws Corba::Error (naming `path`) on failure or when the component refuses.
 *
 * Execution contexts are indexed as rtshell does: owned contexts first, then participating ones.
 */
class ComponentProxy
{
public:
    ComponentProxy(QString ior, QString path);

    QString ior() const { return m_ior; }
    QString path() const { return m_path; }

    /// The component profile with every port's profile.
    ComponentInfo profile() const;
    /// The current profiles of all ports (from get_ports()), including their connectors.
    std::vector<PortInfo> ports() const;
    /// The port named `name` (short `out` or full `Comp0.out`); NotFound when there is none.
    PortInfo port(const QString &name) const;

    /// The composites it is a member of and, for a composite, its members (rtshell's rtcat shows them).
    OrganizationInfo organizations() const;

    /// How much executionContexts() reads: Members adds each context's owner and participants
    /// (one more call per context and one per member, so the pollers stay with Basic); Saved
    /// reads only the owned contexts' handle, kind and rate (what a saved system keeps).
    enum class ContextDetail { Saved, Basic, Members };
    std::vector<ExecutionContextInfo> executionContexts(ContextDetail detail
                                                        = ContextDetail::Basic) const;
    /**
     * Makes this component take part in the execution context `contextIor` (usually owned by
     * another component): ExecutionContext::add_component, then the component's attach_context
     * when the context did not attach it itself (OpenRTM-aist's contexts do). Refused when the
     * component owns the context or already takes part in it.
     */
    void attachContext(const QString &contextIor) const;
    /**
     * Takes this component out of the execution context `contextIor`: remove_component, then
     * detach_context when the component still lists it. Refused for an owned context and by the
     * context while the component is active in it; NotFound when the component is not taking part.
     */
    void detachContext(const QString &contextIor) const;
    /// The component's state in the context at `ecIndex`.
    LifeCycleState state(int ecIndex = 0) const;
    void activate(int ecIndex = 0) const;
    void deactivate(int ecIndex = 0) const;
    void reset(int ecIndex = 0) const;
    /// Asks the component to finalise and leave its contexts (LightweightRTObject::exit).
    void exit() const;
    void startContext(int ecIndex = 0) const;
    void stopContext(int ecIndex = 0) const;
    void setRate(double rate, int ecIndex = 0) const;

    /*
     * Writes to the configuration sets (add, values, remove, parameter) activate again the set
     * that was active before: OpenRTM-aist leaves the whole configuration inactive after any write
     * until a set is activated (rtshell writes, then activates, too).
     */
    std::vector<ConfigurationSet> configurationSets() const;
    /// The active set; empty when the component has none active (written, not activated since).
    QString activeConfigurationSet() const;
    /// configurationSets() and, unless @p activeSet is null, activeConfigurationSet() through one
    /// configuration reference.
    std::vector<ConfigurationSet> configurationSets(QString *activeSet) const;
    ConfigurationSet configurationSet(const QString &id) const;
    void addConfigurationSet(const ConfigurationSet &set) const;
    /// Writes the values of `set` into the existing set `set.id` in one call (parameters not yet in
    /// the set are added).
    void setConfigurationSetValues(const ConfigurationSet &set) const;
    void removeConfigurationSet(const QString &id) const;
    void activateConfigurationSet(const QString &id) const;
    /// The value of `name` in set `setId`; NotFound when the set or the parameter is missing.
    QString parameter(const QString &setId, const QString &name) const;
    /// Writes `name` = `value` into set `setId`; when that set is the active one the component sees
    /// the new value at its next update (rtconf's behaviour).
    void setParameter(const QString &setId, const QString &name, const QString &value) const;

private:
    QString m_ior;
    QString m_path;
};

} // namespace Corba
