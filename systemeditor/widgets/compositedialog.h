// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QDialog>

class QComboBox;
class QListWidget;

namespace SystemEditor {

/**
 * Asks how to group components into a composite: its kind (PeriodicECShared,
 * PeriodicStateShared, Grouping) and which of the members' ports it exports.
 */
class CompositeDialog : public QDialog
{
    Q_OBJECT

public:
    /// What the user chose.
    struct Choice
    {
        QString compositeType;
        QList<ConnectorEnd> exportedPorts;
    };

    /// Offers the ports of `members` in `model` for export; none is ticked at first.
    CompositeDialog(const SystemModel &model, const QStringList &members,
                    QWidget *parent = nullptr);

    Choice choice() const;
    QComboBox *kindBox() const { return m_kind; }
    QListWidget *portList() const { return m_ports; }

private:
    QComboBox *m_kind;
    QListWidget *m_ports;
};

} // namespace SystemEditor
