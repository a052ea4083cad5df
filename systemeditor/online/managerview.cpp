// SPDX-License-Identifier: MIT
#include "managerview.h"

#include "corbaerror.h"
#include "iorendpoint.h"
#include "managerproxy.h"
#include "onlinesession.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QTreeWidget>
#include <QUrl>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

constexpr int KindRole = Qt::UserRole + 1; // "component", "loaded", "loadable", "slave", "package"
constexpr int KeyRole = Qt::UserRole + 2; // instance name, module path or package name
constexpr int VersionRole = Qt::UserRole + 3; // a package's version

/// The type as create_component names it: the implementation id (the type name where a profile
/// has none).
QString typeOf(const Corba::Properties &factory)
{
    return Corba::propertyValue(factory, QStringLiteral("implementation_id"),
                                Corba::propertyValue(factory, QStringLiteral("type_name")));
}

QString modulePath(const Corba::Properties &module)
{
    return Corba::propertyValue(module, QStringLiteral("module_file_path"),
                                Corba::propertyValue(module, QStringLiteral("file_path")));
}

ManagerSnapshot readManager(const QString &ior, const QString &path)
{
    const Corba::ManagerProxy manager(ior, path);
    ManagerSnapshot s;
    s.name = Corba::propertyValue(manager.profile(), QStringLiteral("instance_name"));
    s.master = manager.isMaster();
    for (const QString &slaveIor : manager.slaveManagers()) {
        const Corba::ManagerProxy slave(slaveIor, path + QStringLiteral(" (slave)"));
        s.slaves.append(
            {Corba::propertyValue(slave.profile(), QStringLiteral("instance_name")), slaveIor});
    }
    s.loadable = manager.loadableModules();
    s.loaded = manager.loadedModules();
    s.factories = manager.factoryProfiles();
    s.components = manager.componentProfiles();
    try {
        s.packages = Corba::PackageInstallerProxy(ior, path).installed();
    } catch (const Corba::Error &e) {
        // No install service: an OpenRTM-aist manager, or one with manager.packages.enable: NO.
        if (e.kind() != Corba::Error::Kind::WrongType)
            throw;
    }
    return s;
}

QPushButton *button(const QString &text, const QString &name, QWidget *parent)
{
    auto *b = new QPushButton(text, parent);
    b->setObjectName(name);
    return b;
}

} // namespace

ManagerView::ManagerView(OnlineSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
{
    qRegisterMetaType<ManagerSnapshot>();
    buildUi();
}

void ManagerView::buildUi()
{
    m_title = new QLabel(tr("No manager selected"), this);
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("managerTree"));
    m_tree->setHeaderLabels({tr("Name"), tr("Details")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    auto *remove = button(tr("Delete Component"), QStringLiteral("deleteComponentButton"), this);
    auto *load = button(tr("Load"), QStringLiteral("loadModuleButton"), this);
    auto *unload = button(tr("Unload"), QStringLiteral("unloadModuleButton"), this);
    auto *shutdownButton = button(tr("Shutdown"), QStringLiteral("shutdownButton"), this);
    auto *reloadButton = button(tr("Refresh"), QStringLiteral("refreshButton"), this);
    m_install = button(tr("Install Package…"), QStringLiteral("installPackageButton"), this);
    m_install->setToolTip(tr("Install a component package by the URL of its .deb in a repository "
                             "(rtctl node install)"));
    m_uninstall = button(tr("Uninstall"), QStringLiteral("uninstallPackageButton"), this);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("statusLabel"));
    m_status->setWordWrap(true);

    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(m_tree, 1);
    auto *row = new QHBoxLayout;
    for (QPushButton *b : {remove, load, unload, shutdownButton, reloadButton})
        row->addWidget(b);
    leftLayout->addLayout(row);
    auto *packageRow = new QHBoxLayout;
    packageRow->addWidget(m_install);
    packageRow->addWidget(m_uninstall);
    packageRow->addStretch(1);
    leftLayout->addLayout(packageRow);

    auto *splitter = new QSplitter(this);
    splitter->addWidget(left);
    splitter->addWidget(buildCreateForm());
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_title);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_status);

    auto selected = [this](const QString &kind) -> QString {
        QTreeWidgetItem *item = m_tree->currentItem();
        return item && item->data(0, KindRole).toString() == kind
            ? item->data(0, KeyRole).toString()
            : QString();
    };
    connect(remove, &QPushButton::clicked, this,
            [this, selected] { deleteComponent(selected(QStringLiteral("component"))); });
    connect(load, &QPushButton::clicked, this,
            [this, selected] { loadModule(selected(QStringLiteral("loadable")), QString()); });
    connect(unload, &QPushButton::clicked, this,
            [this, selected] { unloadModule(selected(QStringLiteral("loaded"))); });
    connect(shutdownButton, &QPushButton::clicked, this, &ManagerView::shutdown);
    connect(reloadButton, &QPushButton::clicked, this, &ManagerView::reload);
    connect(m_install, &QPushButton::clicked, this, [this] {
        const QString url = QInputDialog::getText(this, tr("Install Component Package"),
                                                  tr("URL of the package in a repository:"))
                                .trimmed();
        installPackage(url);
    });
    connect(m_uninstall, &QPushButton::clicked, this, [this] {
        QTreeWidgetItem *item = m_tree->currentItem();
        if (item && item->data(0, KindRole).toString() == QLatin1String("package"))
            uninstallPackage(item->data(0, KeyRole).toString(), item->data(0, VersionRole).toString());
    });
}

