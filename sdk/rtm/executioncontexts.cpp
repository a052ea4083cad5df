// SPDX-License-Identifier: MIT
// OpenRTM-aist's execution context classes on the runtime's engines, and their factory.
#include <rtm/ECFactory.h>
#include <rtm/ExtTrigExecutionContext.h>
#include <rtm/Manager.h>
#include <rtm/MultilayerCompositeEC.h>
#include <rtm/OpenHRPExecutionContext.h>
#include <rtm/PeriodicExecutionContext.h>
#include <rtm/RTObject.h>
#include <rtm/SimulatorExecutionContext.h>

#include "sdkinternal.h"

#include <corbautil.h>
#include <executioncontextfactory.h>

#include <algorithm>
#include <iostream>

namespace RTC {

namespace {

double numberOr(const coil::Properties &props, const char *key, double fallback)
{
    const std::string text = props.getProperty(key);
    try {
        return text.empty() ? fallback : std::stod(text);
    } catch (...) {
        return fallback;
    }
}

/// Settings a context takes from a component's properties, applied to @p engine.
void applySettings(Runtime::ExecutionContext *engine, coil::Properties &props)
{
    const double rate = numberOr(props, "exec_cxt.periodic.rate", 0.0);
    if (rate > 0.0)
        engine->set_rate(rate);
}

/// The engine of @p context, set up from the component's @p properties; null with @p error
/// naming @p type when the class has no engine (derived from ExecutionContextBase alone).
Runtime::ExecutionContext *engineOf(const std::string &type, ExecutionContextBase *context,
                                    const Runtime::Properties &properties, std::string *error)
{
    Runtime::ExecutionContext *engine = context != nullptr ? context->engine() : nullptr;
    if (engine == nullptr) {
        if (error)
            *error = "execution context type '" + type
                     + "' has no runtime engine: derive it from one of the built-in contexts";
        if (context != nullptr)
            ExecutionContextFactory::instance().deleteObject(context);
        return nullptr;
    }
    coil::Properties props = Sdk::toCoil(properties);
    context->init(props);
    return engine;
}

/// The runtime factory's entry for a built-in type: the SDK's class, so that C++ code finds
/// ExecutionContextBase behind a component's context.
Runtime::ExecutionContextFactory::Create engineCreator(const std::string &type, ECNewFunc create)
{
    return [type, create](const Runtime::Properties &properties, std::string *error) -> Runtime::ExecutionContext * {
        return engineOf(type, create(), properties, error);
    };
}

template <class Context>
void registerBuiltin(const char *type)
{
    Runtime::ExecutionContextFactory::instance().replace(type, engineCreator(type, ECCreate<Context>));
    ExecutionContextFactory::instance().addFactory(type, coil::Creator<ExecutionContextBase, Context>,
                                                   coil::Destructor<ExecutionContextBase, Context>);
}

/// The built-in types in both tables, and RTC::ExecutionContextFactory as the runtime's second
/// table: a type a program registers there is one `exec_cxt.periodic.type` can name.
const bool builtinsRegistered = [] {
    registerBuiltin<RTC_exp::PeriodicExecutionContext>("PeriodicExecutionContext");
    registerBuiltin<RTC_exp::MultilayerCompositeEC>("MultilayerCompositeEC");
    registerBuiltin<ExtTrigExecutionContext>("ExtTrigExecutionContext");
    registerBuiltin<OpenHRPExecutionContext>("OpenHRPExecutionContext");
    registerBuiltin<SimulatorExecutionContext>("SimulatorExecutionContext");
    Runtime::ExecutionContextFactory::instance().setExternal(
        [] { return ExecutionContextFactory::instance().getIdentifiers(); },
        [](const std::string &type, const Runtime::Properties &properties,
           std::string *error) -> Runtime::ExecutionContext * {
            return engineOf(type, ExecutionContextFactory::instance().createObject(type), properties, error);
        });
    return true;
}();

} // namespace

// --- ExecutionContextBase ---

ExecutionContextBase::ExecutionContextBase(const char *name)
    : rtclog(name != nullptr ? name : "ec")
    , m_engine(nullptr)
    , m_name(name != nullptr ? name : "")
{
    (void)builtinsRegistered;
}

ExecutionContextBase::~ExecutionContextBase() = default;

Runtime::ExecutionContext *ExecutionContextBase::requireEngine(const char *call) const
{
    if (m_engine == nullptr) {
        const std::string message = "ExecutionContextBase::" + std::string(call) + ": execution context '" + m_name
                                    + "' has no runtime engine (derive from a built-in execution context)";
        RTC_ERROR_STR(message);
        std::cerr << message << std::endl;
    }
    return m_engine;
}

void ExecutionContextBase::init(coil::Properties &props)
{
    m_properties << props;
    if (Runtime::ExecutionContext *engine = requireEngine("init"))
        applySettings(engine, props);
}

ReturnCode_t ExecutionContextBase::bindComponent(RTObject_impl *rtc)
{
    Runtime::ExecutionContext *engine = requireEngine("bindComponent");
    if (engine == nullptr)
        return RTC::RTC_ERROR;
    if (rtc == nullptr)
        return RTC::BAD_PARAMETER;
    return rtc->bindContext(engine) < 0 ? RTC::RTC_ERROR : RTC::RTC_OK;
}

CORBA::Boolean ExecutionContextBase::isRunning()
{
    Runtime::ExecutionContext *engine = requireEngine("isRunning");
    return engine != nullptr && engine->is_running();
}

ReturnCode_t ExecutionContextBase::start()
{
    Runtime::ExecutionContext *engine = requireEngine("start");
    return engine ? engine->start() : RTC::RTC_ERROR;
}

ReturnCode_t ExecutionContextBase::stop()
{
    Runtime::ExecutionContext *engine = requireEngine("stop");
    return engine ? engine->stop() : RTC::RTC_ERROR;
}

double ExecutionContextBase::getRate() const
{
    Runtime::ExecutionContext *engine = requireEngine("getRate");
    return engine ? engine->get_rate() : 0.0;
}

std::chrono::nanoseconds ExecutionContextBase::getPeriod() const
{
    const double rate = getRate();
    return rate > 0.0 ? std::chrono::nanoseconds(static_cast<long long>(1e9 / rate)) : std::chrono::nanoseconds(0);
}

ReturnCode_t ExecutionContextBase::setRate(double rate)
{
    Runtime::ExecutionContext *engine = requireEngine("setRate");
    return engine ? engine->set_rate(rate) : RTC::RTC_ERROR;
}

ReturnCode_t ExecutionContextBase::addComponent(LightweightRTObject_ptr comp)
{
    Runtime::ExecutionContext *engine = requireEngine("addComponent");
    return engine ? engine->add_component(comp) : RTC::RTC_ERROR;
}

ReturnCode_t ExecutionContextBase::removeComponent(LightweightRTObject_ptr comp)
{
    Runtime::ExecutionContext *engine = requireEngine("removeComponent");
    return engine ? engine->remove_component(comp) : RTC::RTC_ERROR;
}

ReturnCode_t ExecutionContextBase::activateComponent(LightweightRTObject_ptr comp)
{
    Runtime::ExecutionContext *engine = requireEngine("activateComponent");
    return engine ? engine->activate_component(comp) : RTC::RTC_ERROR;
}

ReturnCode_t ExecutionContextBase::deactivateComponent(LightweightRTObject_ptr comp)
{
    Runtime::ExecutionContext *engine = requireEngine("deactivateComponent");
    return engine ? engine->deactivate_component(comp) : RTC::RTC_ERROR;
}

ReturnCode_t ExecutionContextBase::resetComponent(LightweightRTObject_ptr comp)
{
    Runtime::ExecutionContext *engine = requireEngine("resetComponent");
    return engine ? engine->reset_component(comp) : RTC::RTC_ERROR;
}

LifeCycleState ExecutionContextBase::getComponentState(LightweightRTObject_ptr comp)
{
    Runtime::ExecutionContext *engine = requireEngine("getComponentState");
    return engine ? engine->get_component_state(comp) : RTC::CREATED_STATE;
}

const char *ExecutionContextBase::getStateString(LifeCycleState state)
{
    static const char *const names[] = {"CREATED_STATE", "INACTIVE_STATE", "ACTIVE_STATE", "ERROR_STATE"};
    return state >= RTC::CREATED_STATE && state <= RTC::ERROR_STATE ? names[state] : "";
}

ExecutionKind ExecutionContextBase::getKind() const
{
    Runtime::ExecutionContext *engine = requireEngine("getKind");
    return engine ? engine->get_kind() : RTC::PERIODIC;
}

ExecutionContextProfile *ExecutionContextBase::getProfile()
{
    Runtime::ExecutionContext *engine = requireEngine("getProfile");
    return engine ? engine->get_profile() : new RTC::ExecutionContextProfile;
}

void ExecutionContextBase::setObjRef(ExecutionContextService_ptr ec_ptr)
{
    m_ref = ExecutionContextService::_duplicate(ec_ptr);
}

ExecutionContextService_ptr ExecutionContextBase::getObjRef() const
{
    if (!CORBA::is_nil(m_ref))
        return ExecutionContextService::_duplicate(m_ref);
    Runtime::ExecutionContext *engine = requireEngine("getObjRef");
    return engine ? engine->_this() : ExecutionContextService::_nil();
}

const char *ExecutionContextBase::getKindString(ExecutionKind kind)
{
    static const char *const names[] = {"PERIODIC", "EVENT_DRIVEN", "OTHER"};
    return kind >= RTC::PERIODIC && kind <= RTC::OTHER ? names[kind] : "";
}

ReturnCode_t ExecutionContextBase::setKind(ExecutionKind kind)
{
    Runtime::ExecutionContext *engine = requireEngine("setKind");
    if (engine == nullptr)
        return RTC::RTC_ERROR;
    engine->setExecutionKind(kind);
    return RTC::RTC_OK;
}

ReturnCode_t ExecutionContextBase::setOwner(LightweightRTObject_ptr comp)
{
    Runtime::ExecutionContext *engine = requireEngine("setOwner");
    if (engine == nullptr)
        return RTC::RTC_ERROR;
    if (CORBA::is_nil(comp))
        return RTC::BAD_PARAMETER;
    engine->addOwner(comp, 0);
    return RTC::RTC_OK;
}

RTObject_ptr ExecutionContextBase::getOwner() const
{
    Runtime::ExecutionContext *engine = requireEngine("getOwner");
    if (engine == nullptr)
        return RTObject::_nil();
    ExecutionContextProfile_var profile = engine->get_profile();
    return RTObject::_duplicate(profile->owner);
}

const RTCList &ExecutionContextBase::getComponentList() const
{
    m_components.length(0);
    if (Runtime::ExecutionContext *engine = requireEngine("getComponentList")) {
        ExecutionContextProfile_var profile = engine->get_profile();
        m_components = profile->participants;
    }
    return m_components;
}

void ExecutionContextBase::setProperties(coil::Properties &props)
{
    m_properties << props;
}

coil::Properties ExecutionContextBase::getProperties() const
{
    coil::Properties props(m_properties);
    props.setProperty("type", m_name);
    return props;
}

bool ExecutionContextBase::isAllCurrentState(LifeCycleState state)
{
    const RTCList &list = getComponentList();
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (getComponentState(list[i]) != state)
            return false;
    }
    return true;
}

