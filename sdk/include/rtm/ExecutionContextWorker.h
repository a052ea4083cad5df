// SPDX-License-Identifier: MIT
// The participants of an execution context and one cycle over them.
#ifndef RTC_EXECUTIONCONTEXTWORKER_H
#define RTC_EXECUTIONCONTEXTWORKER_H

#include <condition_variable>
#include <rtm/idl/RTCSkel.h>
#include <rtm/SystemLogger.h>
#include <vector>

#include <chrono>
#include <mutex>

#define NUM_OF_LIFECYCLESTATE 4

namespace RTC
{
class RTObject_impl;
} // namespace RTC

namespace RTC_impl
{
class RTObjectStateMachine;
using LightweightRTObject_ptr = RTC::LightweightRTObject_ptr;
using LightweightRTObject_var = RTC::LightweightRTObject_var;

/**
 * The participants of an execution context, each an RTObjectStateMachine, and one cycle over
 * them (invokeWorker()): first every pending transition or pre-do step, then every do step, then
 * every post-do step. Components added or removed take part from the next cycle on. A context
 * with a thread of its own calls invokeWorker() per period; the wait…Complete() calls carry out
 * the one participant's pending transition themselves, so they return at once whether a thread
 * cycles or not. bindComponent() attaches the owner like any participant (attach_context).
 */
class ExecutionContextWorker
{
public:
    ExecutionContextWorker();
    virtual ~ExecutionContextWorker();

    void setECRef(RTC::ExecutionContextService_ptr ref);
    RTC::ExecutionContextService_ptr getECRef();
    CORBA::Boolean isRunning();
    /// Starts: on_startup on every participant (PRECONDITION_NOT_MET when running).
    RTC::ReturnCode_t start();
    /// Stops: on_shutdown on every participant (PRECONDITION_NOT_MET when stopped).
    RTC::ReturnCode_t stop();
    RTC::ReturnCode_t startThread();
    RTC::ReturnCode_t stopThread();
    /// on_rate_changed on every participant.
    RTC::ReturnCode_t rateChanged();
    /// Asks for ACTIVE; @p rtobj is the participant's state machine (BAD_PARAMETER when
    /// @p comp does not take part, PRECONDITION_NOT_MET when it is not INACTIVE).
    RTC::ReturnCode_t activateComponent(RTC::LightweightRTObject_ptr comp, RTObjectStateMachine *&rtobj);
    /// Runs cycles until @p rtobj is ACTIVE or @p timeout passes (RTC_ERROR then).
    RTC::ReturnCode_t waitActivateComplete(RTObjectStateMachine *&rtobj,
                                           std::chrono::nanoseconds timeout = std::chrono::seconds(1),
                                           long int cycle = 1000);
    RTC::ReturnCode_t deactivateComponent(RTC::LightweightRTObject_ptr comp, RTObjectStateMachine *&rtobj);
    RTC::ReturnCode_t waitDeactivateComplete(RTObjectStateMachine *&rtobj,
                                             std::chrono::nanoseconds timeout = std::chrono::seconds(1),
                                             long int cycle = 1000);
    RTC::ReturnCode_t resetComponent(RTC::LightweightRTObject_ptr comp, RTObjectStateMachine *&rtobj);
    RTC::ReturnCode_t waitResetComplete(RTObjectStateMachine *&rtobj,
                                        std::chrono::nanoseconds timeout = std::chrono::seconds(1),
                                        long int cycle = 1000);
    RTC::LifeCycleState getComponentState(RTC::LightweightRTObject_ptr comp);
    static const char *getStateString(RTC::LifeCycleState state)
    {
        static const char *const names[] = {"CREATED_STATE", "INACTIVE_STATE", "ACTIVE_STATE", "ERROR_STATE"};
        return state >= RTC::CREATED_STATE && state <= RTC::ERROR_STATE ? names[state] : "";
    }
    /// Adds @p comp (attach_context gives its handle); it takes part from the next cycle.
    RTC::ReturnCode_t addComponent(RTC::LightweightRTObject_ptr comp);
    /// Adds the owner @p rtc with its handle for the context.
    RTC::ReturnCode_t bindComponent(RTC::RTObject_impl *rtc);
    RTC::ReturnCode_t removeComponent(RTC::LightweightRTObject_ptr comp);
    RTObjectStateMachine *findComponent(RTC::LightweightRTObject_ptr comp);
    bool isAllCurrentState(RTC::LifeCycleState state);
    bool isAllNextState(RTC::LifeCycleState state);
    bool isOneOfCurrentState(RTC::LifeCycleState state);
    bool isOneOfNextState(RTC::LifeCycleState state);
    /// One cycle: pre-do steps, do steps, post-do steps.
    void invokeWorker();
    void invokeWorkerPreDo();
    void invokeWorkerDo();
    void invokeWorkerPostDo();
    /// Takes in the components added and drops those removed since the last cycle.
    void updateComponentList();

protected:
    RTC::Logger rtclog{"ec_worker"};
    RTC::ExecutionContextService_var m_ref;
    bool m_running{false};
    std::vector<RTC_impl::RTObjectStateMachine *> m_comps;
    mutable std::mutex m_mutex;
    std::vector<RTC_impl::RTObjectStateMachine *> m_addedComps;
    mutable std::mutex m_addedMutex;
    std::vector<RTC_impl::RTObjectStateMachine *> m_removedComps;
    mutable std::mutex m_removedMutex;
    using CompItr = std::vector<RTC_impl::RTObjectStateMachine *>::iterator;

private:
    /// One step at a time over the participants; recursive, as a callback may change states.
    std::recursive_mutex m_stepMutex;
    RTC::ReturnCode_t waitFor(RTObjectStateMachine *rtobj, RTC::LifeCycleState state,
                              std::chrono::nanoseconds timeout, long int cycle);
    std::vector<RTObjectStateMachine *> participants();
};
} // namespace RTC_impl

#endif // RTC_EXECUTIONCONTEXTWORKER_H