QWidget *ManagerView::buildCreateForm()
{
    auto *box = new QGroupBox(tr("Create Component"), this);
    m_type = new QComboBox(box);
    m_type->setObjectName(QStringLiteral("typeCombo"));
    // Editable: a full RTC id (`RTC:vendor:category:Type:version`) may be typed as well.
    m_type->setEditable(true);
    m_target = new QComboBox(box);
    m_target->setObjectName(QStringLiteral("targetCombo"));
    m_parameters = new QTableWidget(1, 2, box);
    m_parameters->setObjectName(QStringLiteral("parameterTable"));
    m_parameters->setHorizontalHeaderLabels({tr("Parameter"), tr("Value")});
    m_parameters->horizontalHeader()->setStretchLastSection(true);
    m_parameters->verticalHeader()->hide();
    m_parameters->setItem(0, 0, new QTableWidgetItem(QStringLiteral("instance_name")));
    m_parameters->setItem(0, 1, new QTableWidgetItem);
    auto *addRow = button(tr("Add Parameter"), QStringLiteral("addParameterButton"), box);
    auto *createButton = button(tr("Create"), QStringLiteral("createButton"), box);
    auto *form = new QFormLayout(box);
    form->addRow(tr("Type:"), m_type);
    form->addRow(tr("Target manager:"), m_target);
    form->addRow(m_parameters);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(addRow);
    buttons->addStretch(1);
    buttons->addWidget(createButton);
    form->addRow(buttons);
    connect(addRow, &QPushButton::clicked, this, [this] {
        const int row = m_parameters->rowCount();
        m_parameters->insertRow(row);
        m_parameters->setItem(row, 0, new QTableWidgetItem);
        m_parameters->setItem(row, 1, new QTableWidgetItem);
    });
    connect(createButton, &QPushButton::clicked, this, &ManagerView::create);
    return box;
}

void ManagerView::setManager(const QString &path, const QString &ior)
{
    m_path = path;
    m_ior = ior;
    m_title->setText(path);
    reload();
}

void ManagerView::reload()
{
    if (m_ior.isEmpty())
        return;
    const QString ior = m_ior;
    const QString path = m_path;
    const QString host = Corba::iorEndpoint(ior).isEmpty() ? path : Corba::iorEndpoint(ior);
    m_session->submit(
        host, [ior, path] { return QVariant::fromValue(readManager(ior, path)); }, this,
        [this, path](const OnlineResult &result) {
            if (path != m_path)
                return;
            if (!result.ok) {
                m_status->setText(result.error);
                return;
            }
            showSnapshot(result.value.value<ManagerSnapshot>());
            emit loaded();
        });
}

