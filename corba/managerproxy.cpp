// SPDX-License-Identifier: MIT
#include "managerproxy.h"

#include "corbacall.h"
#include "orb.h"
#include "rtcconversion.h"

#include <RTStudioManager.hh>

#include <climits>

namespace Corba {

using namespace Internal;

namespace {

RTM::Manager_ptr manager(const QString &ior, const QString &path)
{
    CORBA::Object_var object = toObject(ior, path);
    return RTM::Manager::_unchecked_narrow(object.in());
}

std::vector<Properties> modules(const RTM::ModuleProfileList &list)
{
    std::vector<Properties> result;
    for (CORBA::ULong i = 0; i < list.length(); ++i)
        result.push_back(fromNVList(list[i].properties));
    return result;
}

template<typename List> QStringList iors(const List &list)
{
    QStringList result;
    for (CORBA::ULong i = 0; i < list.length(); ++i)
        result.append(toIor(list[i].in()));
    return result;
}

} // namespace

ManagerProxy::ManagerProxy(QString ior, QString path)
    : m_ior(std::move(ior))
    , m_path(std::move(path))
{ }

void ManagerProxy::loadModule(const QString &pathName, const QString &initFunction) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    const int code = callServed(m_path, m_ior, [&] {
        return int(
            mgr->load_module(pathName.toUtf8().constData(), initFunction.toUtf8().constData()));
    });
    checkWithReason(code, QStringLiteral("load_module(%1)").arg(pathName));
}

void ManagerProxy::unloadModule(const QString &pathName) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    const int code
        = callServed(m_path, m_ior, [&] { return int(mgr->unload_module(pathName.toUtf8().constData())); });
    checkWithReason(code, QStringLiteral("unload_module(%1)").arg(pathName));
}

std::vector<Properties> ManagerProxy::loadableModules() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTM::ModuleProfileList_var list = mgr->get_loadable_modules();
        return modules(list.in());
    });
}

std::vector<Properties> ManagerProxy::loadedModules() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTM::ModuleProfileList_var list = mgr->get_loaded_modules();
        return modules(list.in());
    });
}

std::vector<Properties> ManagerProxy::factoryProfiles() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTM::ModuleProfileList_var list = mgr->get_factory_profiles();
        return modules(list.in());
    });
}

QString ManagerProxy::createComponent(const QString &moduleName) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    const QString ior = callServed(m_path, m_ior, [&] {
        RTC::RTObject_var rtc = mgr->create_component(moduleName.toUtf8().constData());
        return toIor(rtc.in());
    });
    if (ior.isEmpty())
        throw Error(Error::Kind::Refused, refusal(moduleName, refusalReason(moduleName)));
    return ior;
}

std::optional<ManagerProxy::Created>
ManagerProxy::createComponents(const QStringList &requests) const
{
    CORBA::Object_var object = toObject(m_ior, m_path);
    RTStudio::Manager_var mgr = RTStudio::Manager::_unchecked_narrow(object.in());
    RTStudio::CreateRequestList list;
    list.length(CORBA::ULong(requests.size()));
    for (CORBA::ULong i = 0; i < list.length(); ++i)
        list[i] = requests.at(qsizetype(i)).toUtf8().constData();
    const ThreadCallTimeout allCreates(
        int(qMin(qint64(Orb::callTimeout()) * qMax(1, requests.size()), qint64(INT_MAX))));
    CORBA::String_var reason;
    RTC::RTCList_var made;
    const bool served = callServed(m_path, m_ior, [&] {
        try {
            made = mgr->create_components(list, reason.out());
            return true;
        } catch (const CORBA::BAD_OPERATION &) {
            return false;
        }
    });
    if (!served)
        return std::nullopt;
    Created created {iors(made.in()), QString()};
    if (created.iors.size() < requests.size())
        created.refusal = refusal(requests.at(created.iors.size()), toQString(reason.in()));
    return created;
}

// Manager operations answer a refusal with a return code alone; rtmanager says why in its
// profile's last_error, which the message then carries (OpenRTM-aist's managers have none).
void ManagerProxy::checkWithReason(int code, const QString &operation) const
{
    try {
        checkReturnCode(code, m_path, operation);
    } catch (const Error &e) {
        if (e.kind() != Error::Kind::Refused)
            throw;
        QString reason;
        try {
            reason = propertyValue(profile(), QStringLiteral("last_error"));
        } catch (const Error &) {
            // The refusal alone is the message then.
        }
        if (reason.isEmpty())
            throw;
        throw Error(e.kind(), e.message() + QStringLiteral(" (") + reason + QLatin1Char(')'));
    }
}

QString ManagerProxy::refusal(const QString &request, const QString &reason) const
{
    return QStringLiteral("%1: could not create '%2'%3")
        .arg(m_path, request, reason.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(reason));
}

