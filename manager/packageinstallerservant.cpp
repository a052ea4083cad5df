// SPDX-License-Identifier: MIT
#include "packageinstallerservant.h"

#include "manager.h"

#include <packagetool.h>
#include <repositoryfetcher.h>

#include <QFile>

#include <iostream>

namespace Runtime {

namespace {

QString qs(const std::string &text)
{
    return QString::fromStdString(text);
}

QByteArray bytes(const RTStudio::OctetSeq &sequence)
{
    return QByteArray(reinterpret_cast<const char *>(sequence.get_buffer()),
                      qsizetype(sequence.length()));
}

RTStudio::InstalledPackage toWire(const Packages::InstalledPackage &package)
{
    RTStudio::InstalledPackage wire;
    wire.name = package.name.toStdString().c_str();
    wire.version = package.version.toStdString().c_str();
    wire.architecture = package.architecture.toStdString().c_str();
    wire.component_types.length(CORBA::ULong(package.componentTypes.size()));
    for (CORBA::ULong i = 0; i < wire.component_types.length(); ++i)
        wire.component_types[i] = package.componentTypes.at(qsizetype(i)).toStdString().c_str();
    wire.path = package.path.toStdString().c_str();
    return wire;
}

std::vector<std::string> toStd(const QStringList &list)
{
    std::vector<std::string> result;
    for (const QString &item : list)
        result.push_back(item.toStdString());
    return result;
}

bool isBelow(const std::string &path, const QString &folder)
{
    return qs(path).startsWith(folder + QLatin1Char('/'));
}

} // namespace

PackageInstallerServant *PackageInstallerServant::create(Manager &manager, std::string *error)
{
    const Properties config = manager.configuration();
    if (!config.isYes("manager.packages.enable", true))
        return nullptr;
    const QString root = qs(config.value("manager.packages.store"));
    Packages::PackageStore store(root.isEmpty() ? Packages::PackageStore::defaultRoot() : root);
    QString reason;
    // A slave shares its master's store and starts while the master may be installing: only a
    // manager a user started clears what interrupted installs left.
    if (!config.contains("manager.spawned_by") && !store.prepare(&reason)) {
        *error = reason.toStdString();
        return nullptr;
    }
    Packages::InstallPolicy policy;
    policy.keyring = qs(config.value("manager.packages.keyring"));
    policy.allowUnsigned = config.isYes("manager.packages.allow_unsigned");
    policy.sdkAbi = qs(config.value("manager.packages.sdk_abi", RTSTUDIO_SDK_ABI));
    const int timeout
        = std::max(1, std::atoi(config.value("manager.packages.fetch_timeout", "60000").c_str()));
    // The store is read on each lookup, so that what an install put there is loadable at once.
    manager.setPackageModuleDirs(
        [store](const std::string &version) { return toStd(store.moduleDirs(qs(version))); });
    return new PackageInstallerServant(manager, std::move(store), std::move(policy), timeout,
                                       qs(config.value("manager.packages.ca_certificates")));
}

PackageInstallerServant::PackageInstallerServant(Manager &manager, Packages::PackageStore store,
                                                 Packages::InstallPolicy policy, int fetchTimeoutMs,
                                                 QString caCertificates)
    : m_manager(manager)
    , m_store(std::move(store))
    , m_policy(std::move(policy))
    , m_fetchTimeoutMs(fetchTimeoutMs)
    , m_caCertificates(std::move(caCertificates))
{ }

const Packages::InstallPolicy &PackageInstallerServant::policy()
{
    // Asked at the first install, not at every manager's (and slave's) start.
    if (m_policy.architecture.isEmpty()) {
        const Packages::ToolResult arch
            = Packages::runTool(QStringLiteral("dpkg"), {QStringLiteral("--print-architecture")});
        m_policy.architecture = QString::fromUtf8(arch.out).trimmed();
    }
    return m_policy;
}

void PackageInstallerServant::refuse(const QString &package, const QString &reason) const
{
    std::cerr
        << "rtmanager: install refused: "
        << (package.isEmpty() ? reason : package + QStringLiteral(": ") + reason).toStdString()
        << std::endl;
    throw RTStudio::InstallRefused(package.toStdString().c_str(), reason.toStdString().c_str());
}

RTStudio::InstalledPackage *PackageInstallerServant::install(const Packages::PackageSource &source)
{
    const Packages::PackageInstaller installer(m_store, policy());
    Packages::InstallError error;
    const std::optional<Packages::InstalledPackage> installed = installer.install(source, &error);
    if (!installed)
        refuse(error.package, error.reason);
    return new RTStudio::InstalledPackage(toWire(*installed));
}

PackageInstallerServant::Download::Download(const Packages::PackageStore &store,
                                            const QString &package,
                                            const PackageInstallerServant *servant)
    : m_store(store)
{
    // A staging folder of the store: what a killed manager leaves there goes at its next start.
    QString reason;
    const std::optional<QString> folder = store.createStaging(&reason);
    if (!folder)
        servant->refuse(package, reason);
    m_path = *folder;
}

PackageInstallerServant::Download::~Download()
{
    m_store.discard(m_path);
}

RTStudio::InstalledPackage *PackageInstallerServant::install_url(const char *url)
{
    std::lock_guard lock(m_mutex);
    const QUrl location = QUrl::fromUserInput(QString::fromUtf8(url ? url : ""));
    const Download download(m_store, location.fileName(), this);
    const Packages::RepositoryFetcher fetcher(policy().architecture, m_fetchTimeoutMs,
                                              m_caCertificates);
    QString reason;
    const std::optional<Packages::PackageSource> source
        = fetcher.fetch(location, download.path(), &reason);
    if (!source)
        refuse(location.fileName(), reason);
    return install(*source);
}

RTStudio::InstalledPackage *PackageInstallerServant::install_package(
    const RTStudio::OctetSeq &deb, const RTStudio::OctetSeq &in_release, const char *index_path,
    const RTStudio::OctetSeq &index, const char *package, const char *version)
{
    std::lock_guard lock(m_mutex);
    Packages::PackageSource source;
    source.inRelease = bytes(in_release);
    source.indexPath = QString::fromUtf8(index_path ? index_path : "");
    source.index = bytes(index);
    source.package = QString::fromUtf8(package ? package : "");
    source.version = QString::fromUtf8(version ? version : "");
    const Download download(m_store, source.package, this);
    source.debFile = download.path() + QStringLiteral("/package.deb");
    QFile file(source.debFile);
    const QByteArray data = bytes(deb);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.flush())
        refuse(source.package,
               QStringLiteral("cannot keep the package pushed: ") + file.errorString());
    file.close();
    return install(source);
}

