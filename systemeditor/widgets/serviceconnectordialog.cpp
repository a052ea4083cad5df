// SPDX-License-Identifier: MIT
#include "serviceconnectordialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace SystemEditor {

namespace {

constexpr int DescriptorRole = Qt::UserRole;
constexpr int IndexRole = Qt::UserRole + 1;
constexpr int Automatic = -1;
constexpr int Unknown = -2; ///< a saved provider the other port does not list

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

void sortMapping(QList<QPair<QString, QString>> &mapping)
{
    std::sort(mapping.begin(), mapping.end());
}

} // namespace

ServiceConnectorDialog::ServiceConnectorDialog(const QString &name,
                                               const QList<InterfaceInfo> &source,
                                               const QList<InterfaceInfo> &target,
                                               QWidget *parent)
    : ServiceConnectorDialog(ServiceConnectorSettings {name, {}, {}}, {{}, {}, source},
                             {{}, {}, target}, parent)
{ }

ServiceConnectorDialog::ServiceConnectorDialog(const ServiceConnectorSettings &settings,
                                               const ServicePortSide &source,
                                               const ServicePortSide &target, QWidget *parent)
    : QDialog(parent)
    , m_sides {source, target}
    , m_name(new QLineEdit(settings.name))
    , m_direction(buildDirection(settings.connectingPort))
    , m_mapping(new QTableWidget(0, 2))
    , m_warningLabel(new QLabel)
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel))
{
    setWindowTitle(tr("Service Connector"));
    m_name->setObjectName(QStringLiteral("name"));
    m_name->setMaxLength(ConnectorSettings::MaxNameLength + 1);
    m_mapping->setObjectName(QStringLiteral("interfaceMapping"));
    m_mapping->setHorizontalHeaderLabels({tr("Consumer (required)"), tr("Provider (provided)")});
    m_mapping->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_mapping->verticalHeader()->hide();
    m_warningLabel->setObjectName(QStringLiteral("warnings"));
    m_warningLabel->setWordWrap(true);
    m_warningLabel->setStyleSheet(QStringLiteral("color: #8a5a00;"));
    auto *form = new QFormLayout;
    form->addRow(tr("&Name:"), m_name);
    form->addRow(tr("Connect &direction:"), m_direction);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("Interface mapping (automatic pairs by instance name):")));
    layout->addWidget(m_mapping, 1);
    layout->addWidget(m_warningLabel);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &ServiceConnectorDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &ServiceConnectorDialog::reject);
    connect(m_name, &QLineEdit::textChanged, this, &ServiceConnectorDialog::refresh);
    fillMapping(settings);
    resize(std::max(sizeHint().width(), 560), sizeHint().height());
    refresh();
}

QComboBox *ServiceConnectorDialog::buildDirection(const ConnectorEnd &connectingPort)
{
    auto *box = new QComboBox;
    box->setObjectName(QStringLiteral("connectDirection"));
    box->setToolTip(
        tr("Which port calls connect(); the system file records it as the connector's source."));
    QString labels[2];
    int chosen = 0;
    for (int side = 0; side < 2; ++side) {
        const ServicePortSide &port = m_sides[side];
        labels[side] = port.instanceName.isEmpty()
            ? (side == 0 ? tr("first port") : tr("second port"))
            : port.instanceName + QLatin1Char('.') + port.portName;
        m_ends[side] = {port.instanceName, port.portName};
        // The settings' own spelling of the connecting port, so that an unchanged dialog gives
        // back equal settings.
        Profile::RtsTargetPort end;
        end.instanceName = port.instanceName;
        end.portName = port.portName;
        if (ServiceConnectorSettings::isSamePort(end, connectingPort)) {
            m_ends[side] = connectingPort;
            chosen = side;
        }
    }
    for (int side = 0; side < 2; ++side)
        box->addItem(tr("%1 \u2192 %2 (%1 connects)").arg(labels[side], labels[1 - side]), side);
    box->setCurrentIndex(chosen);
    return box;
}

void ServiceConnectorDialog::fillMapping(const ServiceConnectorSettings &settings)
{
    for (int side = 0; side < 2; ++side) {
        for (const InterfaceInfo &interface : m_sides[side].interfaces) {
            if (!isProvided(interface))
                m_consumers.append({side, interface});
        }
    }
    m_unmatched = settings.mapping;
    for (const Consumer &consumer : m_consumers) {
        const int row = m_mapping->rowCount();
        m_mapping->insertRow(row);
        m_mapping->setItem(row, 0, cell(describe(consumer.interface)));
        QComboBox *box = providerBox(consumer);
        m_mapping->setCellWidget(row, 1, box);
        connect(box, &QComboBox::currentIndexChanged, this, &ServiceConnectorDialog::refresh);
    }
}

