// SPDX-License-Identifier: MIT
// Component creation and destruction functions, as a module registers them with the manager.
#ifndef RTM_FACTORY_H
#define RTM_FACTORY_H

#include <coil/Properties.h>
#include <rtm/NumberingPolicy.h>
#include <rtm/NumberingPolicyBase.h>
#include <rtm/RTC.h>

#include <algorithm>
#include <assert.h>
#include <cassert>
#include <ctime>
#include <exception>
#include <functional>
#include <mutex>
#include <ratio>
#include <stdexcept>
#include <sys/single_threaded.h>
#include <system_error>
#include <typeinfo>
#include <utility>

namespace RTC
{
class Manager;
class RTObject_impl;
using RtcBase = RTObject_impl;

/// Makes a new component object for @p manager.
using RtcNewFunc = RTObject_impl *(*)(Manager *manager);
/// Gives a component object back (after it has been finalized).
using RtcDeleteFunc = void (*)(RTObject_impl *rtc);

/// Drops the creator's reference to component @p rtc (what Delete<T> does for any type).
void deleteRTObject(RTObject_impl *rtc);

/// The creation function of component type @p T (constructed with the manager).
template <class T_New>
RTObject_impl *Create(Manager *manager)
{
    return new T_New(manager);
}

/**
 * The destruction function of component type @p T. Components are CORBA servants counted by
 * reference: this drops the creator's reference, so the object goes once the ORB holds none.
 */
template <class T_Delete>
void Delete(RTObject_impl *rtc)
{
    deleteRTObject(static_cast<T_Delete *>(rtc));
}

/// A factory of one component type: its profile and how many of its components live.
class FactoryBase
{
public:
    explicit FactoryBase(const coil::Properties &profile);
    virtual ~FactoryBase();
    virtual RTObject_impl *create(Manager *mgr) = 0;
    virtual void destroy(RTObject_impl *comp) = 0;
    virtual coil::Properties &profile();
    /// -1 at first; each create() adds one, each destroy() takes one away (as OpenRTM-aist counts).
    virtual int number();

protected:
    coil::Properties m_Profile;
    int m_Number;
};

/**
 * The factory of a C++ component type: create() makes the component with @p new_func, gives it
 * the type's profile and an instance name of the type name and the number @p policy (owned)
 * hands out; destroy() frees the number and calls @p delete_func.
 */
class FactoryCXX : public FactoryBase
{
public:
    FactoryCXX(const coil::Properties &profile, RtcNewFunc new_func, RtcDeleteFunc delete_func,
               RTM::NumberingPolicyBase *policy = new RTM::ProcessUniquePolicy());
    ~FactoryCXX() override;
    RTObject_impl *create(Manager *mgr) override;
    void destroy(RTObject_impl *comp) override;

protected:
    RtcNewFunc m_New;
    RtcDeleteFunc m_Delete;
    RTM::NumberingPolicyBase *m_policy;
};
} // namespace RTC

#endif // RTM_FACTORY_H
