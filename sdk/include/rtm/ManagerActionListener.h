// SPDX-License-Identifier: MIT
// Listeners of what the manager does: shutdown, module loading, component creation, naming.
// Component programs (<Name>Comp.cpp) of some OpenRTP generations register them.
#ifndef RTM_MANAGERACTIONLISTENER_H
#define RTM_MANAGERACTIONLISTENER_H

#include <coil/Properties.h>
#include <coil/stringutil.h>
#include <rtm/ListenerHolder.h>

#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace RTC
{
class RTObject_impl;
}

namespace RTM
{
class LocalServiceBase;

/// Called around the manager's shutdown and re-initialisation.
class ManagerActionListener
{
public:
    virtual ~ManagerActionListener();
    virtual void preShutdown() = 0;
    virtual void postShutdown() = 0;
    virtual void preReinit() = 0;
    virtual void postReinit() = 0;
};

/// Called around loading and unloading a module.
class ModuleActionListener
{
public:
    virtual ~ModuleActionListener();
    virtual void preLoad(std::string &modname, std::string &funcname) = 0;
    virtual void postLoad(std::string &modname, std::string &funcname) = 0;
    virtual void preUnload(std::string &modname) = 0;
    virtual void postUnload(std::string &modname) = 0;
};

/// Called at the steps of a component's creation in this process.
class RtcLifecycleActionListener
{
public:
    virtual ~RtcLifecycleActionListener();
    /// With the creation request (`Type?key=value&…`), which the listener may change.
    virtual void preCreate(std::string &args) = 0;
    virtual void postCreate(RTC::RTObject_impl *rtobj) = 0;
    /// With the component's properties before and after rtc.conf's and the request's settings apply.
    virtual void preConfigure(coil::Properties &prop) = 0;
    virtual void postConfigure(coil::Properties &prop) = 0;
    virtual void preInitialize() = 0;
    virtual void postInitialize() = 0;
};

/// Called around binding and unbinding a component's names in the name servers.
class NamingActionListener
{
public:
    virtual ~NamingActionListener();
    virtual void preBind(RTC::RTObject_impl *rtobj, coil::vstring &name) = 0;
    virtual void postBind(RTC::RTObject_impl *rtobj, coil::vstring &name) = 0;
    virtual void preUnbind(RTC::RTObject_impl *rtobj, coil::vstring &name) = 0;
    virtual void postUnbind(RTC::RTObject_impl *rtobj, coil::vstring &name) = 0;
};

/**
 * Called around local services (OpenRTM-aist's plug-in services). This SDK has none, so these
 * listeners are accepted and kept but never called.
 */
class LocalServiceActionListener
{
public:
    virtual ~LocalServiceActionListener();
    virtual void preServiceRegister(std::string service_name) = 0;
    virtual void postServiceRegister(std::string service_name, LocalServiceBase *service) = 0;
    virtual void preServiceInit(coil::Properties &prop, LocalServiceBase *service) = 0;
    virtual void postServiceInit(coil::Properties &prop, LocalServiceBase *service) = 0;
    virtual void preServiceReinit(coil::Properties &prop, LocalServiceBase *service) = 0;
    virtual void postServiceReinit(coil::Properties &prop, LocalServiceBase *service) = 0;
    virtual void postServiceFinalize(std::string service_name, LocalServiceBase *service) = 0;
    virtual void preServiceFinalize(std::string service_name, LocalServiceBase *service) = 0;
};
/// The ManagerActionListeners of a manager; each call reaches every listener in the order added.
class ManagerActionListenerHolder : public ::RTM::util::ListenerHolder<ManagerActionListener>
{
public:
    ManagerActionListenerHolder();
    ~ManagerActionListenerHolder() override;
    virtual void preShutdown();
    virtual void postShutdown();
    virtual void preReinit();
    virtual void postReinit();
};

/// The ModuleActionListeners of a manager; each call reaches every listener in the order added.
class ModuleActionListenerHolder : public ::RTM::util::ListenerHolder<ModuleActionListener>
{
public:
    ModuleActionListenerHolder();
    ~ModuleActionListenerHolder() override;
    virtual void preLoad(std::string &modname, std::string &funcname);
    virtual void postLoad(std::string &modname, std::string &funcname);
    virtual void preUnload(std::string &modname);
    virtual void postUnload(std::string &modname);
};

/// The RtcLifecycleActionListeners of a manager; each call reaches every listener in the order added.
class RtcLifecycleActionListenerHolder : public ::RTM::util::ListenerHolder<RtcLifecycleActionListener>
{
public:
    RtcLifecycleActionListenerHolder();
    ~RtcLifecycleActionListenerHolder() override;
    virtual void preCreate(std::string &args);
    virtual void postCreate(RTC::RTObject_impl *rtobj);
    virtual void preConfigure(coil::Properties &prop);
    virtual void postConfigure(coil::Properties &prop);
    virtual void preInitialize();
    virtual void postInitialize();
};

/// The NamingActionListeners of a manager; each call reaches every listener in the order added.
class NamingActionListenerHolder : public ::RTM::util::ListenerHolder<NamingActionListener>
{
public:
    NamingActionListenerHolder();
    ~NamingActionListenerHolder() override;
    virtual void preBind(RTC::RTObject_impl *rtobj, coil::vstring &name);
    virtual void postBind(RTC::RTObject_impl *rtobj, coil::vstring &name);
    virtual void preUnbind(RTC::RTObject_impl *rtobj, coil::vstring &name);
    virtual void postUnbind(RTC::RTObject_impl *rtobj, coil::vstring &name);
};

/// The LocalServiceActionListeners of a manager; each call reaches every listener in the order added.
class LocalServiceActionListenerHolder : public ::RTM::util::ListenerHolder<LocalServiceActionListener>
{
public:
    LocalServiceActionListenerHolder();
    ~LocalServiceActionListenerHolder() override;
    virtual void preServiceRegister(std::string service_name);
    virtual void postServiceRegister(std::string service_name, LocalServiceBase *service);
    virtual void preServiceInit(coil::Properties &prop, LocalServiceBase *service);
    virtual void postServiceInit(coil::Properties &prop, LocalServiceBase *service);
    virtual void preServiceReinit(coil::Properties &prop, LocalServiceBase *service);
    virtual void postServiceReinit(coil::Properties &prop, LocalServiceBase *service);
    virtual void postServiceFinalize(std::string service_name, LocalServiceBase *service);
    virtual void preServiceFinalize(std::string service_name, LocalServiceBase *service);
};

/// A manager's action listeners, one holder per kind.
class ManagerActionListeners
{
public:
    ManagerActionListeners();
    ~ManagerActionListeners();
    ManagerActionListenerHolder manager_;
    ModuleActionListenerHolder module_;
    RtcLifecycleActionListenerHolder rtclifecycle_;
    NamingActionListenerHolder naming_;
    LocalServiceActionListenerHolder localservice_;
};
} // namespace RTM

#endif // RTM_MANAGERACTIONLISTENER_H