// create_component answers a refusal with nil alone; rtmanager says why in its profile (a slave
// or another host's manager it could not reach, an unknown type, a name taken): by request, as
// creates may run side by side, else its last error.
QString ManagerProxy::refusalReason(const QString &request) const
{
    try {
        const Properties properties = profile();
        const QString reason
            = propertyValue(properties, QStringLiteral("rtstudio.create_error.") + request);
        return reason.isEmpty() ? propertyValue(properties, QStringLiteral("last_error")) : reason;
    } catch (const Error &) {
        return QString();
    }
}

QString ManagerProxy::deleteComponent(const QString &instanceName) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    const int code = call(
        m_path, [&] { return int(mgr->delete_component(instanceName.toUtf8().constData())); });
    try {
        checkReturnCode(code, m_path, QStringLiteral("delete_component(%1)").arg(instanceName));
        return m_path;
    } catch (const Error &refused) {
        QStringList slaves;
        try {
            slaves = slaveManagers();
        } catch (const Error &) {
            throw refused;
        }
        for (qsizetype i = 0; i < slaves.size(); ++i) {
            const ManagerProxy slave(slaves.at(i), m_path + QLatin1Char('/') + slaveName(int(i)));
            try {
                if (slave.componentsByName(instanceName).isEmpty())
                    continue;
            } catch (const Error &) {
                continue; // a slave that does not answer cannot be asked to delete either
            }
            return slave.deleteComponent(instanceName);
        }
        throw refused;
    }
}

QStringList ManagerProxy::components() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTC::RTCList_var list = mgr->get_components();
        return iors(list.in());
    });
}

std::vector<ComponentInfo> ManagerProxy::componentProfiles() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTC::ComponentProfileList_var list = mgr->get_component_profiles();
        std::vector<ComponentInfo> result;
        for (CORBA::ULong i = 0; i < list->length(); ++i)
            result.push_back(toComponentInfo(list[i]));
        return result;
    });
}

QStringList ManagerProxy::componentsByName(const QString &name) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTC::RTCList_var list = mgr->get_components_by_name(name.toUtf8().constData());
        return iors(list.in());
    });
}

Properties ManagerProxy::profile() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTM::ManagerProfile_var profile = mgr->get_profile();
        return fromNVList(profile->properties);
    });
}

Properties ManagerProxy::configuration() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTM::NVList_var list = mgr->get_configuration();
        return fromNVList(list.in());
    });
}

void ManagerProxy::setConfiguration(const QString &name, const QString &value) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    const int code = callServed(m_path, m_ior, [&] {
        return int(mgr->set_configuration(name.toUtf8().constData(), value.toUtf8().constData()));
    });
    checkReturnCode(code, m_path, QStringLiteral("set_configuration(%1)").arg(name));
}

bool ManagerProxy::isMaster() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] { return bool(mgr->is_master()); });
}

QStringList ManagerProxy::masterManagers() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTM::ManagerList_var list = mgr->get_master_managers();
        return iors(list.in());
    });
}

void ManagerProxy::addMasterManager(const QString &managerIor) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    RTM::Manager_var other = manager(managerIor, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(mgr->add_master_manager(other.in())); }), m_path,
                    QStringLiteral("add_master_manager"));
}

void ManagerProxy::removeMasterManager(const QString &managerIor) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    RTM::Manager_var other = manager(managerIor, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(mgr->remove_master_manager(other.in())); }),
                    m_path, QStringLiteral("remove_master_manager"));
}

QStringList ManagerProxy::slaveManagers() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        RTM::ManagerList_var list = mgr->get_slave_managers();
        return iors(list.in());
    });
}

void ManagerProxy::addSlaveManager(const QString &managerIor) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    RTM::Manager_var other = manager(managerIor, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(mgr->add_slave_manager(other.in())); }), m_path,
                    QStringLiteral("add_slave_manager"));
}

void ManagerProxy::removeSlaveManager(const QString &managerIor) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    RTM::Manager_var other = manager(managerIor, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(mgr->remove_slave_manager(other.in())); }),
                    m_path, QStringLiteral("remove_slave_manager"));
}

void ManagerProxy::fork() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    checkWithReason(callServed(m_path, m_ior, [&] { return int(mgr->fork()); }), QStringLiteral("fork"));
}

void ManagerProxy::shutdown() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    checkReturnCode(callServed(m_path, m_ior, [&] { return int(mgr->shutdown()); }), m_path,
                    QStringLiteral("shutdown"));
}

void ManagerProxy::restart() const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    checkWithReason(callServed(m_path, m_ior, [&] { return int(mgr->restart()); }), QStringLiteral("restart"));
}

QString ManagerProxy::service(const QString &name) const
{
    RTM::Manager_var mgr = manager(m_ior, m_path);
    return callServed(m_path, m_ior, [&] {
        CORBA::Object_var object = mgr->get_service(name.toUtf8().constData());
        return toIor(object.in());
    });
}

} // namespace Corba
