// SPDX-License-Identifier: MIT
#include "serviceconnectordialog.h"

#include "connectionrules.h"
#include "connectorsettings.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

QString describe(const InterfaceInfo &interface)
{
    return QStringLiteral("%1 (%2)").arg(interface.name, interface.type);
}

bool isProvided(const InterfaceInfo &interface)
{
    return interface.polarity == Profile::RtcDirection::Provided;
}

QTableWidgetItem *cell(const QString &text)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}

} // namespace

ServiceConnectorDialog::ServiceConnectorDialog(const QString &name,
                                               const QList<InterfaceInfo> &source,
                                               const QList<InterfaceInfo> &target,
                                               QWidget *parent)
    : QDialog(parent)
    , m_name(new QLineEdit(name))
    , m_mapping(new QTableWidget(0, 2))
    , m_warningLabel(new QLabel)
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel))
{
    setWindowTitle(tr("Service Connector"));
    m_name->setObjectName(QStringLiteral("name"));
    m_mapping->setObjectName(QStringLiteral("interfaceMapping"));
    m_mapping->setHorizontalHeaderLabels({tr("Consumer (required)"), tr("Provider (provided)")});
    m_mapping->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_mapping->verticalHeader()->hide();
    m_warningLabel->setObjectName(QStringLiteral("warnings"));
    m_warningLabel->setWordWrap(true);
    m_warningLabel->setStyleSheet(QStringLiteral("color: #8a5a00;"));
    auto *form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("Interface mapping:")));
    layout->addWidget(m_mapping, 1);
    layout->addWidget(m_warningLabel);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ServiceConnectorDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ServiceConnectorDialog::reject);
    connect(m_name, &QLineEdit::textChanged, this, &ServiceConnectorDialog::refresh);
    fillMapping(source, target);
    refresh();
}

void ServiceConnectorDialog::fillMapping(const QList<InterfaceInfo> &source,
                                         const QList<InterfaceInfo> &target)
{
    const QList<QPair<int, int>> pairs = ConnectionRules::matchingInterfaces(source, target);
    QSet<int> pairedSource;
    QSet<int> pairedTarget;
    for (const auto &[a, b] : pairs) {
        pairedSource.insert(a);
        pairedTarget.insert(b);
        const InterfaceInfo &first = source.at(a);
        const InterfaceInfo &second = target.at(b);
        const InterfaceInfo &consumer = isProvided(first) ? second : first;
        const InterfaceInfo &provider = isProvided(first) ? first : second;
        const int row = m_mapping->rowCount();
        m_mapping->insertRow(row);
        m_mapping->setItem(row, 0, cell(describe(consumer)));
        m_mapping->setItem(row, 1, cell(describe(provider)));
        if (consumer.type != provider.type)
            m_warnings << tr("\"%1\" requires %2 but \"%3\" provides %4.")
                              .arg(consumer.name, consumer.type, provider.name, provider.type);
    }
    const auto unpaired = [this](const QList<InterfaceInfo> &list, const QSet<int> &paired) {
        for (int i = 0; i < list.size(); ++i) {
            if (!paired.contains(i))
                m_warnings << tr("Interface \"%1\" has no counterpart on the other port.")
                                  .arg(list.at(i).name);
        }
    };
    unpaired(source, pairedSource);
    unpaired(target, pairedTarget);
}

QString ServiceConnectorDialog::name() const
{
    return m_name->text().trimmed();
}

void ServiceConnectorDialog::setName(const QString &name)
{
    m_name->setText(name);
}

void ServiceConnectorDialog::refresh()
{
    QStringList lines = m_warnings;
    const bool nameOk = !name().isEmpty() && name().size() <= ConnectorSettings::MaxNameLength;
    if (!nameOk)
        lines.prepend(tr("The name must have 1 to %1 characters.")
                          .arg(ConnectorSettings::MaxNameLength));
    m_warningLabel->setText(lines.join(QLatin1Char('\n')));
    m_warningLabel->setVisible(!lines.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(nameOk);
}

void ServiceConnectorDialog::accept()
{
    if (!m_buttons->button(QDialogButtonBox::Ok)->isEnabled())
        return;
    QDialog::accept();
}

} // namespace SystemEditor
