// SPDX-License-Identifier: MIT
#pragma once

#include "connectorsettings.h"
#include "serviceconnectorsettings.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace SystemEditor {

/**
 * The service connector dialog: the connector's name, the connect direction (which of the two
 * ports calls connect(); saved as the connector's source end, see ServiceConnectorSettings) and
 * the interface mapping, one row per
 * required (consumer) interface of either port. Each row chooses its provider among the provided
 * interfaces of the other port (the only polarity that fits), by instance name, or leaves it
 * "automatic": paired by instance name when connecting, nothing written. A chosen provider is
 * saved as the reference's mapping property (ServiceConnectorSettings). The dialog warns about
 * interfaces left without a counterpart and about pairs whose types or instance names differ;
 * only an empty or too long name keeps OK disabled. The direction starts at the settings'
 * connecting port (else the source side) and can be changed when both ports are known by name
 * and setDirectionChangeable() allows it.
 */
class ServiceConnectorDialog : public QDialog
{
    Q_OBJECT

public:
    ServiceConnectorDialog(const ServiceConnectorSettings &settings, const ServicePortSide &source,
                           const ServicePortSide &target, QWidget *parent = nullptr);
    /// A dialog for a new connector between ports known only by their interfaces.
    ServiceConnectorDialog(const QString &name, const QList<InterfaceInfo> &source,
                           const QList<InterfaceInfo> &target, QWidget *parent = nullptr);

    QString name() const;
    void setName(const QString &name);
    /// Whether the user may choose the other port (false for a connection that exists live).
    void setDirectionChangeable(bool changeable);
    /// The connect direction field; item 0 is "source connects", item 1 "target connects".
    QComboBox *directionChoice() const { return m_direction; }
    /// The fields as they are now.
    ServiceConnectorSettings settings() const;
    /// What the user should know before connecting (unpaired interfaces, differing types).
    QStringList warnings() const { return m_warnings; }
    QTableWidget *mappingTable() const { return m_mapping; }
    /// The provider choice of mapping row `row` (item 0 is "automatic").
    QComboBox *providerChoice(int row) const;

    void accept() override;

private:
    struct Consumer
    {
        int side; ///< 0 source, 1 target
        InterfaceInfo interface;
    };

    QComboBox *buildDirection(const ConnectorEnd &connectingPort);
    void fillMapping(const ServiceConnectorSettings &settings);
    /// The provider choices of `consumer`, set to its entry in m_unmatched (which it takes).
    QComboBox *providerBox(const Consumer &consumer);
    const InterfaceInfo *providerOf(int row) const;
    void refresh();

    ServicePortSide m_sides[2];
    QList<Consumer> m_consumers;
    QList<QPair<QString, QString>> m_unmatched; ///< mapping entries no row names (kept)
    ConnectorEnd m_ends[2]; ///< the ports as the settings name them (kept for comparing)
    bool m_directionChangeable = true;
    QLineEdit *m_name;
    QComboBox *m_direction;
    QTableWidget *m_mapping;
    QLabel *m_warningLabel;
    QDialogButtonBox *m_buttons;
    QStringList m_warnings;
};

} // namespace SystemEditor