bool ExecutionContextBase::isOneOfCurrentState(LifeCycleState state)
{
    const RTCList &list = getComponentList();
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (getComponentState(list[i]) == state)
            return true;
    }
    return false;
}

void ExecutionContextBase::invokeWorker()
{
    if (Runtime::ExecutionContext *engine = requireEngine("invokeWorker"))
        engine->runCycle();
}

void ExecutionContextBase::invokeWorkerPreDo()
{
    if (!m_splitStepRefused) {
        m_splitStepRefused = true;
        RTC_ERROR(("invokeWorkerPreDo/invokeWorkerPostDo: the runtime's engine runs a cycle as one step;"
                   " invokeWorkerDo() (or invokeWorker()) runs the whole cycle"));
    }
}

void ExecutionContextBase::invokeWorkerDo()
{
    invokeWorker();
}

void ExecutionContextBase::invokeWorkerPostDo()
{
    invokeWorkerPreDo();
}

// --- ExtTrigExecutionContext's task interface ---

int ExtTrigExecutionContext::open(void *args)
{
    (void)args;
    RTC_ERROR(("ExtTrigExecutionContext::open: the runtime's engine owns the context's thread; start() starts it"));
    return -1;
}

int ExtTrigExecutionContext::svc()
{
    RTC_ERROR(("ExtTrigExecutionContext::svc: the runtime's engine runs the cycles; tick() asks for one"));
    return -1;
}