void PackageInstallerServant::checkNotRunning(const Packages::InstalledPackage &package)
{
    const QString name = package.name + QLatin1Char(' ') + package.version;
    for (const std::string &module : m_manager.runningModulePaths()) {
        if (isBelow(module, package.path))
            refuse(name,
                   QStringLiteral("components made from %1 are running; delete them first")
                       .arg(qs(module).section(QLatin1Char('/'), -1)));
    }
    // Slaves share the store; what they run is known by type only, so any version counts.
    if (!m_manager.isMaster())
        return;
    const RTC::ComponentProfileList profiles = m_manager.slaveComponentProfiles();
    for (CORBA::ULong i = 0; i < profiles.length(); ++i) {
        const QString type = QString::fromUtf8(profiles[i].type_name.in());
        if (package.componentTypes.contains(type))
            refuse(name,
                   QStringLiteral("%1 components are running in a slave manager; delete them first")
                       .arg(type));
    }
}

void PackageInstallerServant::unloadModules(const Packages::InstalledPackage &package)
{
    for (const Properties &module : m_manager.loadedModules()) {
        const std::string path = module.value("file_path");
        if (isBelow(path, package.path))
            m_manager.unloadModule(path, nullptr);
    }
}

void PackageInstallerServant::uninstall(const char *package, const char *version)
{
    std::lock_guard lock(m_mutex);
    const QString name = QString::fromUtf8(package ? package : "");
    const QString wanted = QString::fromUtf8(version ? version : "");
    QList<Packages::InstalledPackage> removed;
    for (const Packages::InstalledPackage &installed : m_store.versions(name)) {
        if (wanted.isEmpty() || installed.version == wanted)
            removed << installed;
    }
    if (removed.isEmpty())
        refuse(name,
               wanted.isEmpty() ? QStringLiteral("not installed")
                                : QStringLiteral("version %1 is not installed").arg(wanted));
    for (const Packages::InstalledPackage &installed : removed)
        checkNotRunning(installed);
    for (const Packages::InstalledPackage &installed : removed) {
        unloadModules(installed);
        QString reason;
        if (!m_store.remove(installed, &reason))
            refuse(name + QLatin1Char(' ') + installed.version, reason);
    }
}

RTStudio::InstalledPackageList *PackageInstallerServant::list_installed()
{
    const QList<Packages::InstalledPackage> all = m_store.installed();
    auto *list = new RTStudio::InstalledPackageList;
    list->length(CORBA::ULong(all.size()));
    for (CORBA::ULong i = 0; i < list->length(); ++i)
        (*list)[i] = toWire(all.at(qsizetype(i)));
    return list;
}

} // namespace Runtime
