// SPDX-License-Identifier: MIT
#include <rtm/SdoServiceAdmin.h>

#include <rtm/NVUtil.h>
#include <rtm/RTObject.h>
#include <rtm/SdoServiceConsumerBase.h>
#include <rtm/SdoServiceProviderBase.h>

#include <coil/UUID.h>

#include <memory>

namespace RTC {

namespace {

const char providerKey[] = "sdo.service.provider.enabled_services";
const char consumerKey[] = "sdo.service.consumer.enabled_services";

coil::vstring listOf(const coil::Properties &prop, const char *key)
{
    coil::vstring names;
    for (const std::string &name : coil::split(prop.getProperty(key), ",", true))
        names.push_back(coil::eraseBlank(name));
    return names;
}

bool listsAll(const coil::vstring &names)
{
    return coil::includes(names, "ALL");
}

} // namespace

SdoServiceAdmin::SdoServiceAdmin(RTObject_impl &rtobj)
    : m_rtobj(rtobj)
    , m_allConsumerEnabled(true)
    , rtclog("SdoServiceAdmin")
{
}

SdoServiceAdmin::~SdoServiceAdmin() = default;

void SdoServiceAdmin::init(const coil::Properties &prop)
{
    initProvider(prop);
    initConsumer(prop);
}

void SdoServiceAdmin::initProvider(const coil::Properties &prop)
{
    const coil::vstring enabled = listOf(prop, providerKey);
    coil::Properties options(prop); // getNode() is not const
    auto &factory = SdoServiceProviderFactory::instance();
    for (const std::string &type : factory.getIdentifiers()) {
        if (!listsAll(enabled) && !coil::includes(enabled, type))
            continue;
        SdoServiceProviderBase *provider = factory.createObject(type);
        if (provider == nullptr)
            continue;
        SDOPackage::ServiceProfile profile;
        profile.id = CORBA::string_dup(getUUID().c_str());
        profile.interface_type = CORBA::string_dup(type.c_str());
        NVUtil::copyFromProperties(profile.properties, options.getNode(type));
        if (!provider->init(m_rtobj, profile) || !addSdoServiceProvider(profile, provider)) {
            RTC_WARN(("SDO service provider '%s' refused to start; not offered", type.c_str()));
            factory.deleteObject(provider);
        }
    }
}

void SdoServiceAdmin::initConsumer(const coil::Properties &prop)
{
    m_consumerTypes = listOf(prop, consumerKey);
    // OpenRTM-aist's default for the key is ALL: an unset key accepts every type.
    m_allConsumerEnabled = m_consumerTypes.empty() || listsAll(m_consumerTypes);
}

SDOPackage::ServiceProfileList *SdoServiceAdmin::getServiceProviderProfiles()
{
    std::lock_guard<std::mutex> lock(m_rtobj.m_sdoMutex);
    auto *profiles = new SDOPackage::ServiceProfileList;
    profiles->length(CORBA::ULong(m_rtobj.m_sdoProviders.size()));
    CORBA::ULong i = 0;
    for (const auto &offered : m_rtobj.m_sdoProviders)
        (*profiles)[i++] = offered.first;
    return profiles;
}

SDOPackage::ServiceProfile *SdoServiceAdmin::getServiceProviderProfile(const char *id)
{
    std::lock_guard<std::mutex> lock(m_rtobj.m_sdoMutex);
    for (const auto &offered : m_rtobj.m_sdoProviders) {
        if (id != nullptr && std::string(offered.first.id) == id)
            return new SDOPackage::ServiceProfile(offered.first);
    }
    throw SDOPackage::InvalidParameter("no SDO service provider of this id");
}

SDOPackage::SDOService_ptr SdoServiceAdmin::getServiceProvider(const char *id)
{
    std::unique_ptr<SDOPackage::ServiceProfile> profile(getServiceProviderProfile(id));
    return SDOPackage::SDOService::_duplicate(profile->service);
}

bool SdoServiceAdmin::addSdoServiceProvider(const SDOPackage::ServiceProfile &prof, SdoServiceProviderBase *provider)
{
    return m_rtobj.addSdoServiceProvider(prof, provider);
}

bool SdoServiceAdmin::removeSdoServiceProvider(const char *id)
{
    return m_rtobj.removeSdoServiceProvider(id);
}

bool SdoServiceAdmin::addSdoServiceConsumer(const SDOPackage::ServiceProfile &sProfile)
{
    if (!isEnabledConsumerType(sProfile)) {
        RTC_ERROR(("SDO service consumer type '%s' is not enabled (%s)",
                   static_cast<const char *>(sProfile.interface_type), consumerKey));
        return false;
    }
    return m_rtobj.addSdoServiceConsumer(sProfile);
}

bool SdoServiceAdmin::removeSdoServiceConsumer(const char *id)
{
    return m_rtobj.removeSdoServiceConsumer(id);
}

bool SdoServiceAdmin::isEnabledConsumerType(const SDOPackage::ServiceProfile &sProfile)
{
    if (m_allConsumerEnabled)
        return true;
    std::string type(sProfile.interface_type);
    return coil::includes(m_consumerTypes, type) || coil::includes(m_consumerTypes, ifrToKey(type));
}

bool SdoServiceAdmin::isExistingConsumerType(const SDOPackage::ServiceProfile &sProfile)
{
    return SdoServiceConsumerFactory::instance().hasFactory(std::string(sProfile.interface_type));
}

std::string SdoServiceAdmin::getUUID()
{
    std::unique_ptr<coil::UUID> uuid(coil::UUID_Generator::generateUUID(2, 0x01));
    return uuid->to_string();
}

std::string SdoServiceAdmin::ifrToKey(std::string &ifr)
{
    // "IDL:module/Type:1.0": the last path element before the version.
    const std::string::size_type colon = ifr.rfind(':');
    const std::string path = ifr.substr(0, colon == std::string::npos || colon < 4 ? ifr.size() : colon);
    const std::string::size_type slash = path.find_last_of("/:");
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

} // namespace RTC