int ExtTrigExecutionContext::close(unsigned long flags)
{
    (void)flags;
    RTC_ERROR(("ExtTrigExecutionContext::close: the runtime's engine owns the context's thread; stop() stops it"));
    return -1;
}

// --- ECFactoryCXX ---

ECFactoryCXX::ECFactoryCXX(const char *name, ECNewFunc new_func, ECDeleteFunc delete_func)
    : m_name(name != nullptr ? name : "")
    , m_New(new_func)
    , m_Delete(delete_func)
{
}

ECFactoryCXX::~ECFactoryCXX() = default;

const char *ECFactoryCXX::name()
{
    return m_name.c_str();
}

ExecutionContextBase *ECFactoryCXX::create()
{
    return m_New != nullptr ? m_New() : nullptr;
}

void ECFactoryCXX::destroy(ExecutionContextBase *ec)
{
    if (m_Delete != nullptr)
        m_Delete(ec);
}

} // namespace RTC

// --- The built-in contexts ---

namespace RTC_exp {

PeriodicExecutionContext::PeriodicExecutionContext()
    : Runtime::PeriodicExecutionContext(DEFAULT_EXECUTION_RATE)
    , RTC::ExecutionContextBase("periodic_ec")
{
    setEngine(this);
}

PeriodicExecutionContext::~PeriodicExecutionContext() = default;

void PeriodicExecutionContext::init(coil::Properties &props)
{
    RTC::ExecutionContextBase::init(props);
}

RTC::ReturnCode_t PeriodicExecutionContext::start()
{
    return Runtime::PeriodicExecutionContext::start();
}

RTC::ReturnCode_t PeriodicExecutionContext::stop()
{
    return Runtime::PeriodicExecutionContext::stop();
}

MultilayerCompositeEC::MultilayerCompositeEC() = default;

MultilayerCompositeEC::~MultilayerCompositeEC()
{
    for (auto &layer : m_layers) {
        for (RTC::LightweightRTObject_ptr rtc : layer)
            CORBA::release(rtc);
    }
}

void MultilayerCompositeEC::init(coil::Properties &props)
{
    PeriodicExecutionContext::init(props);
}

int MultilayerCompositeEC::svc()
{
    RTC_ERROR(("MultilayerCompositeEC::svc: the runtime's engine runs this context's cycles in its own thread;"
               " use start() and stop()"));
    return -1;
}

RTC::ReturnCode_t MultilayerCompositeEC::bindComponent(RTC::RTObject_impl *rtc)
{
    return PeriodicExecutionContext::bindComponent(rtc);
}

RTC_impl::RTObjectStateMachine *MultilayerCompositeEC::findComponent(RTC::LightweightRTObject_ptr)
{
    RTC_ERROR(("MultilayerCompositeEC::findComponent: the participants' state machines belong to the runtime's"
               " engine; use getComponentState()"));
    return nullptr;
}

void MultilayerCompositeEC::addTask(std::vector<RTC::LightweightRTObject_ptr> rtcs)
{
    // The engine runs participants in the order they joined: a layer after the ones before it.
    std::vector<RTC::LightweightRTObject_ptr> layer;
    for (RTC::LightweightRTObject_ptr rtc : rtcs) {
        if (CORBA::is_nil(rtc))
            continue;
        if (addComponent(rtc) != RTC::RTC_OK) {
            RTC_WARN(("MultilayerCompositeEC::addTask: a member could not join the context"));
            continue;
        }
        layer.push_back(RTC::LightweightRTObject::_duplicate(rtc));
    }
    m_layers.push_back(layer);
}

} // namespace RTC_exp

