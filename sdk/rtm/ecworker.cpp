// SPDX-License-Identifier: MIT
// RTC_impl::RTObjectStateMachine and ExecutionContextWorker (OpenRTM's own engine classes, for
// code that builds contexts from them), and the periodic task factory.
#include <rtm/DefaultPeriodicTask.h>
#include <rtm/ExecutionContextWorker.h>
#include <rtm/PeriodicTaskFactory.h>
#include <rtm/RTObject.h>
#include <rtm/RTObjectStateMachine.h>

#include <coil/PeriodicTask.h>
#include <coil/stringutil.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <mutex>

namespace RTC_impl {

// --- RTObjectStateMachine ---

RTObjectStateMachine::RTObjectStateMachine(RTC::ExecutionContextHandle_t id, RTC::LightweightRTObject_ptr comp)
    : rtclog("rtobject_state_machine")
    , m_id(id)
    , m_rtobj(RTC::LightweightRTObject::_duplicate(comp))
    , m_sm(NUM_OF_LIFECYCLESTATE)
    , m_ca(false)
    , m_dfc(false)
    , m_fsm(false)
    , m_mode(false)
    // Calls go through the reference: omniORB calls a servant of this process directly anyway.
    , m_rtobjPtr(nullptr)
    , m_measure(false)
    , m_activation(false)
    , m_deactivation(false)
    , m_reset(false)
{
    setComponentAction(comp);
    setDataFlowComponentAction(comp);
    setFsmParticipantAction(comp);
    setMultiModeComponentAction(comp);
    m_sm.setListener(this);
    m_sm.setEntryAction(RTC::ACTIVE_STATE, &RTObjectStateMachine::onActivated);
    m_sm.setDoAction(RTC::ACTIVE_STATE, &RTObjectStateMachine::onExecute);
    m_sm.setPostDoAction(RTC::ACTIVE_STATE, &RTObjectStateMachine::onStateUpdate);
    m_sm.setExitAction(RTC::ACTIVE_STATE, &RTObjectStateMachine::onDeactivated);
    m_sm.setEntryAction(RTC::ERROR_STATE, &RTObjectStateMachine::onAborting);
    m_sm.setDoAction(RTC::ERROR_STATE, &RTObjectStateMachine::onError);
    m_sm.setExitAction(RTC::ERROR_STATE, &RTObjectStateMachine::onReset);
    ExecContextStates start;
    start.curr = start.prev = start.next = RTC::INACTIVE_STATE;
    m_sm.setStartState(start);
}

RTObjectStateMachine::~RTObjectStateMachine() = default;

void RTObjectStateMachine::setComponentAction(RTC::LightweightRTObject_ptr comp)
{
    m_caVar = RTC::ComponentAction::_narrow(comp);
    m_ca = !CORBA::is_nil(m_caVar);
}

void RTObjectStateMachine::setDataFlowComponentAction(RTC::LightweightRTObject_ptr comp)
{
    m_dfcVar = RTC::DataFlowComponentAction::_narrow(comp);
    m_dfc = !CORBA::is_nil(m_dfcVar);
}

void RTObjectStateMachine::setFsmParticipantAction(RTC::LightweightRTObject_ptr comp)
{
    m_fsmVar = RTC::FsmParticipantAction::_narrow(comp);
    m_fsm = !CORBA::is_nil(m_fsmVar);
}

void RTObjectStateMachine::setMultiModeComponentAction(RTC::LightweightRTObject_ptr comp)
{
    m_modeVar = RTC::MultiModeComponentAction::_narrow(comp);
    m_mode = !CORBA::is_nil(m_modeVar);
}

RTC::LightweightRTObject_ptr RTObjectStateMachine::getRTObject()
{
    return RTC::LightweightRTObject::_duplicate(m_rtobj);
}

bool RTObjectStateMachine::isEquivalent(RTC::LightweightRTObject_ptr comp)
{
    try {
        return !CORBA::is_nil(comp) && m_rtobj->_is_equivalent(comp);
    } catch (const CORBA::Exception &) {
        return false;
    }
}

RTC::ExecutionContextHandle_t RTObjectStateMachine::getExecutionContextHandle()
{
    return m_id;
}

template <typename Call>
void RTObjectStateMachine::guarded(Call call)
{
    try {
        if (call() != RTC::RTC_OK)
            m_sm.goTo(RTC::ERROR_STATE);
    } catch (const CORBA::Exception &e) {
        RTC_ERROR(("component call failed: %s", e._name()));
        m_sm.goTo(RTC::ERROR_STATE);
    }
}

void RTObjectStateMachine::onStartup()
{
    if (!m_ca)
        return;
    try {
        m_caVar->on_startup(m_id);
    } catch (const CORBA::Exception &) {
        // A component that is gone has nothing to start.
    }
}

void RTObjectStateMachine::onShutdown()
{
    if (!m_ca)
        return;
    try {
        m_caVar->on_shutdown(m_id);
    } catch (const CORBA::Exception &) {
    }
}

void RTObjectStateMachine::onActivated(const ExecContextStates &)
{
    if (m_ca)
        guarded([this] { return m_caVar->on_activated(m_id); });
}

void RTObjectStateMachine::onDeactivated(const ExecContextStates &)
{
    if (!m_ca)
        return;
    try {
        m_caVar->on_deactivated(m_id);
    } catch (const CORBA::Exception &) {
    }
}

void RTObjectStateMachine::onAborting(const ExecContextStates &)
{
    if (!m_ca)
        return;
    try {
        m_caVar->on_aborting(m_id);
    } catch (const CORBA::Exception &) {
    }
}

void RTObjectStateMachine::onError(const ExecContextStates &)
{
    if (!m_ca)
        return;
    try {
        m_caVar->on_error(m_id);
    } catch (const CORBA::Exception &) {
    }
}

void RTObjectStateMachine::onReset(const ExecContextStates &)
{
    // Leaving ERROR: a reset that fails keeps the component there.
    if (m_ca)
        guarded([this] { return m_caVar->on_reset(m_id); });
}

void RTObjectStateMachine::onExecute(const ExecContextStates &)
{
    if (m_dfc)
        guarded([this] { return m_dfcVar->on_execute(m_id); });
}

void RTObjectStateMachine::onStateUpdate(const ExecContextStates &)
{
    if (m_dfc)
        guarded([this] { return m_dfcVar->on_state_update(m_id); });
}

RTC::ReturnCode_t RTObjectStateMachine::onRateChanged()
{
    if (!m_dfc)
        return RTC::RTC_OK;
    try {
        const RTC::ReturnCode_t result = m_dfcVar->on_rate_changed(m_id);
        if (result != RTC::RTC_OK)
            m_sm.goTo(RTC::ERROR_STATE);
        return result;
    } catch (const CORBA::Exception &) {
        m_sm.goTo(RTC::ERROR_STATE);
        return RTC::RTC_ERROR;
    }
}

void RTObjectStateMachine::onAction(const ExecContextStates &)
{
    if (m_fsm)
        guarded([this] { return m_fsmVar->on_action(m_id); });
}

void RTObjectStateMachine::onModeChanged(const ExecContextStates &)
{
    if (m_mode)
        guarded([this] { return m_modeVar->on_mode_changed(m_id); });
}

ExecContextState RTObjectStateMachine::getState()
{
    return m_sm.getState();
}

ExecContextStates RTObjectStateMachine::getStates()
{
    return m_sm.getStates();
}

bool RTObjectStateMachine::isCurrentState(ExecContextState state)
{
    return getState() == state;
}

bool RTObjectStateMachine::isNextState(ExecContextState state)
{
    return m_sm.getStates().next == state;
}

void RTObjectStateMachine::goTo(ExecContextState state)
{
    m_sm.goTo(state);
}

void RTObjectStateMachine::workerPreDo()
{
    m_sm.worker_pre();
}

void RTObjectStateMachine::workerDo()
{
    m_sm.worker_do();
}

void RTObjectStateMachine::workerPostDo()
{
    m_sm.worker_post();
    updateState();
}

namespace {

bool askFor(RTC_Utils::StateHolder<ExecContextState> states, ExecContextState from)
{
    return states.curr == from && states.next == from;
}

} // namespace

bool RTObjectStateMachine::activate()
{
    if (!askFor(m_sm.getStates(), RTC::INACTIVE_STATE))
        return false;
    m_activation = true;
    m_sm.goTo(RTC::ACTIVE_STATE);
    return true;
}

bool RTObjectStateMachine::deactivate()
{
    if (!askFor(m_sm.getStates(), RTC::ACTIVE_STATE))
        return false;
    m_deactivation = true;
    m_sm.goTo(RTC::INACTIVE_STATE);
    return true;
}

bool RTObjectStateMachine::reset()
{
    if (!askFor(m_sm.getStates(), RTC::ERROR_STATE))
        return false;
    m_reset = true;
    m_sm.goTo(RTC::INACTIVE_STATE);
    return true;
}

void RTObjectStateMachine::updateState()
{
    // A request is over once the machine has settled.
    const ExecContextStates states = m_sm.getStates();
    if (states.curr == states.next) {
        m_activation = false;
        m_deactivation = false;
        m_reset = false;
    }
}

// --- ExecutionContextWorker ---

ExecutionContextWorker::ExecutionContextWorker() = default;

ExecutionContextWorker::~ExecutionContextWorker()
{
    updateComponentList();
    for (RTObjectStateMachine *comp : m_comps)
        delete comp;
    m_comps.clear();
}

void ExecutionContextWorker::setECRef(RTC::ExecutionContextService_ptr ref)
{
    m_ref = RTC::ExecutionContextService::_duplicate(ref);
}

RTC::ExecutionContextService_ptr ExecutionContextWorker::getECRef()
{
    return RTC::ExecutionContextService::_duplicate(m_ref);
}

CORBA::Boolean ExecutionContextWorker::isRunning()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_running;
}

