// SPDX-License-Identifier: MIT
// The base of OpenRTM-aist's execution contexts: the calls an EC offers its owner and drivers.
#ifndef RTC_EXECUTIONCONTEXTBASE_H
#define RTC_EXECUTIONCONTEXTBASE_H

#include <rtm/idl/RTCSkel.h>
#include <rtm/idl/OpenRTMSkel.h>
#include <rtm/Factory.h>
#include <rtm/SystemLogger.h>

#include <coil/Factory.h>
#include <coil/Properties.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#define DEFAULT_EXECUTION_RATE 1000

namespace Runtime
{
class ExecutionContext;
}

namespace RTC
{
/**
 * What every execution context offers besides its CORBA interface: binding its owner, start /
 * stop, rate, adding components and changing their states from C++. The built-in contexts
 * (PeriodicExecutionContext, ExtTrigExecutionContext, OpenHRPExecutionContext,
 * SimulatorExecutionContext) run on the runtime's engine; a class that derives from this one
 * alone has no engine, and each call on it logs that and fails (RTC_ERROR).
 */
class ExecutionContextBase
{
public:
    explicit ExecutionContextBase(const char *name);
    virtual ~ExecutionContextBase();

    /// Reads `exec_cxt.periodic.rate` and `exec_cxt.transition_timeout` from @p props.
    virtual void init(coil::Properties &props);
    /// Makes @p rtc the owner: the context becomes the component's own (handle 0 for the first).
    virtual RTC::ReturnCode_t bindComponent(RTC::RTObject_impl *rtc);

    CORBA::Boolean isRunning();
    RTC::ReturnCode_t start();
    virtual RTC::ReturnCode_t stop();
    double getRate() const;
    std::chrono::nanoseconds getPeriod() const;
    RTC::ReturnCode_t setRate(double rate);
    RTC::ReturnCode_t addComponent(RTC::LightweightRTObject_ptr comp);
    RTC::ReturnCode_t removeComponent(RTC::LightweightRTObject_ptr comp);
    RTC::ReturnCode_t activateComponent(RTC::LightweightRTObject_ptr comp);
    RTC::ReturnCode_t deactivateComponent(RTC::LightweightRTObject_ptr comp);
    RTC::ReturnCode_t resetComponent(RTC::LightweightRTObject_ptr comp);
    RTC::LifeCycleState getComponentState(RTC::LightweightRTObject_ptr comp);
    static const char *getStateString(RTC::LifeCycleState state);
    RTC::ExecutionKind getKind() const;
    /// A copy of the profile (the caller owns it).
    RTC::ExecutionContextProfile *getProfile();
    /// Records @p ec_ptr as the context's reference (the built-in contexts know their own).
    void setObjRef(RTC::ExecutionContextService_ptr ec_ptr);
    RTC::ExecutionContextService_ptr getObjRef() const;
    static const char *getKindString(RTC::ExecutionKind kind);
    RTC::ReturnCode_t setKind(RTC::ExecutionKind kind);
    RTC::ReturnCode_t setOwner(RTC::LightweightRTObject_ptr comp);
    RTC::RTObject_ptr getOwner() const;
    /// The participants, owner included.
    const RTC::RTCList &getComponentList() const;
    void setProperties(coil::Properties &props);
    coil::Properties getProperties() const;

    bool isAllCurrentState(RTC::LifeCycleState state);
    bool isOneOfCurrentState(RTC::LifeCycleState state);
    /// Next states equal the current ones here: a state change is over when its call returns.
    bool isAllNextState(RTC::LifeCycleState state) { return isAllCurrentState(state); }
    bool isOneOfNextState(RTC::LifeCycleState state) { return isOneOfCurrentState(state); }
    /// One execution cycle now, in the caller's thread.
    void invokeWorker();
    /**
     * The three steps of a cycle, for a context that runs them apart: the pending state changes
     * (pre-do), the active components' onExecute (do), their onStateUpdate (post-do). The
     * runtime's engines run a cycle as one step: invokeWorkerDo() runs the whole cycle, the
     * other two are refused (logged once per context) so that a cycle never runs twice.
     */
    void invokeWorkerPreDo();
    void invokeWorkerDo();
    void invokeWorkerPostDo();

    /// RT Studio: the runtime engine underneath; null for a context without one.
    ::Runtime::ExecutionContext *engine() const { return m_engine; }

protected:
    /// The built-in contexts hand over the engine they are (themselves).
    void setEngine(::Runtime::ExecutionContext *engine) { m_engine = engine; }

    mutable RTC::Logger rtclog;

private:
    ::Runtime::ExecutionContext *requireEngine(const char *call) const;

    ::Runtime::ExecutionContext *m_engine;
    std::string m_name;
    coil::Properties m_properties;
    RTC::ExecutionContextService_var m_ref;
    mutable RTC::RTCList m_components;
    bool m_splitStepRefused = false;
};

/**
 * The process's execution context types by name (`exec_cxt.periodic.type`). The manager picks a
 * component's context from the runtime's own types and from the ones registered here; a type
 * registered here must derive from one of the built-in contexts (their engine runs it).
 */
using ExecutionContextFactory = coil::GlobalFactory<ExecutionContextBase>;
} // namespace RTC

#endif // RTC_EXECUTIONCONTEXTBASE_H