namespace RTC {

using Tick = Runtime::TriggeredExecutionContext::Tick;

ExtTrigExecutionContext::ExtTrigExecutionContext()
    : Runtime::TriggeredExecutionContext("ExtTrigExecutionContext", Tick::Asynchronous, DEFAULT_EXECUTION_RATE)
    , ExecutionContextBase("exttrig_async_ec")
{
    setEngine(this);
}

ExtTrigExecutionContext::~ExtTrigExecutionContext() = default;

void ExtTrigExecutionContext::init(coil::Properties &props)
{
    ExecutionContextBase::init(props);
}

ReturnCode_t ExtTrigExecutionContext::start()
{
    return Runtime::TriggeredExecutionContext::start();
}

ReturnCode_t ExtTrigExecutionContext::stop()
{
    return Runtime::TriggeredExecutionContext::stop();
}

OpenHRPExecutionContext::OpenHRPExecutionContext()
    : OpenHRPExecutionContext("OpenHRPExecutionContext")
{
}

OpenHRPExecutionContext::OpenHRPExecutionContext(const char *typeName)
    : Runtime::TriggeredExecutionContext(typeName, Tick::Synchronous, DEFAULT_EXECUTION_RATE)
    , ExecutionContextBase("exttrig_sync_ec")
{
    setEngine(this);
}

OpenHRPExecutionContext::~OpenHRPExecutionContext() = default;

void OpenHRPExecutionContext::init(coil::Properties &props)
{
    ExecutionContextBase::init(props);
}

ReturnCode_t OpenHRPExecutionContext::start()
{
    return Runtime::TriggeredExecutionContext::start();
}

ReturnCode_t OpenHRPExecutionContext::stop()
{
    return Runtime::TriggeredExecutionContext::stop();
}

SimulatorExecutionContext::SimulatorExecutionContext()
    : OpenHRPExecutionContext("SimulatorExecutionContext")
{
}

SimulatorExecutionContext::~SimulatorExecutionContext() = default;

// The triggered engine already changes states at once in the caller's thread, between cycles.
ReturnCode_t SimulatorExecutionContext::activate_component(LightweightRTObject_ptr comp)
{
    return OpenHRPExecutionContext::activate_component(comp);
}

ReturnCode_t SimulatorExecutionContext::deactivate_component(LightweightRTObject_ptr comp)
{
    return OpenHRPExecutionContext::deactivate_component(comp);
}

ReturnCode_t SimulatorExecutionContext::reset_component(LightweightRTObject_ptr comp)
{
    return OpenHRPExecutionContext::reset_component(comp);
}

} // namespace RTC