std::vector<RTObjectStateMachine *> ExecutionContextWorker::participants()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_comps;
}

RTC::ReturnCode_t ExecutionContextWorker::start()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_running)
            return RTC::PRECONDITION_NOT_MET;
    }
    updateComponentList();
    for (RTObjectStateMachine *comp : participants())
        comp->onStartup();
    std::lock_guard<std::mutex> lock(m_mutex);
    m_running = true;
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContextWorker::stop()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (!m_running)
            return RTC::PRECONDITION_NOT_MET;
        m_running = false;
    }
    for (RTObjectStateMachine *comp : participants())
        comp->onShutdown();
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContextWorker::startThread()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_running = true;
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContextWorker::stopThread()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_running = false;
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContextWorker::rateChanged()
{
    RTC::ReturnCode_t result = RTC::RTC_OK;
    for (RTObjectStateMachine *comp : participants()) {
        if (comp->onRateChanged() != RTC::RTC_OK)
            result = RTC::RTC_ERROR;
    }
    return result;
}

RTC::ReturnCode_t ExecutionContextWorker::activateComponent(RTC::LightweightRTObject_ptr comp,
                                                            RTObjectStateMachine *&rtobj)
{
    rtobj = findComponent(comp);
    if (rtobj == nullptr)
        return RTC::BAD_PARAMETER;
    return rtobj->activate() ? RTC::RTC_OK : RTC::PRECONDITION_NOT_MET;
}

