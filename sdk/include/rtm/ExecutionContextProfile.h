// SPDX-License-Identifier: MIT
// The profile of an execution context: kind, rate, owner, participants and properties.
#ifndef RTC_EXECUTIONCONTEXTPROFILE_H
#define RTC_EXECUTIONCONTEXTPROFILE_H

#include <mutex>
#include <coil/Properties.h>
#include <rtm/idl/RTCStub.h>
#include <rtm/SystemLogger.h>

#include <chrono>

namespace RTC_impl
{
/**
 * An RTC::ExecutionContextProfile kept under a lock, with the rate also as a period. Contexts
 * built on it answer get_profile() with a copy.
 */
class ExecutionContextProfile
{
public:
    explicit ExecutionContextProfile(RTC::ExecutionKind kind = RTC::PERIODIC);
    virtual ~ExecutionContextProfile();

    void setObjRef(RTC::ExecutionContextService_ptr ec_ptr);
    RTC::ExecutionContextService_ptr getObjRef() const;
    /// BAD_PARAMETER for a rate that is not positive.
    RTC::ReturnCode_t setRate(double rate);
    RTC::ReturnCode_t setPeriod(std::chrono::nanoseconds period);
    double getRate() const;
    std::chrono::nanoseconds getPeriod() const;
    static const char *getKindString(RTC::ExecutionKind kind);
    const char *getKindString() const { return getKindString(m_profile.kind); }
    RTC::ReturnCode_t setKind(RTC::ExecutionKind kind);
    RTC::ExecutionKind getKind() const;
    RTC::ReturnCode_t setOwner(RTC::LightweightRTObject_ptr comp);
    RTC::RTObject_ptr getOwner() const;
    /// Adds @p comp to the participants (BAD_PARAMETER for nil).
    RTC::ReturnCode_t addComponent(RTC::LightweightRTObject_ptr comp);
    /// Removes @p comp (BAD_PARAMETER when it does not take part).
    RTC::ReturnCode_t removeComponent(RTC::LightweightRTObject_ptr comp);
    const RTC::RTCList &getComponentList() const;
    void setProperties(coil::Properties &props);
    coil::Properties getProperties() const;
    /// A copy for the caller to own.
    RTC::ExecutionContextProfile *getProfile();
    const RTC::ExecutionContextProfile &getProfile() const;
    void lock() const;
    void unlock() const;

private:
    mutable RTC::Logger rtclog;
    RTC::ExecutionContextProfile m_profile;
    mutable std::mutex m_profileMutex;
    std::chrono::nanoseconds m_period;
    RTC::ExecutionContextService_var m_ref;
};
} // namespace RTC_impl

#endif // RTC_EXECUTIONCONTEXTPROFILE_H
