// SPDX-License-Identifier: MIT
// One component's life cycle in one execution context, as a state machine.
#ifndef RTC_IMPL_RTOBJECTSTATEMACHINE_H
#define RTC_IMPL_RTOBJECTSTATEMACHINE_H

#include <cstdlib>
#include <rtm/SystemLogger.h>
#include <coil/TimeMeasure.h>
#include <rtm/idl/RTCSkel.h>
#include <rtm/StateMachine.h>
#include <cassert>
#include <iostream>
#include <atomic>

#define NUM_OF_LIFECYCLESTATE 4

namespace RTC
{
class RTObject_impl;
} // namespace RTC

namespace RTC_impl
{
using Ecid = RTC::ExecutionContextHandle_t;
using ExecContextState = RTC::LifeCycleState;
using ExecContextStates = RTC_Utils::StateHolder<ExecContextState>;

/**
 * A participant of an execution context: its OMG life cycle (INACTIVE, ACTIVE, ERROR) and the
 * callbacks each step makes on it — on_activated entering ACTIVE, on_execute and
 * on_state_update while ACTIVE, on_deactivated leaving it, on_aborting entering ERROR, on_error
 * while in it and on_reset leaving it. A callback that fails (or a component that does not
 * answer) sends it to ERROR. A component in this process is called directly, others through
 * their references.
 */
class RTObjectStateMachine
{
public:
    RTObjectStateMachine(RTC::ExecutionContextHandle_t id, RTC::LightweightRTObject_ptr comp);
    RTObjectStateMachine(RTObjectStateMachine const &) = delete;
    virtual ~RTObjectStateMachine();
    RTObjectStateMachine &operator=(RTObjectStateMachine const &) = delete;

    RTC::LightweightRTObject_ptr getRTObject();
    bool isEquivalent(RTC::LightweightRTObject_ptr comp);
    RTC::ExecutionContextHandle_t getExecutionContextHandle();

    // The component's callbacks, as the state machine's actions.
    void onStartup();
    void onShutdown();
    void onActivated(const ExecContextStates &st);
    void onDeactivated(const ExecContextStates &st);
    void onAborting(const ExecContextStates &st);
    void onError(const ExecContextStates &st);
    void onReset(const ExecContextStates &st);
    void onExecute(const ExecContextStates &st);
    void onStateUpdate(const ExecContextStates &st);
    RTC::ReturnCode_t onRateChanged();
    void onAction(const ExecContextStates &st);
    void onModeChanged(const ExecContextStates &st);

    ExecContextState getState();
    ExecContextStates getStates();
    bool isCurrentState(ExecContextState state);
    bool isNextState(ExecContextState state);
    void goTo(ExecContextState state);

    /// The transition asked for (or the pre-do step); the do step; the post-do step.
    void workerPreDo();
    void workerDo();
    void workerPostDo();

    /// Asks for ACTIVE (from INACTIVE); false from any other state.
    bool activate();
    /// Asks for INACTIVE (from ACTIVE); false from any other state.
    bool deactivate();
    /// Asks for INACTIVE (from ERROR); false from any other state.
    bool reset();

protected:
    void setComponentAction(RTC::LightweightRTObject_ptr comp);
    void setDataFlowComponentAction(RTC::LightweightRTObject_ptr comp);
    void setFsmParticipantAction(RTC::LightweightRTObject_ptr comp);
    void setMultiModeComponentAction(RTC::LightweightRTObject_ptr comp);
    void updateState();

private:
    /// Runs @p call; a failure or an exception sends the component to ERROR.
    template <typename Call>
    void guarded(Call call);

    RTC::Logger rtclog;
    RTC::ExecutionContextHandle_t m_id;
    RTC::LightweightRTObject_var m_rtobj;
    RTC_Utils::StateMachine<ExecContextState, RTObjectStateMachine> m_sm;
    bool m_ca;
    bool m_dfc;
    bool m_fsm;
    bool m_mode;
    RTC::ComponentAction_var m_caVar;
    RTC::DataFlowComponentAction_var m_dfcVar;
    RTC::FsmParticipantAction_var m_fsmVar;
    RTC::MultiModeComponentAction_var m_modeVar;
    RTC::RTObject_impl *m_rtobjPtr;
    bool m_measure;
    coil::TimeMeasure m_svtMeasure;
    coil::TimeMeasure m_refMeasure;
    std::atomic<bool> m_activation;
    std::atomic<bool> m_deactivation;
    std::atomic<bool> m_reset;
};
} // namespace RTC_impl

#endif // RTC_IMPL_RTOBJECTSTATEMACHINE_H
