// SPDX-License-Identifier: MIT
#include "nodecommand.h"

#include "corbaerror.h"
#include "managerunit.h"
#include "packageinstallerproxy.h"

#include <packagetool.h>
#include <repository.h>
#include <repositoryindex.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

namespace Cli {

using namespace Corba;

namespace {

QByteArray readFile(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        throw Error(Error::Kind::NotFound, QStringLiteral("%1: %2").arg(path, file.errorString()));
    return file.readAll();
}

/// The .deb @p debFile with the files of the repository folder @p repo that list it.
PushedPackage pushedPackage(const QString &debFile, const QString &repo)
{
    Packages::Repository repository(repo);
    QString error;
    if (!repository.open(&error))
        throw Error(Error::Kind::NotFound, error);
    const std::optional<Packages::IndexEntry> entry
        = Packages::readDebEntry(debFile, QString(), &error);
    if (!entry)
        throw Error(Error::Kind::NotFound, error);
    const QString suite = repository.suiteFolder();
    QString arch = entry->architecture();
    // An Architecture: all package is listed in every architecture's index.
    if (arch == QLatin1String("all"))
        arch = repository.config().architectures.value(0);
    PushedPackage pushed;
    pushed.deb = readFile(debFile);
    // An unsigned repository has only its Release; the manager decides whether to take it.
    pushed.inRelease = readFile(QFileInfo::exists(suite + QStringLiteral("/InRelease"))
                                    ? suite + QStringLiteral("/InRelease")
                                    : suite + QStringLiteral("/Release"));
    pushed.indexPath = repository.config().component + QStringLiteral("/binary-") + arch
        + QStringLiteral("/Packages");
    pushed.index = readFile(suite + QLatin1Char('/') + pushed.indexPath);
    pushed.package = entry->package();
    pushed.version = entry->version();
    return pushed;
}

QString describe(const InstalledPackageInfo &package)
{
    return QStringLiteral("%1 %2 %3 %4 %5")
        .arg(package.name, package.version, package.architecture,
             package.componentTypes.isEmpty() ? QStringLiteral("-")
                                              : package.componentTypes.join(QLatin1Char(',')),
             package.path);
}

QJsonObject toJson(const InstalledPackageInfo &package)
{
    return {{QStringLiteral("package"), package.name},
            {QStringLiteral("version"), package.version},
            {QStringLiteral("architecture"), package.architecture},
            {QStringLiteral("types"), QJsonArray::fromStringList(package.componentTypes)},
            {QStringLiteral("path"), package.path}};
}

} // namespace

QString NodeCommand::summary() const
{
    return QStringLiteral("install component packages on a manager without root; start it at boot");
}

QString NodeCommand::usage() const
{
    return QStringLiteral(
        "Usage:\n"
        "  rtctl node install MANAGER URL [--timeout MS]\n"
        "  rtctl node install MANAGER FILE.deb --repo REPO [--timeout MS]\n"
        "  rtctl node uninstall MANAGER PACKAGE[=VERSION]\n"
        "  rtctl node packages MANAGER [--json]\n"
        "  rtctl node enable [--user|--system] [--config FILE] [--unit-dir DIR] [--program FILE]\n"
        "  rtctl node disable [--user|--system] [--unit-dir DIR]\n\n"
        "MANAGER is an RT Studio manager (rtmanager), named as for rtctl mgr (a path in the\n"
        "name servers or corbaloc::HOST:PORT/manager). It installs into its own package store\n"
        "(manager.packages.store, default $XDG_DATA_HOME/rtstudio/packages), without root.\n"
        "  URL        a package in the pool of a repository made by rtctl repo (http, https,\n"
        "             file), …/pool/COMPONENT/…/NAME_VERSION_ARCH.deb[#SUITE]: the manager\n"
        "             fetches it with the repository's InRelease and Packages index\n"
        "  FILE.deb   pushed through the call with the InRelease and index of the repository\n"
        "             folder REPO that lists it, for managers that cannot reach the repository\n"
        "Either way the manager verifies InRelease with gpgv against its keyring\n"
        "(manager.packages.keyring; manager.packages.allow_unsigned: YES takes unsigned ones),\n"
        "the index against the Release and the package against the index, then its\n"
        "Architecture, SDK ABI and Debian dependencies, and only then unpacks it. Its types are\n"
        "loadable at once; several versions stay side by side, the newest used unless a\n"
        "create request names one (\"Type?version=1.0\").\n"
        "--timeout MS bounds each call; for an install it defaults to 120000 (fetch, gpgv,\n"
        "unpack) instead of rtctl's default.\n"
        "uninstall refuses while components of the package run; without =VERSION it removes\n"
        "every version. packages prints NAME VERSION ARCH TYPES PATH per installed version.\n"
        "enable writes the systemd unit rtmanager.service starting rtmanager -f FILE at boot\n"
        "(a user unit in ~/.config/systemd/user by default, --system: /etc/systemd/system) and\n"
        "enables it with systemctl; --unit-dir DIR writes it there and leaves systemctl out;\n"
        "--program names the rtmanager (default: the one beside rtctl, else on PATH).\n"
        "disable removes it.\n"
        "Exit codes: 0 done, 1 refused or failed, 2 usage error.\n");
}

QStringList NodeCommand::flagNames() const
{
    return {QStringLiteral("--json"), QStringLiteral("--user"), QStringLiteral("--system")};
}

QStringList NodeCommand::optionNames() const
{
    return {QStringLiteral("--repo"), QStringLiteral("--config"), QStringLiteral("--unit-dir"),
            QStringLiteral("--program")};
}

int NodeCommand::execute(const RtOptions &options, Streams streams)
{
    const QString action = options.positionals.value(0);
    if (action == QLatin1String("enable") || action == QLatin1String("disable"))
        return unit(action == QLatin1String("enable"), options, streams);
    if (!QStringList {"install", "uninstall", "packages"}.contains(action))
        return usageError(action.isEmpty() ? QStringLiteral("missing action")
                                           : QStringLiteral("unknown action '%1'").arg(action),
                          streams);
    const int wanted = action == QLatin1String("packages") ? 2 : 3;
    if (options.positionals.size() != wanted)
        return usageError(QStringLiteral("'%1' needs %2")
                              .arg(action,
                                   wanted == 2 ? QStringLiteral("MANAGER")
                                               : QStringLiteral("MANAGER and one argument")),
                          streams);
    const ManagerProxy manager = managerAt(options.positionals.at(1));
    PackageInstallerProxy installer(manager.ior(), manager.path());
    // run() checked the number; an install fetches, verifies and unpacks: it waits that long.
    if (options.values.contains(QStringLiteral("--timeout")))
        installer.setInstallTimeout(options.value(QStringLiteral("--timeout")).toInt());
    if (action == QLatin1String("install"))
        return install(installer, options, streams);
    if (action == QLatin1String("uninstall"))
        return uninstall(installer, options.positionals.at(2), streams);
    return packages(installer, options.has(QStringLiteral("--json")), streams);
}

int NodeCommand::install(const PackageInstallerProxy &installer, const RtOptions &options,
                         Streams streams) const
{
    const QString what = options.positionals.at(2);
    const QString repo = options.value(QStringLiteral("--repo"));
    const bool isFile
        = what.endsWith(QLatin1String(".deb")) && !what.contains(QLatin1String("://"));
    if (isFile && repo.isEmpty())
        return usageError(QStringLiteral("%1: a pushed package needs --repo REPO").arg(what),
                          streams);
    const InstalledPackageInfo installed
        = isFile ? installer.installPackage(pushedPackage(what, repo)) : installer.installUrl(what);
    streams.out << describe(installed) << '\n';
    return ExitOk;
}

int NodeCommand::uninstall(const PackageInstallerProxy &installer, const QString &argument,
                           Streams streams) const
{
    installer.uninstall(argument.section(QLatin1Char('='), 0, 0),
                        argument.section(QLatin1Char('='), 1));
    Q_UNUSED(streams)
    return ExitOk;
}

int NodeCommand::packages(const PackageInstallerProxy &installer, bool json, Streams streams) const
{
    const QList<InstalledPackageInfo> all = installer.installed();
    if (json) {
        QJsonArray array;
        for (const InstalledPackageInfo &package : all)
            array.append(toJson(package));
        streams.out << jsonText(array) << '\n';
        return ExitOk;
    }
    for (const InstalledPackageInfo &package : all)
        streams.out << describe(package) << '\n';
    return ExitOk;
}

int NodeCommand::unit(bool enable, const RtOptions &options, Streams streams) const
{
    if (options.has(QStringLiteral("--user")) && options.has(QStringLiteral("--system")))
        return usageError(QStringLiteral("--user and --system exclude each other"), streams);
    const Deploy::ManagerUnit unit(
        options.has(QStringLiteral("--system")), options.value(QStringLiteral("--config")),
        options.value(QStringLiteral("--unit-dir")), options.value(QStringLiteral("--program")));
    QString error;
    if (!(enable ? unit.enable(&error) : unit.disable(&error))) {
        report(error, streams);
        return ExitProblems;
    }
    streams.out << unit.path() << '\n';
    return ExitOk;
}

} // namespace Cli
