// SPDX-License-Identifier: MIT
// Component creation and destruction functions, as a module registers them with the manager.
#ifndef RTM_FACTORY_H
#define RTM_FACTORY_H

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
    if (rtc != nullptr)
        static_cast<PortableServer::ServantBase *>(static_cast<T_Delete *>(rtc))->_remove_ref();
}
} // namespace RTC

#endif // RTM_FACTORY_H