namespace {

template <class Context>
void registerType(RTC::Manager *manager, const char *name)
{
    if (manager != nullptr)
        manager->registerECFactory(name, RTC::ECCreate<Context>, RTC::ECDelete<Context>);
    else
        RTC::ExecutionContextFactory::instance().addFactory(name, coil::Creator<RTC::ExecutionContextBase, Context>,
                                                            coil::Destructor<RTC::ExecutionContextBase, Context>);
}

} // namespace

extern "C" {

void PeriodicExecutionContextInit(RTC::Manager *manager)
{
    registerType<RTC_exp::PeriodicExecutionContext>(manager, "PeriodicExecutionContext");
}

void MultilayerCompositeECInit(RTC::Manager *manager)
{
    registerType<RTC_exp::MultilayerCompositeEC>(manager, "MultilayerCompositeEC");
}

void ExtTrigExecutionContextInit(RTC::Manager *manager)
{
    registerType<RTC::ExtTrigExecutionContext>(manager, "ExtTrigExecutionContext");
}

void OpenHRPExecutionContextInit(RTC::Manager *manager)
{
    registerType<RTC::OpenHRPExecutionContext>(manager, "OpenHRPExecutionContext");
}

void SimulatorExecutionContextInit(RTC::Manager *manager)
{
    registerType<RTC::SimulatorExecutionContext>(manager, "SimulatorExecutionContext");
}
}