RTC::ReturnCode_t ExecutionContextWorker::deactivateComponent(RTC::LightweightRTObject_ptr comp,
                                                              RTObjectStateMachine *&rtobj)
{
    rtobj = findComponent(comp);
    if (rtobj == nullptr)
        return RTC::BAD_PARAMETER;
    return rtobj->deactivate() ? RTC::RTC_OK : RTC::PRECONDITION_NOT_MET;
}

RTC::ReturnCode_t ExecutionContextWorker::resetComponent(RTC::LightweightRTObject_ptr comp,
                                                         RTObjectStateMachine *&rtobj)
{
    rtobj = findComponent(comp);
    if (rtobj == nullptr)
        return RTC::BAD_PARAMETER;
    return rtobj->reset() ? RTC::RTC_OK : RTC::PRECONDITION_NOT_MET;
}

RTC::ReturnCode_t ExecutionContextWorker::waitFor(RTObjectStateMachine *rtobj, RTC::LifeCycleState state,
                                                  std::chrono::nanoseconds timeout, long int cycle)
{
    if (rtobj == nullptr)
        return RTC::BAD_PARAMETER;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (long int i = 0; i < std::max(cycle, 1L); ++i) {
        if (rtobj->isCurrentState(state))
            return RTC::RTC_OK;
        if (!rtobj->isNextState(state) || std::chrono::steady_clock::now() > deadline)
            return RTC::RTC_ERROR;
        std::lock_guard<std::recursive_mutex> step(m_stepMutex);
        rtobj->workerPreDo();
    }
    return rtobj->isCurrentState(state) ? RTC::RTC_OK : RTC::RTC_ERROR;
}

