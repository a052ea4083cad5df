// SPDX-License-Identifier: MIT
// Static finite-state-machine components: a Macho state machine (rtm/Macho.h) whose states report
// their actions to the component (RTObject_impl::preOnFsmEntry() and the other FSM hooks, which
// call the FSM action listeners) and whose events come from EventInPorts (rtm/EventPort.h).
//
//   FSM_TOPSTATE(Top) { struct Box { ... }; FSM_STATE(Top); virtual void open() {} ... };
//   FSM_SUBSTATE(Closed, Top) { FSM_STATE(Closed); void open() override { setState<Opened>(); } };
//   FSM_INIT_VALUE(Top) FSM_INIT_VALUE(Closed) ...     (once, in a source file)
//   RTC::Machine<Top> m_fsm;  // constructed with the component: m_fsm(this)
#ifndef RTM_STATICFSM_H
#define RTM_STATICFSM_H

#include <rtm/EventBase.h>
#include <rtm/Macho.h>
#include <rtm/RTObject.h>
#include <rtm/RingBuffer.h>

/// Declares the top state @p TOP of an FSM component's machine.
#define FSM_TOPSTATE(TOP) struct TOP : public ::RTC::Link<TOP, ::Macho::TopBase<TOP> >
/// Declares state @p STATE inside @p SUPERSTATE.
#define FSM_SUBSTATE(STATE, SUPERSTATE) struct STATE : public ::RTC::Link<STATE, SUPERSTATE>
/// The members every FSM state class has; the first thing in an FSM_TOPSTATE / FSM_SUBSTATE body.
#define FSM_STATE(S) MACHO_STATE_MEMBERS_(S, ::RTC::Link)
/// Gives state @p S its identifier; once per state, at namespace scope in one source file.
#define FSM_INIT_VALUE(S)                                                                                      \
    template <>                                                                                                \
    const ::Macho::ID Macho::StateID<S>::value = ::Macho::Machine<S::TOP>::theStateCount++;

namespace RTC
{
template <class C, class P>
class Link;

/**
 * The state machine of an FSM component, of top state @p TOP. EventInPorts queue the events
 * they receive in getBuffer(); run_event() (called from onExecute) dispatches them in order.
 * The states report their entry, init and exit actions to the component @p comp from the
 * first transition after construction on.
 */
template <class TOP>
class Machine : public Macho::Machine<TOP>
{
public:
    explicit Machine(RTObject_impl *comp)
        : Macho::Machine<TOP>()
        , rtComponent(comp)
    {
        if (rtComponent != nullptr)
            rtComponent->setFsmState(this->currentState().name());
    }
    ~Machine() override
    {
        // Events never run are deleted with the machine.
        while (m_buffer.readable() > 0) {
            EventBase *event = m_buffer.get();
            m_buffer.advanceRptr();
            delete event;
        }
    }
    Machine(const Machine &) = delete;
    Machine &operator=(const Machine &) = delete;

    /// The queue of received events.
    virtual RingBuffer<EventBase *> &getBuffer() { return m_buffer; }
    /// Dispatches every queued event, oldest first.
    virtual void run_event()
    {
        while (m_buffer.readable() > 0) {
            EventBase *event = m_buffer.get();
            m_buffer.advanceRptr();
            (*event)();
            delete event;
        }
    }

private:
    template <class C, class P>
    friend class Link;

    RTObject_impl *rtComponent;
    RingBuffer<EventBase *> m_buffer;
};

// onEntry() / onInit() / onExit() override their superstate's without saying so (see below).
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Winconsistent-missing-override"
#pragma clang diagnostic ignored "-Wsuggest-override"
#elif defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wsuggest-override"
#endif

/**
 * The link between FSM state @p C and its superstate @p P. States implement onEntry(), onInit()
 * (which may choose a substate with setState<S>()) and onExit(); each runs between the
 * component's pre… and post… FSM hooks. Entering a state is a state change: the component hears
 * postOnFsmStateChange(C) before C's entry, and preOnFsmStateChange(C) after C's exit.
 */
template <class C, class P>
class Link : public Macho::Link<C, P>
{
public:
    using LINK = Link<C, P>;

    void entry() override
    {
        setrtc();
        if (rtComponent == nullptr) {
            onEntry();
            return;
        }
        rtComponent->postOnFsmStateChange(C::_state_name(), RTC::RTC_OK);
        rtComponent->preOnFsmEntry(C::_state_name());
        rtComponent->postOnFsmEntry(C::_state_name(), onEntry());
    }
    void init() override
    {
        setrtc();
        if (rtComponent == nullptr) {
            onInit();
            return;
        }
        rtComponent->preOnFsmInit(C::_state_name());
        rtComponent->postOnFsmInit(C::_state_name(), onInit());
    }
    void exit() override
    {
        setrtc();
        if (rtComponent == nullptr) {
            onExit();
            return;
        }
        rtComponent->preOnFsmExit(C::_state_name());
        rtComponent->postOnFsmExit(C::_state_name(), onExit());
        rtComponent->preOnFsmStateChange(C::_state_name());
    }

    // Declared again in every link, so that a state without its own action does nothing (rather
    // than run its superstate's).
    virtual RTC::ReturnCode_t onEntry() { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onInit() { return RTC::RTC_OK; }
    virtual RTC::ReturnCode_t onExit() { return RTC::RTC_OK; }

    /// The component the machine belongs to (null while the machine is being constructed).
    RTObject_impl *rtComponent;

protected:
    explicit Link(Macho::_StateInstance &instance)
        : Macho::Link<C, P>(instance)
        , rtComponent(nullptr)
    {
    }
    ~Link() override {}

    /// Finds the component once the machine is an RTC::Machine (not yet while it is constructed).
    void setrtc()
    {
        if (rtComponent != nullptr)
            return;
        const RTC::Machine<typename P::TOP> *machine =
            dynamic_cast<const RTC::Machine<typename P::TOP> *>(&this->_machine());
        if (machine != nullptr)
            rtComponent = machine->rtComponent;
    }
};

#if defined(__clang__)
#pragma clang diagnostic pop
#elif defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
} // namespace RTC

#endif // RTM_STATICFSM_H
