// SPDX-License-Identifier: MIT
#include "manageractions.h"

#include "sdkinternal.h"

#include <rtm/RTObject.h>

#include <manager.h>

namespace RTM {

ManagerActionListener::~ManagerActionListener() = default;
ModuleActionListener::~ModuleActionListener() = default;
RtcLifecycleActionListener::~RtcLifecycleActionListener() = default;
NamingActionListener::~NamingActionListener() = default;
LocalServiceActionListener::~LocalServiceActionListener() = default;

ManagerActionListenerHolder::ManagerActionListenerHolder() = default;
ManagerActionListenerHolder::~ManagerActionListenerHolder() = default;

void ManagerActionListenerHolder::preShutdown()
{
    LISTENERHOLDER_CALLBACK(preShutdown, ());
}

void ManagerActionListenerHolder::postShutdown()
{
    LISTENERHOLDER_CALLBACK(postShutdown, ());
}

void ManagerActionListenerHolder::preReinit()
{
    LISTENERHOLDER_CALLBACK(preReinit, ());
}

void ManagerActionListenerHolder::postReinit()
{
    LISTENERHOLDER_CALLBACK(postReinit, ());
}

ModuleActionListenerHolder::ModuleActionListenerHolder() = default;
ModuleActionListenerHolder::~ModuleActionListenerHolder() = default;

void ModuleActionListenerHolder::preLoad(std::string &modname, std::string &funcname)
{
    LISTENERHOLDER_CALLBACK(preLoad, (modname, funcname));
}

void ModuleActionListenerHolder::postLoad(std::string &modname, std::string &funcname)
{
    LISTENERHOLDER_CALLBACK(postLoad, (modname, funcname));
}

void ModuleActionListenerHolder::preUnload(std::string &modname)
{
    LISTENERHOLDER_CALLBACK(preUnload, (modname));
}

void ModuleActionListenerHolder::postUnload(std::string &modname)
{
    LISTENERHOLDER_CALLBACK(postUnload, (modname));
}

RtcLifecycleActionListenerHolder::RtcLifecycleActionListenerHolder() = default;
RtcLifecycleActionListenerHolder::~RtcLifecycleActionListenerHolder() = default;

void RtcLifecycleActionListenerHolder::preCreate(std::string &args)
{
    LISTENERHOLDER_CALLBACK(preCreate, (args));
}

void RtcLifecycleActionListenerHolder::postCreate(RTC::RTObject_impl *rtobj)
{
    LISTENERHOLDER_CALLBACK(postCreate, (rtobj));
}

void RtcLifecycleActionListenerHolder::preConfigure(coil::Properties &prop)
{
    LISTENERHOLDER_CALLBACK(preConfigure, (prop));
}

void RtcLifecycleActionListenerHolder::postConfigure(coil::Properties &prop)
{
    LISTENERHOLDER_CALLBACK(postConfigure, (prop));
}

void RtcLifecycleActionListenerHolder::preInitialize()
{
    LISTENERHOLDER_CALLBACK(preInitialize, ());
}

void RtcLifecycleActionListenerHolder::postInitialize()
{
    LISTENERHOLDER_CALLBACK(postInitialize, ());
}

NamingActionListenerHolder::NamingActionListenerHolder() = default;
NamingActionListenerHolder::~NamingActionListenerHolder() = default;

void NamingActionListenerHolder::preBind(RTC::RTObject_impl *rtobj, coil::vstring &name)
{
    LISTENERHOLDER_CALLBACK(preBind, (rtobj, name));
}

void NamingActionListenerHolder::postBind(RTC::RTObject_impl *rtobj, coil::vstring &name)
{
    LISTENERHOLDER_CALLBACK(postBind, (rtobj, name));
}

void NamingActionListenerHolder::preUnbind(RTC::RTObject_impl *rtobj, coil::vstring &name)
{
    LISTENERHOLDER_CALLBACK(preUnbind, (rtobj, name));
}

void NamingActionListenerHolder::postUnbind(RTC::RTObject_impl *rtobj, coil::vstring &name)
{
    LISTENERHOLDER_CALLBACK(postUnbind, (rtobj, name));
}

LocalServiceActionListenerHolder::LocalServiceActionListenerHolder() = default;
LocalServiceActionListenerHolder::~LocalServiceActionListenerHolder() = default;

void LocalServiceActionListenerHolder::preServiceRegister(std::string service_name)
{
    LISTENERHOLDER_CALLBACK(preServiceRegister, (service_name));
}

void LocalServiceActionListenerHolder::postServiceRegister(std::string service_name, LocalServiceBase *service)
{
    LISTENERHOLDER_CALLBACK(postServiceRegister, (service_name, service));
}

void LocalServiceActionListenerHolder::preServiceInit(coil::Properties &prop, LocalServiceBase *service)
{
    LISTENERHOLDER_CALLBACK(preServiceInit, (prop, service));
}

void LocalServiceActionListenerHolder::postServiceInit(coil::Properties &prop, LocalServiceBase *service)
{
    LISTENERHOLDER_CALLBACK(postServiceInit, (prop, service));
}

void LocalServiceActionListenerHolder::preServiceReinit(coil::Properties &prop, LocalServiceBase *service)
{
    LISTENERHOLDER_CALLBACK(preServiceReinit, (prop, service));
}

void LocalServiceActionListenerHolder::postServiceReinit(coil::Properties &prop, LocalServiceBase *service)
{
    LISTENERHOLDER_CALLBACK(postServiceReinit, (prop, service));
}

void LocalServiceActionListenerHolder::postServiceFinalize(std::string service_name, LocalServiceBase *service)
{
    LISTENERHOLDER_CALLBACK(postServiceFinalize, (service_name, service));
}

void LocalServiceActionListenerHolder::preServiceFinalize(std::string service_name, LocalServiceBase *service)
{
    LISTENERHOLDER_CALLBACK(preServiceFinalize, (service_name, service));
}

ManagerActionListeners::ManagerActionListeners() = default;
ManagerActionListeners::~ManagerActionListeners() = default;

} // namespace RTM