QTreeWidgetItem *ManagerView::section(const QString &title, const QString &name)
{
    auto *item = new QTreeWidgetItem(m_tree, {title});
    item->setData(0, KindRole, name);
    QFont font = item->font(0);
    font.setBold(true);
    item->setFont(0, font);
    return item;
}

void ManagerView::showSnapshot(const ManagerSnapshot &snapshot)
{
    m_snapshot = snapshot;
    m_tree->clear();
    auto add = [](QTreeWidgetItem *parent, const QString &name, const QString &detail,
                  const QString &kind, const QString &key) {
        auto *item = new QTreeWidgetItem(parent, {name, detail});
        item->setData(0, KindRole, kind);
        item->setData(0, KeyRole, key);
    };
    QTreeWidgetItem *slaves = section(tr("Slave managers"), QStringLiteral("slaves"));
    for (const auto &[name, ior] : snapshot.slaves)
        add(slaves, name, Corba::iorEndpoint(ior), QStringLiteral("slave"), ior);
    QTreeWidgetItem *components = section(tr("Components"), QStringLiteral("components"));
    for (const Corba::ComponentInfo &c : snapshot.components)
        add(components, c.instanceName, c.typeName, QStringLiteral("component"), c.instanceName);
    QTreeWidgetItem *factories = section(tr("Factories"), QStringLiteral("factories"));
    for (const Corba::Properties &f : snapshot.factories)
        add(factories, typeOf(f), Corba::propertyValue(f, QStringLiteral("description")),
            QStringLiteral("factory"), typeOf(f));
    QTreeWidgetItem *loaded = section(tr("Loaded modules"), QStringLiteral("loadedModules"));
    for (const Corba::Properties &m : snapshot.loaded)
        add(loaded, QUrl::fromLocalFile(modulePath(m)).fileName(), modulePath(m),
            QStringLiteral("loaded"), modulePath(m));
    QTreeWidgetItem *loadable = section(tr("Loadable modules"), QStringLiteral("loadableModules"));
    // A manager lists a loadable module by the component types it registers (OpenRTM-aist's and
    // rtmanager); one that only names files shows them.
    for (const Corba::Properties &m : snapshot.loadable) {
        const QString type = typeOf(m);
        add(loadable, type.isEmpty() ? QUrl::fromLocalFile(modulePath(m)).fileName() : type,
            modulePath(m), QStringLiteral("loadable"), modulePath(m));
    }
    // Only a manager with an install service has packages to show and install.
    m_install->setEnabled(snapshot.packages.has_value());
    m_uninstall->setEnabled(snapshot.packages.has_value());
    if (snapshot.packages) {
        QTreeWidgetItem *packages = section(tr("Installed packages"), QStringLiteral("packages"));
        for (const Corba::InstalledPackageInfo &p : *snapshot.packages) {
            auto *item = new QTreeWidgetItem(packages, {QStringLiteral("%1 %2").arg(p.name, p.version),
                                                        p.componentTypes.join(QLatin1Char(' '))});
            item->setToolTip(1, p.path);
            item->setData(0, KindRole, QStringLiteral("package"));
            item->setData(0, KeyRole, p.name);
            item->setData(0, VersionRole, p.version);
        }
    }
    m_tree->expandAll();

    const QString type = m_type->currentText();
    m_type->clear();
    m_type->addItems(types());
    if (!type.isEmpty())
        m_type->setCurrentText(type);
    const int target = m_target->currentIndex();
    m_target->clear();
    m_target->addItems(targets());
    m_target->setCurrentIndex(std::max(0, std::min(target, m_target->count() - 1)));
}

QStringList ManagerView::types() const
{
    // A type a loadable module registers is created by loading that module.
    QStringList result;
    for (const auto *list : {&m_snapshot.factories, &m_snapshot.loadable}) {
        for (const Corba::Properties &p : *list) {
            const QString type = typeOf(p);
            if (!type.isEmpty() && !result.contains(type))
                result.append(type);
        }
    }
    return result;
}

