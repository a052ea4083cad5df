// SPDX-License-Identifier: MIT
#pragma once

#include "connectorsettings.h"
#include "serviceconnectorsettings.h"
#include "systemmodel.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

namespace SystemEditor {

/// A fresh connector id: a UUID without braces, as the reference generates them.
QString newConnectorId();

/**
 * A data-port connector from `source` (OutPort) to `target` (InPort) of the model, with a new
 * id, the port ends (portName and instanceName; componentId from the components) and
 * `settings` applied (an InToOut connect direction makes the InPort the source end).
 */
Profile::RtsDataPortConnector makeDataConnector(const SystemModel &model,
                                                const ConnectorEnd &source,
                                                const ConnectorEnd &target,
                                                const ConnectorSettings &settings);
/// A service-port connector with a new id, named `<source port>_<target port>` when `name` is
/// empty.
Profile::RtsServicePortConnector makeServiceConnector(const SystemModel &model,
                                                      const ConnectorEnd &source,
                                                      const ConnectorEnd &target,
                                                      const QString &name = {});
/// A service-port connector with a new id and `settings` (name, interface mapping) applied.
Profile::RtsServicePortConnector makeServiceConnector(const SystemModel &model,
                                                      const ConnectorEnd &source,
                                                      const ConnectorEnd &target,
                                                      const ServiceConnectorSettings &settings);

/// Adds a data or service connector (the connector is made by the functions above).
class ConnectCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(ConnectCommand)

public:
    ConnectCommand(SystemModel *model, const Profile::RtsDataPortConnector &connector,
                   QUndoCommand *parent = nullptr);
    ConnectCommand(SystemModel *model, const Profile::RtsServicePortConnector &connector,
                   QUndoCommand *parent = nullptr);

    QString connectorId() const { return m_id; }
    void redo() override;
    void undo() override;

private:
    QPointer<SystemModel> m_model;
    QString m_id;
    std::optional<Profile::RtsDataPortConnector> m_data;
    std::optional<Profile::RtsServicePortConnector> m_service;
    bool m_applied = false; ///< an id that was taken must not remove the other connector on undo
    bool m_topLevel = true; ///< only a top-level command may be dropped by the stack
};

/// Removes a connector; undo puts it back at the same place in its list.
class DisconnectCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(DisconnectCommand)

public:
    DisconnectCommand(SystemModel *model, const QString &connectorId,
                      QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;

private:
    QPointer<SystemModel> m_model;
    QString m_id;
    int m_index = -1;
    std::optional<Profile::RtsDataPortConnector> m_data;
    std::optional<Profile::RtsServicePortConnector> m_service;
};

/// Replaces a connector's record (name, types, properties) — the connector dialogs' OK.
class EditConnectorCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(EditConnectorCommand)

public:
    EditConnectorCommand(SystemModel *model, const Profile::RtsDataPortConnector &after,
                         QUndoCommand *parent = nullptr);
    EditConnectorCommand(SystemModel *model, const Profile::RtsServicePortConnector &after,
                         QUndoCommand *parent = nullptr);
    /// Applies `settings` to the data connector `connectorId`.
    static EditConnectorCommand *fromSettings(SystemModel *model, const QString &connectorId,
                                              const ConnectorSettings &settings);
    /// Applies `settings` to the service connector `connectorId`; null when there is none.
    static EditConnectorCommand *fromSettings(SystemModel *model, const QString &connectorId,
                                              const ServiceConnectorSettings &settings);

    void redo() override;
    void undo() override;

private:
    QPointer<SystemModel> m_model;
    std::optional<Profile::RtsDataPortConnector> m_dataBefore, m_dataAfter;
    std::optional<Profile::RtsServicePortConnector> m_serviceBefore, m_serviceAfter;
};

/// Sets a connector's bend points; successive drags of the same connector merge.
class SetBendPointsCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetBendPointsCommand)

public:
    SetBendPointsCommand(SystemModel *model, const QString &connectorId,
                         const QList<QPointF> &points, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<SystemModel> m_model;
    QString m_id;
    QList<QPointF> m_before;
    QList<QPointF> m_after;
};

} // namespace SystemEditor