QComboBox *ServiceConnectorDialog::providerBox(const Consumer &consumer)
{
    auto *box = new QComboBox;
    box->setObjectName(QStringLiteral("provider_") + consumer.interface.name);
    box->addItem(tr("automatic"), QString());
    box->setItemData(0, Automatic, IndexRole);
    const ServicePortSide &other = m_sides[1 - consumer.side];
    for (int i = 0; i < other.interfaces.size(); ++i) {
        const InterfaceInfo &candidate = other.interfaces.at(i);
        if (!isProvided(candidate))
            continue;
        const QString descriptor = InterfaceDescriptor::of(other, candidate).toString();
        box->addItem(QStringLiteral("%1 (%2)").arg(candidate.instanceName, candidate.type),
                     descriptor);
        box->setItemData(box->count() - 1, i, IndexRole);
    }
    // The saved choice of this consumer, if any; it leaves the unmatched entries.
    const ServicePortSide &own = m_sides[consumer.side];
    for (int e = 0; e < m_unmatched.size(); ++e) {
        const auto descriptor = InterfaceDescriptor::parse(m_unmatched.at(e).first);
        if (!descriptor || !descriptor->names(own, consumer.interface))
            continue;
        const QString provider = m_unmatched.takeAt(e).second;
        int index = box->findData(provider, DescriptorRole);
        if (index < 0) {
            box->addItem(tr("%1 (not on the other port)").arg(provider), provider);
            index = box->count() - 1;
            box->setItemData(index, Unknown, IndexRole);
        }
        box->setCurrentIndex(index);
        break;
    }
    return box;
}

QComboBox *ServiceConnectorDialog::providerChoice(int row) const
{
    return qobject_cast<QComboBox *>(m_mapping->cellWidget(row, 1));
}

const InterfaceInfo *ServiceConnectorDialog::providerOf(int row) const
{
    const Consumer &consumer = m_consumers.at(row);
    const QList<InterfaceInfo> &others = m_sides[1 - consumer.side].interfaces;
    const int index = providerChoice(row)->currentData(IndexRole).toInt();
    if (index >= 0)
        return &others.at(index);
    if (index == Unknown)
        return nullptr;
    const auto found = std::find_if(others.begin(), others.end(), [&](const InterfaceInfo &i) {
        return isProvided(i) && i.instanceName == consumer.interface.instanceName;
    });
    return found == others.end() ? nullptr : &*found;
}

QString ServiceConnectorDialog::name() const
{
    return m_name->text().trimmed();
}

void ServiceConnectorDialog::setName(const QString &name)
{
    m_name->setText(name);
}

void ServiceConnectorDialog::setDirectionChangeable(bool changeable)
{
    m_directionChangeable = changeable;
    refresh();
}

ServiceConnectorSettings ServiceConnectorDialog::settings() const
{
    ServiceConnectorSettings s;
    s.name = name();
    s.connectingPort = m_ends[m_direction->currentIndex() == 1 ? 1 : 0];
    s.mapping = m_unmatched;
    for (int row = 0; row < m_consumers.size(); ++row) {
        const QString provider = providerChoice(row)->currentData(DescriptorRole).toString();
        if (provider.isEmpty())
            continue;
        const Consumer &consumer = m_consumers.at(row);
        s.mapping.append(
            {InterfaceDescriptor::of(m_sides[consumer.side], consumer.interface).toString(),
             provider});
    }
    sortMapping(s.mapping);
    return s;
}

void ServiceConnectorDialog::refresh()
{
    m_warnings.clear();
    QList<const InterfaceInfo *> used;
    for (int row = 0; row < m_consumers.size(); ++row) {
        const InterfaceInfo &consumer = m_consumers.at(row).interface;
        const InterfaceInfo *provider = providerOf(row);
        if (!provider) {
            m_warnings << tr("Interface \"%1\" has no counterpart on the other port.")
                              .arg(consumer.name);
            continue;
        }
        used << provider;
        if (consumer.type != provider->type)
            m_warnings << tr("\"%1\" requires %2 but \"%3\" provides %4.")
                              .arg(consumer.name, consumer.type, provider->name, provider->type);
        else if (consumer.instanceName != provider->instanceName)
            m_warnings << tr("\"%1\" uses \"%2\" of another instance name (%3, %4).")
                              .arg(consumer.name, provider->name, consumer.instanceName,
                                   provider->instanceName);
    }
    for (const ServicePortSide &side : m_sides) {
        for (const InterfaceInfo &interface : side.interfaces) {
            if (isProvided(interface) && !used.contains(&interface))
                m_warnings << tr("Interface \"%1\" has no counterpart on the other port.")
                                  .arg(interface.name);
        }
    }
    QStringList lines = m_warnings;
    const QStringList problems = settings().validate();
    lines = problems + lines;
    m_warningLabel->setText(lines.join(QLatin1Char('\n')));
    m_warningLabel->setVisible(!lines.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problems.isEmpty());
    // Without names for both ports there is nothing to record the direction with.
    m_direction->setEnabled(m_directionChangeable && !m_sides[0].instanceName.isEmpty()
                            && !m_sides[1].instanceName.isEmpty());
}

void ServiceConnectorDialog::accept()
{
    if (!m_buttons->button(QDialogButtonBox::Ok)->isEnabled())
        return;
    QDialog::accept();
}

} // namespace SystemEditor
