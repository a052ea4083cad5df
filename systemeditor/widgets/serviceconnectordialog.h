// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QTableWidget;

namespace SystemEditor {

/**
 * The service connector dialog: the connector's name and the table that maps each required
 * (consumer) interface to the provided one it will use, paired by instance name and polarity
 * (ConnectionRules::matchingInterfaces). It warns about interfaces left without a counterpart and
 * about pairs whose types differ; only an empty or too long name keeps OK disabled.
 */
class ServiceConnectorDialog : public QDialog
{
    Q_OBJECT

public:
    ServiceConnectorDialog(const QString &name, const QList<InterfaceInfo> &source,
                           const QList<InterfaceInfo> &target, QWidget *parent = nullptr);

    QString name() const;
    void setName(const QString &name);
    /// What the user should know before connecting (unpaired interfaces, differing types).
    QStringList warnings() const { return m_warnings; }
    QTableWidget *mappingTable() const { return m_mapping; }

    void accept() override;

private:
    void fillMapping(const QList<InterfaceInfo> &source, const QList<InterfaceInfo> &target);
    void refresh();

    QLineEdit *m_name;
    QTableWidget *m_mapping;
    QLabel *m_warningLabel;
    QDialogButtonBox *m_buttons;
    QStringList m_warnings;
};

} // namespace SystemEditor
