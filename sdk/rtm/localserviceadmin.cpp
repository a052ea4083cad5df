// SPDX-License-Identifier: MIT
#include <rtm/LocalServiceAdmin.h>

#include <coil/stringutil.h>

namespace RTM {

namespace {

/// Deletes @p service the way it was made: by the factory when it made it, else with delete.
void dispose(LocalServiceBase *service)
{
    if (LocalServiceFactory::instance().deleteObject(service) != coil::FactoryReturn::OK)
        delete service;
}

} // namespace

LocalServiceAdmin::LocalServiceAdmin()
    : rtclog("LocalServiceAdmin")
{
}

LocalServiceAdmin::~LocalServiceAdmin()
{
    finalize();
}

void LocalServiceAdmin::init(coil::Properties &props)
{
    coil::vstring enabled;
    for (const std::string &name : coil::split(props.getProperty("enabled_services"), ",", true))
        enabled.push_back(coil::eraseBlank(name));
    for (const std::string &id : LocalServiceFactory::instance().getIdentifiers()) {
        if (!isEnabled(id, enabled))
            continue;
        {
            std::lock_guard<std::mutex> lock(m_services_mutex);
            if (!notExisting(id))
                continue;
        }
        LocalServiceBase *service = LocalServiceFactory::instance().createObject(id);
        if (service == nullptr)
            continue;
        if (!service->init(props)) {
            RTC_ERROR(("local service '%s' refused its properties; not started", id.c_str()));
            dispose(service);
            continue;
        }
        std::lock_guard<std::mutex> lock(m_services_mutex);
        m_services.push_back(service);
    }
}

void LocalServiceAdmin::finalize()
{
    std::vector<LocalServiceBase *> services;
    {
        std::lock_guard<std::mutex> lock(m_services_mutex);
        services.swap(m_services);
    }
    for (LocalServiceBase *service : services) {
        service->finalize();
        dispose(service);
    }
}

LocalServiceProfileList LocalServiceAdmin::getServiceProfiles()
{
    std::lock_guard<std::mutex> lock(m_services_mutex);
    LocalServiceProfileList profiles;
    for (LocalServiceBase *service : m_services)
        profiles.push_back(service->getProfile());
    return profiles;
}

bool LocalServiceAdmin::getServiceProfile(const std::string &name, LocalServiceProfile &prof)
{
    std::lock_guard<std::mutex> lock(m_services_mutex);
    for (LocalServiceBase *service : m_services) {
        if (service->getProfile().name == name) {
            prof = service->getProfile();
            return true;
        }
    }
    return false;
}

LocalServiceBase *LocalServiceAdmin::getService(const char *id)
{
    std::lock_guard<std::mutex> lock(m_services_mutex);
    for (LocalServiceBase *service : m_services) {
        if (id != nullptr && service->getProfile().name == id)
            return service;
    }
    return nullptr;
}

bool LocalServiceAdmin::addLocalService(LocalServiceBase *service)
{
    if (service == nullptr)
        return false;
    std::lock_guard<std::mutex> lock(m_services_mutex);
    if (!notExisting(service->getProfile().name))
        return false;
    m_services.push_back(service);
    return true;
}

bool LocalServiceAdmin::removeLocalService(const std::string &name)
{
    LocalServiceBase *removed = nullptr;
    {
        std::lock_guard<std::mutex> lock(m_services_mutex);
        for (auto it = m_services.begin(); it != m_services.end(); ++it) {
            if ((*it)->getProfile().name == name) {
                removed = *it;
                m_services.erase(it);
                break;
            }
        }
    }
    if (removed == nullptr)
        return false;
    removed->finalize();
    dispose(removed);
    return true;
}

bool LocalServiceAdmin::isEnabled(const std::string &id, const coil::vstring &enabled)
{
    return coil::includes(enabled, "ALL") || coil::includes(enabled, id);
}

bool LocalServiceAdmin::notExisting(const std::string &id)
{
    for (LocalServiceBase *service : m_services) {
        if (service->getProfile().name == id)
            return false;
    }
    return true;
}

} // namespace RTM
