// SPDX-License-Identifier: MIT
#include "packageinstallerproxy.h"

#include "corbacall.h"
#include "orb.h"

#include <RTStudioManager.hh>

namespace Corba {

using namespace Internal;

namespace {

RTStudio::OctetSeq octets(const QByteArray &data)
{
    RTStudio::OctetSeq sequence;
    sequence.length(CORBA::ULong(data.size()));
    std::copy(data.cbegin(), data.cend(), reinterpret_cast<char *>(sequence.get_buffer()));
    return sequence;
}

InstalledPackageInfo fromWire(const RTStudio::InstalledPackage &wire)
{
    InstalledPackageInfo info {toQString(wire.name),
                               toQString(wire.version),
                               toQString(wire.architecture),
                               {},
                               toQString(wire.path)};
    for (CORBA::ULong i = 0; i < wire.component_types.length(); ++i)
        info.componentTypes << toQString(wire.component_types[i]);
    return info;
}

RTStudio::PackageInstaller_ptr narrow(const QString &ior, const QString &path)
{
    CORBA::Object_var object = toObject(ior, path);
    return RTStudio::PackageInstaller::_unchecked_narrow(object.in());
}

} // namespace

PackageInstallerProxy::PackageInstallerProxy(QString managerIor, QString path)
    : m_ior(std::move(managerIor))
    , m_path(std::move(path))
{ }

QString PackageInstallerProxy::installer() const
{
    CORBA::Object_var object = toObject(m_ior, m_path);
    RTStudio::Manager_var manager = RTStudio::Manager::_unchecked_narrow(object.in());
    const Error none(
        Error::Kind::WrongType,
        QStringLiteral("%1 has no install service (not an RT Studio manager)").arg(m_path));
    const QString ior = callServed(m_path, m_ior, [&] {
        try {
            RTStudio::PackageInstaller_var installer = manager->get_package_installer();
            return toIor(installer.in());
        } catch (const CORBA::BAD_OPERATION &) {
        } catch (const CORBA::NO_IMPLEMENT &) {
        } catch (const CORBA::OBJECT_NOT_EXIST &) { }
        // OpenRTM-aist's managers do not know the operation.
        throw none;
    });
    if (ior.isEmpty())
        throw Error(Error::Kind::WrongType,
                    QStringLiteral("%1 has no install service (manager.packages.enable is NO)")
                        .arg(m_path));
    return ior;
}

/// Runs @p f on the installer, an InstallRefused turned into a Refused error naming the package.
template<typename F> static auto onInstaller(const QString &path, const QString &ior, F &&f)
{
    RTStudio::PackageInstaller_var installer = narrow(ior, path);
    return callServed(path, ior, [&] {
        try {
            return f(installer.in());
        } catch (const RTStudio::InstallRefused &refused) {
            const QString package = toQString(refused.package);
            throw Error(Error::Kind::Refused,
                        QStringLiteral("%1: %2%3")
                            .arg(path,
                                 package.isEmpty() ? QString() : package + QStringLiteral(": "),
                                 toQString(refused.reason)));
        }
    });
}

InstalledPackageInfo PackageInstallerProxy::installUrl(const QString &url) const
{
    const QString ior = installer();
    const ThreadCallTimeout timeout(m_installTimeout);
    return onInstaller(m_path, ior, [&](RTStudio::PackageInstaller_ptr service) {
        RTStudio::InstalledPackage_var installed = service->install_url(url.toUtf8().constData());
        return fromWire(installed.in());
    });
}

InstalledPackageInfo PackageInstallerProxy::installPackage(const PushedPackage &package) const
{
    const QString ior = installer();
    const ThreadCallTimeout timeout(m_installTimeout);
    return onInstaller(m_path, ior, [&](RTStudio::PackageInstaller_ptr service) {
        RTStudio::InstalledPackage_var installed = service->install_package(
            octets(package.deb), octets(package.inRelease), package.indexPath.toUtf8().constData(),
            octets(package.index), package.package.toUtf8().constData(),
            package.version.toUtf8().constData());
        return fromWire(installed.in());
    });
}

void PackageInstallerProxy::uninstall(const QString &package, const QString &version) const
{
    onInstaller(m_path, installer(), [&](RTStudio::PackageInstaller_ptr service) {
        service->uninstall(package.toUtf8().constData(), version.toUtf8().constData());
        return true;
    });
}

QList<InstalledPackageInfo> PackageInstallerProxy::installed() const
{
    return onInstaller(m_path, installer(), [&](RTStudio::PackageInstaller_ptr service) {
        RTStudio::InstalledPackageList_var list = service->list_installed();
        QList<InstalledPackageInfo> result;
        for (CORBA::ULong i = 0; i < list->length(); ++i)
            result << fromWire(list[i]);
        return result;
    });
}

} // namespace Corba
