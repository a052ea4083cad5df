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
