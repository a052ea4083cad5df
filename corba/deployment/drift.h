// SPDX-License-Identifier: MIT
#pragma once

#include "restoreplan.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace Profile {
struct RtsProfile;
}

namespace Deploy {

/// One difference between a saved system and the live one.
struct DriftItem
{
    enum class Kind {
        MissingComponent, ///< a saved component is not running (or is of another type)
        MissingPort, ///< a saved port does not exist on the live component
        MissingConnector, ///< a saved connector is not connected
        ExtraConnector, ///< the live components are connected in a way the file does not say
        ConfigurationValue, ///< a parameter's live value differs (or the set/parameter is missing)
        ActiveSet, ///< another configuration set is active
        State, ///< a component is in the error state or does not answer
        Unreachable ///< the live component could not be asked
    };

    Kind kind = Kind::MissingComponent;
    QString subject; ///< instance name, connector id, `Instance.set.param`
    QString saved; ///< the value in the file (when there is one)
    QString live; ///< the live value (when there is one)

    /// "missing component", "missing connector", "configuration", ...
    static QString kindName(Kind kind);
    /// `KIND subject: saved 'x', live 'y'`, one line as rtctl prints it (translated in the GUI).
    QString toString() const;

    Q_DECLARE_TR_FUNCTIONS(Deploy::DriftItem)
};

/**
 * What differs between `profile` and the live system it was mapped onto (`plan`, see
 * planRestore()): missing components and ports, missing and extra connectors, configuration
 * values and active sets, components in the error state. Makes no change; remote failures become
 * Unreachable items. Safe to call from a worker thread.
 *
 * Ports and connectors are first taken from the plan's reading (ComponentMapping::plannedPorts);
 * the components where they disagree with the file are read again. So make the plan right before
 * the comparison, as rtctl and the Drift view do.
 */
QList<DriftItem> diffSystem(const Profile::RtsProfile &profile, const RestorePlan &plan);

} // namespace Deploy
