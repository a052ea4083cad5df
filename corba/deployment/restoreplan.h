// SPDX-License-Identifier: MIT
#pragma once

#include "componentmapper.h"
#include "corbatypes.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

namespace Profile {
struct RtsDataPortConnector;
struct RtsPortConnector;
} // namespace Profile

namespace Deploy {

/// One saved connector and how it will be connected.
struct ConnectorPlan
{
    QString connectorId;
    QString name;
    bool dataPort = true;
    QString sourceInstance;
    QString sourcePort; ///< as saved, usually `Instance0.port`
    QString targetInstance;
    QString targetPort;
    Corba::Properties properties; ///< what connect() is given (IOR keys removed)
    bool required = true; ///< both ends are required components
    bool connect = true; ///< a GUI mapping dialog may untick it
};

/**
 * What a restore will do: the mapping of every component and the connectors, in the order the
 * restore runs them (data connectors of required components first, then the others, then
 * service connectors). A dry run prints it.
 */
struct RestorePlan
{
    QList<ComponentMapping> components;
    QList<ConnectorPlan> connectors;
    QStringList problems; ///< from looking up the live system

    const ComponentMapping *component(const QString &instanceName) const;
    /// The required components that are neither found nor to be created.
    QList<ComponentMapping> missingRequired() const;
    /// A readable plan, one line per component and connector (translated in the GUI).
    QString toText() const;

private:
    static QString componentLine(const ComponentMapping &c);
    static QString optionalLine(const QString &line, bool required);

    Q_DECLARE_TR_FUNCTIONS(Deploy::RestorePlan)
};

/// True for the connector properties that carry object references of one particular live
/// connection (`dataport.corba_cdr.inport_ior`, `…_ref`, `IOR`), which a restore must not reuse.
bool isIorKey(const QString &key);
/// The properties a data connector is connected with: the four `dataport.*` attributes
/// overlaid by its `rtsExt:Properties`, minus IOR keys.
Corba::Properties dataConnectorProperties(const Profile::RtsDataPortConnector &connector);
/// The `rtsExt:Properties` of a service connector, minus IOR keys.
Corba::Properties serviceConnectorProperties(const Profile::RtsPortConnector &connector);
/// The connectors of `profile` in restore order, required flags from `components`.
QList<ConnectorPlan> connectorPlans(const Profile::RtsProfile &profile,
                                    const QList<ComponentMapping> &components);
/// Maps the live system and plans the restore of `profile`; makes no change anywhere.
RestorePlan planRestore(const Profile::RtsProfile &profile, const TargetOptions &options);

} // namespace Deploy
