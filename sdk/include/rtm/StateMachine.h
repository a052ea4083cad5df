// SPDX-License-Identifier: MIT
// A table-driven state machine: per-state entry, pre-do, do, post-do and exit callbacks.
#ifndef RTC_STATEMACHINE_H
#define RTC_STATEMACHINE_H

#include <mutex>

#include <cassert>
#include <utility>
#include <vector>

namespace RTC_Utils
{
/// The state a machine is in, the one it was in and the one it goes to next.
template <class State>
struct StateHolder
{
    State curr;
    State prev;
    State next;
};

/**
 * A state machine over the states 0 … num_of_state-1 of @p State whose actions are member
 * functions of @p Listener. goTo() asks for a state; the next worker() call leaves the current
 * one (exit action) and enters it (entry action); while the state stays, each worker() call runs
 * its pre-do, do and post-do actions, stopping early when a transition is asked for meanwhile.
 * worker_pre() / worker_do() / worker_post() run those steps one at a time.
 */
template <class State, class Listener, class States = StateHolder<State>,
          class Callback = void (Listener::*)(const States &states)>
class StateMachine
{
public:
    explicit StateMachine(int num_of_state)
        : m_num(num_of_state)
        , m_listener(nullptr)
        , m_entry(std::size_t(num_of_state), Callback(nullptr))
        , m_predo(std::size_t(num_of_state), Callback(nullptr))
        , m_do(std::size_t(num_of_state), Callback(nullptr))
        , m_postdo(std::size_t(num_of_state), Callback(nullptr))
        , m_exit(std::size_t(num_of_state), Callback(nullptr))
        , m_transit(nullptr)
        , m_states()
        , m_selftrans(false)
    {
    }
    virtual ~StateMachine() {}
    StateMachine(const StateMachine &other)
        : m_num(other.m_num)
        , m_listener(other.m_listener)
        , m_entry(other.m_entry)
        , m_predo(other.m_predo)
        , m_do(other.m_do)
        , m_postdo(other.m_postdo)
        , m_exit(other.m_exit)
        , m_transit(other.m_transit)
        , m_states(other.m_states)
        , m_selftrans(other.m_selftrans)
    {
    }
    StateMachine &operator=(const StateMachine &other)
    {
        StateMachine copy(other);
        swap(copy);
        return *this;
    }
    void swap(StateMachine &other)
    {
        std::swap(m_num, other.m_num);
        std::swap(m_listener, other.m_listener);
        m_entry.swap(other.m_entry);
        m_predo.swap(other.m_predo);
        m_do.swap(other.m_do);
        m_postdo.swap(other.m_postdo);
        m_exit.swap(other.m_exit);
        std::swap(m_transit, other.m_transit);
        std::swap(m_states, other.m_states);
        std::swap(m_selftrans, other.m_selftrans);
    }

    /// Makes @p call_back every action of every state (a listener's "do nothing").
    void setNOP(Callback call_back)
    {
        setNullFunc(m_entry, call_back);
        setNullFunc(m_do, call_back);
        setNullFunc(m_exit, call_back);
        setNullFunc(m_predo, call_back);
        setNullFunc(m_postdo, call_back);
        m_transit = call_back;
    }
    void setListener(Listener *listener)
    {
        assert(listener != nullptr);
        m_listener = listener;
    }
    /// False (and an assertion in debug builds) for a state out of range.
    bool setEntryAction(State state, Callback call_back) { return setAction(m_entry, state, call_back); }
    bool setPreDoAction(State state, Callback call_back) { return setAction(m_predo, state, call_back); }
    bool setDoAction(State state, Callback call_back) { return setAction(m_do, state, call_back); }
    bool setPostDoAction(State state, Callback call_back) { return setAction(m_postdo, state, call_back); }
    bool setExitAction(State state, Callback call_back) { return setAction(m_exit, state, call_back); }
    bool setTransitionAction(Callback call_back)
    {
        m_transit = call_back;
        return true;
    }
    void setStartState(States states)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_states = states;
    }
    States getStates()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_states;
    }
    State getState()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_states.curr;
    }
    bool isIn(State state)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_states.curr == state;
    }
    /// Asks for @p state; the transition happens in the next worker call.
    void goTo(State state)
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_states.next = state;
        if (m_states.curr == state)
            m_selftrans = true;
    }

    /// One step: the transition asked for, or the state's pre-do, do and post-do actions.
    void worker()
    {
        States st = snapshot();
        if (st.curr != st.next) {
            transit(st);
            return;
        }
        call(m_predo, st);
        if (transitionPending())
            return;
        call(m_do, st);
        if (transitionPending())
            return;
        call(m_postdo, st);
    }
    /// The transition asked for, or else the current state's pre-do action.
    void worker_pre()
    {
        States st = snapshot();
        if (st.curr != st.next)
            transit(st);
        else
            call(m_predo, st);
    }
    void worker_do()
    {
        States st = snapshot();
        call(m_do, st);
    }
    void worker_post()
    {
        States st = snapshot();
        call(m_postdo, st);
    }

protected:
    void setNullFunc(std::vector<Callback> &s, Callback nullfunc)
    {
        s.assign(std::size_t(m_num), nullfunc);
    }

    int m_num;
    Listener *m_listener;
    std::vector<Callback> m_entry;
    std::vector<Callback> m_predo;
    std::vector<Callback> m_do;
    std::vector<Callback> m_postdo;
    std::vector<Callback> m_exit;
    Callback m_transit;
    States m_states;
    bool m_selftrans;
    std::mutex m_mutex;

private:
    bool setAction(std::vector<Callback> &table, State state, Callback call_back)
    {
        if (int(state) < 0 || int(state) >= m_num) {
            assert(false && "state out of range");
            return false;
        }
        table[std::size_t(state)] = call_back;
        return true;
    }
    void call(const std::vector<Callback> &table, const States &st)
    {
        Callback action = table[std::size_t(st.curr)];
        if (action != nullptr && m_listener != nullptr)
            (m_listener->*action)(st);
    }
    States snapshot()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_states;
    }
    bool transitionPending()
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_states.curr != m_states.next;
    }
    // Exit the current state, then enter the one asked for (asked for again meanwhile, maybe).
    void transit(States st)
    {
        call(m_exit, st);
        st = snapshot();
        if (st.curr == st.next)
            return;
        st.prev = st.curr;
        st.curr = st.next;
        call(m_entry, st);
        std::lock_guard<std::mutex> guard(m_mutex);
        m_states.prev = st.prev;
        m_states.curr = st.curr;
        m_selftrans = false;
    }
};
} // namespace RTC_Utils

#endif // RTC_STATEMACHINE_H
