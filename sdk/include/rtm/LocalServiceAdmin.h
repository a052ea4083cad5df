// SPDX-License-Identifier: MIT
// The local services of the manager's process: made, listed and ended in one place.
#ifndef RTC_LOCALSERVICEADMIN_H
#define RTC_LOCALSERVICEADMIN_H

#include <coil/Factory.h>
#include <coil/Singleton.h>
#include <rtm/LocalServiceBase.h>
#include <rtm/SystemLogger.h>
#include <rtm/idl/SDOPackageStub.h>

#include <mutex>
#include <string>
#include <vector>

namespace RTM
{
class LocalServiceBase;
/// Makes a local service (what LocalServiceFactory entries are built from).
using ECNewFunc = LocalServiceBase *(*)();
/// Deletes a local service made by the matching ECNewFunc.
using ECDeleteFunc = void (*)(LocalServiceBase *);

/**
 * The process's local services. init() makes, from RTM::LocalServiceFactory, the services whose
 * names the `enabled_services` property lists (comma separated; `ALL` for every registered one),
 * initialises each with the properties given and keeps those that accept them; finalize() ends
 * them all. Services can also be added by hand (addLocalService), and are then ended with the rest.
 */
class LocalServiceAdmin : public coil::Singleton<LocalServiceAdmin>
{
public:
    LocalServiceAdmin();
    virtual ~LocalServiceAdmin();

    void init(coil::Properties &props);
    /// Finalizes and deletes every service.
    void finalize();
    ::RTM::LocalServiceProfileList getServiceProfiles();
    /// Copies the profile of service @p name into @p prof; false when there is none.
    bool getServiceProfile(const std::string &name, ::RTM::LocalServiceProfile &prof);
    /// Service @p id (its profile's name); null when there is none.
    ::RTM::LocalServiceBase *getService(const char *id);
    /// Keeps @p service (owned from now on); false for null or a name already kept.
    bool addLocalService(::RTM::LocalServiceBase *service);
    /// Finalizes and deletes service @p name; false when there is none.
    bool removeLocalService(const std::string &name);

private:
    bool isEnabled(const std::string &id, const coil::vstring &enabled);
    bool notExisting(const std::string &id); // m_services_mutex held
    std::vector<LocalServiceBase *> m_services;
    std::mutex m_services_mutex;
    ::RTC::Logger rtclog;
};
} // namespace RTM

#endif // RTC_LOCALSERVICEADMIN_H