namespace RTC::Sdk {

namespace {

/// Lets listeners see (and change) runtime properties through coil's interface.
template <typename Call>
void throughCoil(Runtime::Properties &properties, Call call)
{
    coil::Properties view = toCoil(properties);
    call(view);
    properties = toRuntime(view);
}

} // namespace

void ManagerActions::install(Runtime::Manager &runtime)
{
    using RTM::NamingActionListener;
    using RTM::RtcLifecycleActionListener;
    Runtime::Manager::LifecycleHooks hooks;
    hooks.preCreate = [this](std::string &request) {
        each(lifecycle, [&request](RtcLifecycleActionListener &l) { l.preCreate(request); });
    };
    hooks.postCreate = [this](Runtime::RtObject *component) {
        auto *rtobj = dynamic_cast<RTObject_impl *>(component);
        each(lifecycle, [rtobj](RtcLifecycleActionListener &l) { l.postCreate(rtobj); });
    };
    hooks.preConfigure = [this](Runtime::Properties &properties) {
        if (!lifecycle.empty())
            throughCoil(properties, [this](coil::Properties &p) {
                each(lifecycle, [&p](RtcLifecycleActionListener &l) { l.preConfigure(p); });
            });
    };
    hooks.postConfigure = [this](Runtime::Properties &properties) {
        if (!lifecycle.empty())
            throughCoil(properties, [this](coil::Properties &p) {
                each(lifecycle, [&p](RtcLifecycleActionListener &l) { l.postConfigure(p); });
            });
    };
    hooks.preInitialize = [this] { each(lifecycle, [](RtcLifecycleActionListener &l) { l.preInitialize(); }); };
    hooks.postInitialize = [this] { each(lifecycle, [](RtcLifecycleActionListener &l) { l.postInitialize(); }); };
    hooks.preNaming = [this](Runtime::RtObject *component, std::vector<std::string> &names, bool bind) {
        auto *rtobj = dynamic_cast<RTObject_impl *>(component);
        each(naming, [&](NamingActionListener &l) { bind ? l.preBind(rtobj, names) : l.preUnbind(rtobj, names); });
    };
    hooks.postNaming = [this](Runtime::RtObject *component, std::vector<std::string> &names, bool bind) {
        auto *rtobj = dynamic_cast<RTObject_impl *>(component);
        each(naming, [&](NamingActionListener &l) { bind ? l.postBind(rtobj, names) : l.postUnbind(rtobj, names); });
    };
    runtime.setLifecycleHooks(std::move(hooks));
}

} // namespace RTC::Sdk