RTC::ReturnCode_t ExecutionContextWorker::waitActivateComplete(RTObjectStateMachine *&rtobj,
                                                               std::chrono::nanoseconds timeout, long int cycle)
{
    return waitFor(rtobj, RTC::ACTIVE_STATE, timeout, cycle);
}

RTC::ReturnCode_t ExecutionContextWorker::waitDeactivateComplete(RTObjectStateMachine *&rtobj,
                                                                 std::chrono::nanoseconds timeout, long int cycle)
{
    return waitFor(rtobj, RTC::INACTIVE_STATE, timeout, cycle);
}

RTC::ReturnCode_t ExecutionContextWorker::waitResetComplete(RTObjectStateMachine *&rtobj,
                                                            std::chrono::nanoseconds timeout, long int cycle)
{
    return waitFor(rtobj, RTC::INACTIVE_STATE, timeout, cycle);
}

RTC::LifeCycleState ExecutionContextWorker::getComponentState(RTC::LightweightRTObject_ptr comp)
{
    RTObjectStateMachine *rtobj = findComponent(comp);
    return rtobj != nullptr ? rtobj->getState() : RTC::CREATED_STATE;
}

RTC::ReturnCode_t ExecutionContextWorker::addComponent(RTC::LightweightRTObject_ptr comp)
{
    if (CORBA::is_nil(comp))
        return RTC::BAD_PARAMETER;
    if (findComponent(comp) != nullptr)
        return RTC::PRECONDITION_NOT_MET;
    RTC::ExecutionContextHandle_t handle = 0;
    try {
        handle = comp->attach_context(m_ref);
    } catch (const CORBA::Exception &) {
        return RTC::BAD_PARAMETER;
    }
    if (handle < 0)
        return RTC::RTC_ERROR;
    std::lock_guard<std::mutex> lock(m_addedMutex);
    m_addedComps.push_back(new RTObjectStateMachine(handle, comp));
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContextWorker::bindComponent(RTC::RTObject_impl *rtc)
{
    if (rtc == nullptr)
        return RTC::BAD_PARAMETER;
    RTC::RTObject_var ref = rtc->getObjRef();
    return addComponent(ref);
}

RTC::ReturnCode_t ExecutionContextWorker::removeComponent(RTC::LightweightRTObject_ptr comp)
{
    RTObjectStateMachine *rtobj = findComponent(comp);
    if (rtobj == nullptr)
        return RTC::BAD_PARAMETER;
    try {
        comp->detach_context(rtobj->getExecutionContextHandle());
    } catch (const CORBA::Exception &) {
        // A component that is gone is removed all the same.
    }
    std::lock_guard<std::mutex> lock(m_removedMutex);
    m_removedComps.push_back(rtobj);
    return RTC::RTC_OK;
}

RTObjectStateMachine *ExecutionContextWorker::findComponent(RTC::LightweightRTObject_ptr comp)
{
    {
        std::lock_guard<std::mutex> lock(m_removedMutex);
        for (RTObjectStateMachine *removed : m_removedComps) {
            if (removed->isEquivalent(comp))
                return nullptr;
        }
    }
    for (RTObjectStateMachine *rtobj : participants()) {
        if (rtobj->isEquivalent(comp))
            return rtobj;
    }
    std::lock_guard<std::mutex> lock(m_addedMutex);
    for (RTObjectStateMachine *rtobj : m_addedComps) {
        if (rtobj->isEquivalent(comp))
            return rtobj;
    }
    return nullptr;
}

bool ExecutionContextWorker::isAllCurrentState(RTC::LifeCycleState state)
{
    for (RTObjectStateMachine *comp : participants()) {
        if (!comp->isCurrentState(state))
            return false;
    }
    return true;
}

bool ExecutionContextWorker::isAllNextState(RTC::LifeCycleState state)
{
    for (RTObjectStateMachine *comp : participants()) {
        if (!comp->isNextState(state))
            return false;
    }
    return true;
}

bool ExecutionContextWorker::isOneOfCurrentState(RTC::LifeCycleState state)
{
    for (RTObjectStateMachine *comp : participants()) {
        if (comp->isCurrentState(state))
            return true;
    }
    return false;
}

bool ExecutionContextWorker::isOneOfNextState(RTC::LifeCycleState state)
{
    for (RTObjectStateMachine *comp : participants()) {
        if (comp->isNextState(state))
            return true;
    }
    return false;
}

void ExecutionContextWorker::invokeWorker()
{
    updateComponentList();
    std::lock_guard<std::recursive_mutex> step(m_stepMutex);
    invokeWorkerPreDo();
    invokeWorkerDo();
    invokeWorkerPostDo();
}

void ExecutionContextWorker::invokeWorkerPreDo()
{
    std::lock_guard<std::recursive_mutex> step(m_stepMutex);
    for (RTObjectStateMachine *comp : participants())
        comp->workerPreDo();
}

void ExecutionContextWorker::invokeWorkerDo()
{
    std::lock_guard<std::recursive_mutex> step(m_stepMutex);
    for (RTObjectStateMachine *comp : participants())
        comp->workerDo();
}

void ExecutionContextWorker::invokeWorkerPostDo()
{
    std::lock_guard<std::recursive_mutex> step(m_stepMutex);
    for (RTObjectStateMachine *comp : participants())
        comp->workerPostDo();
}

void ExecutionContextWorker::updateComponentList()
{
    std::vector<RTObjectStateMachine *> added;
    std::vector<RTObjectStateMachine *> removed;
    {
        std::lock_guard<std::mutex> lock(m_addedMutex);
        added.swap(m_addedComps);
    }
    {
        std::lock_guard<std::mutex> lock(m_removedMutex);
        removed.swap(m_removedComps);
    }
    // Not while a cycle walks the list: removed machines are deleted here.
    std::lock_guard<std::recursive_mutex> step(m_stepMutex);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_comps.insert(m_comps.end(), added.begin(), added.end());
        for (RTObjectStateMachine *comp : removed)
            m_comps.erase(std::remove(m_comps.begin(), m_comps.end(), comp), m_comps.end());
    }
    for (RTObjectStateMachine *comp : removed)
        delete comp;
}

} // namespace RTC_impl

extern "C" void DefaultPeriodicTaskInit()
{
    RTC::PeriodicTaskFactory::instance().addFactory("default",
                                                    coil::Creator<coil::PeriodicTaskBase, RTC::DefaultPeriodicTask>,
                                                    coil::Destructor<coil::PeriodicTaskBase, RTC::DefaultPeriodicTask>);
}