QStringList ManagerView::targets() const
{
    QStringList result {tr("%1 (this manager)").arg(m_snapshot.name)};
    for (const auto &slave : m_snapshot.slaves)
        result.append(slave.first);
    return result;
}

QString ManagerView::targetIor(int target) const
{
    return target <= 0 || target > m_snapshot.slaves.size()
        ? m_ior
        : m_snapshot.slaves.at(target - 1).second;
}

void ManagerView::setCreateForm(const QString &type, int target,
                                const Corba::Properties &parameters)
{
    m_type->setCurrentText(type);
    m_target->setCurrentIndex(target);
    m_parameters->setRowCount(0);
    for (const auto &[name, value] : parameters) {
        const int row = m_parameters->rowCount();
        m_parameters->insertRow(row);
        m_parameters->setItem(row, 0, new QTableWidgetItem(name));
        m_parameters->setItem(row, 1, new QTableWidgetItem(value));
    }
}

QString ManagerView::createArgument() const
{
    QStringList pairs;
    for (int row = 0; row < m_parameters->rowCount(); ++row) {
        const QTableWidgetItem *name = m_parameters->item(row, 0);
        const QTableWidgetItem *value = m_parameters->item(row, 1);
        // Empty rows (e.g. an instance_name left blank) let the manager choose.
        if (!name || !value || name->text().trimmed().isEmpty() || value->text().isEmpty())
            continue;
        pairs.append(name->text().trimmed() + QLatin1Char('=') + value->text());
    }
    const QString type = m_type->currentText();
    return pairs.isEmpty() ? type : type + QLatin1Char('?') + pairs.join(QLatin1Char('&'));
}

void ManagerView::submit(const QString &ior, const std::function<void()> &call)
{
    const QString host = Corba::iorEndpoint(ior).isEmpty() ? m_path : Corba::iorEndpoint(ior);
    m_session->submit(
        host,
        [call] {
            call();
            return QVariant();
        },
        this,
        [this](const OnlineResult &result) {
            m_status->setText(result.ok ? tr("Done") : result.error);
            emit actionFinished(result.ok ? QString() : result.error);
            reload();
        });
}

void ManagerView::create()
{
    if (m_type->currentText().isEmpty())
        return;
    const QString ior = targetIor(m_target->currentIndex());
    const Corba::ManagerProxy target(ior, m_path);
    const QString argument = createArgument();
    submit(ior, [target, argument] { target.createComponent(argument); });
}

void ManagerView::deleteComponent(const QString &instanceName)
{
    if (instanceName.isEmpty())
        return;
    const Corba::ManagerProxy manager(m_ior, m_path);
    submit(m_ior, [manager, instanceName] { manager.deleteComponent(instanceName); });
}

void ManagerView::loadModule(const QString &path, const QString &initFunction)
{
    if (path.isEmpty())
        return;
    const Corba::ManagerProxy manager(m_ior, m_path);
    submit(m_ior, [manager, path, initFunction] { manager.loadModule(path, initFunction); });
}

void ManagerView::unloadModule(const QString &path)
{
    if (path.isEmpty())
        return;
    const Corba::ManagerProxy manager(m_ior, m_path);
    submit(m_ior, [manager, path] { manager.unloadModule(path); });
}

void ManagerView::installPackage(const QString &url)
{
    if (url.isEmpty() || m_ior.isEmpty())
        return;
    const Corba::PackageInstallerProxy installer(m_ior, m_path);
    m_status->setText(tr("Installing %1…").arg(url));
    submit(m_ior, [installer, url] { installer.installUrl(url); });
}

void ManagerView::uninstallPackage(const QString &package, const QString &version)
{
    if (package.isEmpty() || m_ior.isEmpty())
        return;
    const Corba::PackageInstallerProxy installer(m_ior, m_path);
    submit(m_ior, [installer, package, version] { installer.uninstall(package, version); });
}

void ManagerView::shutdown()
{
    if (m_ior.isEmpty())
        return;
    const Corba::ManagerProxy manager(m_ior, m_path);
    submit(m_ior, [manager] { manager.shutdown(); });
}

} // namespace SystemEditor
