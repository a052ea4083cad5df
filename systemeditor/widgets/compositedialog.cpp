// SPDX-License-Identifier: MIT
#include "compositedialog.h"

#include "compositecommands.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

constexpr int InstanceRole = Qt::UserRole;
constexpr int PortRole = Qt::UserRole + 1;

QString portKindText(PortKind kind)
{
    switch (kind) {
    case PortKind::DataIn:
        return CompositeDialog::tr("InPort");
    case PortKind::DataOut:
        return CompositeDialog::tr("OutPort");
    case PortKind::Service:
        return CompositeDialog::tr("Service port");
    case PortKind::Unknown:
        break;
    }
    return CompositeDialog::tr("Port");
}

} // namespace

CompositeDialog::CompositeDialog(const SystemModel &model, const QStringList &members,
                                 QWidget *parent)
    : QDialog(parent)
    , m_kind(new QComboBox)
    , m_ports(new QListWidget)
{
    setWindowTitle(tr("Group as Composite"));
    m_kind->setObjectName(QStringLiteral("compositeKind"));
    m_kind->addItems(compositeKinds());
    m_ports->setObjectName(QStringLiteral("exportedPorts"));
    for (const QString &member : members) {
        for (const PortInfo &port : model.ports(member)) {
            auto *item = new QListWidgetItem(
                QStringLiteral("%1 (%2)").arg(port.name, portKindText(port.kind)), m_ports);
            item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
            item->setCheckState(Qt::Unchecked);
            item->setData(InstanceRole, member);
            item->setData(PortRole, port.name);
        }
    }
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *form = new QFormLayout;
    form->addRow(tr("&Kind:"), m_kind);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Members: %1").arg(members.join(QStringLiteral(", ")))));
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("Exported ports:")));
    layout->addWidget(m_ports, 1);
    layout->addWidget(buttons);
}

CompositeDialog::Choice CompositeDialog::choice() const
{
    Choice choice;
    choice.compositeType = m_kind->currentText();
    for (int row = 0; row < m_ports->count(); ++row) {
        const QListWidgetItem *item = m_ports->item(row);
        if (item->checkState() == Qt::Checked)
            choice.exportedPorts.append(
                {item->data(InstanceRole).toString(), item->data(PortRole).toString()});
    }
    return choice;
}

} // namespace SystemEditor
