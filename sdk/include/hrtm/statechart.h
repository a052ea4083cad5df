// SPDX-License-Identifier: MIT
/*!
 * @file statechart.h
 * @brief hrtm::sc: hierarchical state machines whose states are classes (HRTM's statechart).
 *
 * A machine's top state is declared with TOPSTATE(Top), its substates with
 * SUBSTATE(Name, Superstate); the first thing in each body is STATE(Name). Events are virtual
 * member functions of the top state, overridden by the states that handle them; the current
 * state's override runs (or the nearest superstate's). on_entry() / on_exit() run as states are
 * entered and left, on_init() when a state becomes the target of a transition (it may move on to
 * a substate). Each state may declare a `struct Data`, which exists while the state is active
 * (PERSISTENT() keeps it) and is reached with data().
 *
 * @code
 * TOPSTATE(Top) {
 *     struct Data { int count = 0; };
 *     STATE(Top)
 *     virtual void press() {}
 *   private:
 *     void on_init() { Off::set_state(machine()); }
 * };
 * SUBSTATE(Off, Top) { STATE(Off) void press() { On::set_state(machine()); } };
 * SUBSTATE(On, Top)  { STATE(On)  void press() { Off::set_state(machine()); } };
 *
 * hrtm::sc::Machine<Top> m;                      // enters Top, then Off
 * m->press();                                    // Off → On
 * m.dispatch(hrtm::sc::Event(&Top::press));      // On → Off
 * @endcode
 *
 * Transitions requested in an action (X::set_state(machine())) are taken when the action
 * returns: the states that do not contain the target are left (innermost first), the target's
 * superstates that were not active are entered (outermost first), then the target itself, then
 * its on_init(). An event posted with dispatch() from an action is handled after that, and the
 * events put aside with defer() once the next transition (with its init steps) is done. HISTORY() / DEEPHISTORY() make a
 * state remember its last active direct substate / innermost active state, which set_state()
 * then returns to instead of calling on_init() (set_state_direct() ignores the history).
 */
#ifndef HRTM_STATECHART_H_
#define HRTM_STATECHART_H_

#include "hrtm/defs.h"

#include <algorithm>
#include <cassert>
#include <iostream>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

/*! Declares the top state @p TOP of a machine. */
#define TOPSTATE(TOP) struct TOP : public hrtm::sc::Link<TOP, hrtm::sc::TopState<TOP> >

/*! Declares state @p STATE inside @p SUPERSTATE. */
#define SUBSTATE(STATE, SUPERSTATE) struct STATE : public hrtm::sc::Link<STATE, SUPERSTATE>

/*! The members every state has; the first thing in its body (leaves the body public). */
#define STATE(S)                                                                                               \
public:                                                                                                        \
    S(hrtm::sc::StateInfo &info)                                                                               \
        : hrtm::sc::Link<S, SUPER>(info)                                                                       \
    {                                                                                                          \
        static_assert(std::is_same<LinkType, hrtm::sc::Link<S, SUPER> >::value,                               \
                      "STATE() must name the state it is in");                                                 \
    }                                                                                                          \
    ~S() {}                                                                                                    \
    static const char *state_name() { return #S; }                                                            \
    Data &data() { return *static_cast<Data *>(local_data()); }

/*! The state remembers its innermost active state when left. */
#define DEEPHISTORY()                                                                                          \
private:                                                                                                       \
    void save_history(hrtm::sc::StateInfo &self, hrtm::sc::StateInfo & /* shallow */,                        \
                      hrtm::sc::StateInfo &deep)                                                               \
    {                                                                                                          \
        self.set_history(&deep);                                                                               \
        SUPER::set_history_super(self, deep);                                                                  \
    }                                                                                                          \
                                                                                                               \
protected:                                                                                                     \
    void set_history_super(hrtm::sc::StateInfo &self, hrtm::sc::StateInfo &deep)                              \
    {                                                                                                          \
        self.set_history_super(deep);                                                                          \
    }                                                                                                          \
                                                                                                               \
public:

/*! The state remembers its last active direct substate when left. */
#define HISTORY()                                                                                              \
private:                                                                                                       \
    void save_history(hrtm::sc::StateInfo &self, hrtm::sc::StateInfo &shallow, hrtm::sc::StateInfo &deep)     \
    {                                                                                                          \
        self.set_history(&shallow);                                                                            \
        SUPER::set_history_super(self, deep);                                                                  \
    }                                                                                                          \
                                                                                                               \
protected:                                                                                                     \
    void set_history_super(hrtm::sc::StateInfo &self, hrtm::sc::StateInfo &deep)                              \
    {                                                                                                          \
        self.set_history_super(deep);                                                                          \
    }                                                                                                          \
                                                                                                               \
public:

/*! The state's Data outlives the state's activity (kept when the state is left). */
#define PERSISTENT()                                                                                           \
private:                                                                                                       \
    void delete_data(hrtm::sc::StateInfo &) {}                                                                 \
                                                                                                               \
public:

namespace hrtm {
namespace sc {
/*! A state's index in its machine (0 is the root above the top state). */
using Key = unsigned int;

class MachineBase;
class EventBase;
template<class T> class Machine;
template<class T> class EventParamBase;
class StateInfo;
template<class T> class TopState;
template<class S> class State;

/*! The Data of states that declare none. */
class EmptyData
{
public:
    EmptyData() = default;
};

/*! Gives each state class of machine @p TOP its key, at static initialisation. */
template<class TOP> struct KeyInit
{
    KeyInit()
        : key(Machine<TOP>::the_state_count_++)
    { }
    Key key;
};

/*! What every state object is: the actions, and the link to its StateInfo. */
class EXPORT_DLL StateBase
{
public:
    virtual ~StateBase() = default;
    static Key key() { return 0; }

protected:
    StateBase(StateInfo &info) // NOLINT: states are made from their info
        : state_info_(info)
    { }
    virtual void restore(StateInfo &current);
    virtual void shutdown();
    /*! Passes a history record on to the superstates (only states with history do). */
    virtual void set_history_super(StateInfo & /* self */, StateInfo & /* deep */) { }

protected:
    virtual void on_entry() { }
    virtual void on_init() { }
    virtual void on_exit() { }

protected:
    friend class StateInfo;
    friend class RootStateInfo;
    friend class MachineBase;

    /*! The root's info in @p machine (created on first use). */
    static StateInfo &get_info(MachineBase &machine);
    virtual void delete_data(StateInfo & /* info */) { }
    virtual void save_history(StateInfo & /* self */, StateInfo & /* shallow */, StateInfo & /* deep */) { }

protected:
    StateInfo &state_info_;
};

/*!
 * One state of one machine: its state object, its superstate, its Data while it has one and
 * its history.
 */
class EXPORT_DLL StateInfo
{
public:
    StateInfo(MachineBase &machine, StateInfo *parent);
    virtual ~StateInfo();

    /*! Enters the superstates not active in @p previous, then this state (when @p first or new). */
    void on_entry(StateInfo &previous, bool first = true);
    /*! Leaves this state and its superstates that do not contain @p next. */
    void on_exit(StateInfo &next);
    /*! Runs on_init(), or with @p history moves on to the remembered substate instead. */
    void on_init(bool history);

    void save_history(StateInfo &shallow, StateInfo &deep) { instance_->save_history(*this, shallow, deep); }
    /*! Offers @p deep to the superstate's history (this state being the shallow one). */
    void set_history_super(StateInfo &deep)
    {
        if (parent_ != nullptr)
            parent_->save_history(*this, deep);
    }
    /*! Gives the state @p data (a new Data of its type) instead of a default one. */
    void set_data(void *data)
    {
        if (data_ != nullptr)
            delete_data();
        data_ = data;
    }

    /*! Copies @p original's history and Data (the same state of another machine). */
    void copy(StateInfo &original);
    /*! This state (and its superstates) in @p new_machine. */
    StateInfo *clone(MachineBase &new_machine);
    virtual void clone_data(void *data) = 0;

    void shutdown() { instance_->shutdown(); }
    void restore(StateInfo &info) { instance_->restore(info); }

    virtual Key key() = 0;
    virtual StateInfo *create(MachineBase &machine, StateInfo *parent) = 0;
    virtual void create_data() = 0;
    virtual void delete_data() = 0;
    virtual const char *name() const = 0;

    /*! True when @p state is this state or one of its superstates. */
    bool is_child(StateInfo &state) const
    {
        return this == &state || (parent_ != nullptr && parent_->is_child(state));
    }
    StateBase &instance()
    {
        assert(instance_);
        return *instance_;
    }
    void *data()
    {
        assert(data_);
        return data_;
    }
    MachineBase &machine() { return machine_; }
    void set_history(StateInfo *history) { history_ = history; }

protected:
    MachineBase &machine_;
    StateBase *instance_;
    StateInfo *history_;
    StateInfo *parent_;
    void *data_;
    void *data_place; // unused: Data is allocated per activation
};

/*! The base of a machine's top state @p T (TOPSTATE derives from it). */
template<class T> class TopState : public StateBase
{
public:
    using TOP = T;

protected:
    TopState(StateInfo &info) // NOLINT: states are made from their info
        : StateBase(info)
    { }
    /*! Handles @p event after the current action (and its transition). */
    void dispatch(EventParamBase<TOP> *event);
    /*!
     * Puts @p event aside until the next transition has been taken; a second event under the
     * same @p name before then is dropped.
     */
    void defer(EventParamBase<TOP> *event, const std::string &name = "event");
    Machine<TOP> &machine() { return *static_cast<Machine<TOP> *>(&this->state_info_.machine()); }
};

using GetInfoFn = StateInfo &(*)(MachineBase &);
using DestroyFn = void (*)(void *);
using CloneFn = void *(*)(void *);

/*! What a StateAlias needs to know of its state class. */
struct StateCharacter
{
    GetInfoFn get_info;
    DestroyFn destroy;
    CloneFn clone;
};

/*! A state chosen at run time (State<S>), with optional Data for it; copies hand the Data on. */
class StateAlias
{
public:
    StateAlias(const StateAlias &other)
        : data_(other.take_data())
        , character_(other.character_)
    { }
    StateAlias &operator=(const StateAlias &other)
    {
        if (this != &other) {
            (character_->destroy)(data_);
            character_ = other.character_;
            data_ = other.take_data();
        }
        return *this;
    }
    ~StateAlias() { (character_->destroy)(data_); }
    /*! A copy with a copy of the Data (this alias keeps its own). */
    StateAlias clone() { return StateAlias(character_, data_ != nullptr ? (character_->clone)(data_) : nullptr); }
    StateInfo &get_info(MachineBase &machine) const { return (character_->get_info)(machine); }
    /*! The Data, which the caller now owns. */
    void *take_data() const
    {
        void *data = data_;
        data_ = nullptr;
        return data;
    }

protected:
    StateAlias(StateCharacter *character, void *data)
        : data_(data)
        , character_(character)
    { }

private:
    mutable void *data_;
    StateCharacter *character_;
};

/*! The state-independent part of a machine. */
class EXPORT_DLL MachineBase
{
public:
    /*! Takes the transition to @p info now (with @p data as its Data when not null). */
    void set_state(StateInfo &info, bool history, void *data);
    void set_state(const StateAlias &state, bool history);
    /*! Records the transition to @p info, taken when the current action returns. */
    void set_pending_state(StateInfo &info, bool history, void *data)
    {
        assert((!pending_state_ || pending_state_ == &info) && "There is already a state transition pending!");
        pending_state_ = &info;
        pending_data_ = data;
        pending_history_ = history;
    }
    /*! Records @p event, handled when the current action returns. */
    void set_pending_event(EventBase *event)
    {
        assert(event);
        assert(!pending_event_ && "There is already an event pending!");
        pending_event_ = event;
    }
    void add_deferred_event(EventBase *event, const std::string &name);
    /*! Takes the pending transitions, then handles the pending and deferred events. */
    void perform_pending();
    void perform_pending_event();
    void perform_deferred_events();
    StateInfo *&get_info(Key name) { return states_[name]; }
    /*! True when @p info is the current state or one of its superstates. */
    bool is_current(StateInfo &info) { return current_state_->is_child(info); }
    bool is_current_direct(StateInfo &info) const { return current_state_ == &info; }

protected:
    MachineBase();
    ~MachineBase();
    void start(StateInfo &info, void *data);
    void shutdown();
    void allocate(unsigned int count);
    void free(unsigned int count);
    void copy(StateInfo **other, unsigned int count);
    StateInfo *create_clone(Key key, StateInfo *original);
    /*! One step of perform_pending(): leaves, enters and initialises for the pending transition. */
    void take_pending_transition();

protected:
    using EventQueue = std::map<std::string, EventBase *>;
    using EventNames = std::vector<std::string>;

    friend class StateInfo;
    friend class StateBase;

    StateInfo *current_state_ {nullptr};
    StateInfo *pending_state_ {nullptr};
    void *pending_data_ {nullptr};
    bool pending_history_ {false};
    EventBase *pending_event_ {nullptr};
    EventQueue deferred_events_;
    EventNames deferred_names_;
    StateInfo **states_ {nullptr};
};

/*! Makes state @p C a substate of @p P (SUBSTATE / TOPSTATE derive from it). */
template<class C, class P> class Link : public P
{
public:
    using SUPER = P;
    using TOP = typename P::TOP;
    using Data = EmptyData;

    static Key key() { return the_key_.key; }
    /*! True when the machine is in this state or one of its substates. */
    static bool is_current(Machine<TOP> &m) { return m.is_current(get_info(m)); }
    /*! True when the machine is in exactly this state. */
    static bool is_current_direct(Machine<TOP> &m) { return m.is_current_direct(get_info(m)); }
    static void clear_history(Machine<TOP> &m) { get_info(m).set_history(nullptr); }
    /*! Forgets the history of this state and of all its substates. */
    static void clear_history_deep(Machine<TOP> &m) { m.clear_history_deep(get_info(m)); }
    /*! Moves @p machine to this state (to its history if it has one) after the current action. */
    static void set_state(Machine<TOP> &machine, void *data = nullptr)
    {
        machine.set_pending_state(get_info(machine), true, data);
    }
    /*! Moves @p machine to this state, ignoring its history, after the current action. */
    static void set_state_direct(Machine<TOP> &machine, void *data = nullptr)
    {
        machine.set_pending_state(get_info(machine), false, data);
    }
    void set_state(const StateAlias &state)
    {
        P::machine().set_pending_state(state.get_info(P::machine()), true, state.take_data());
    }
    void set_state_direct(const StateAlias &state)
    {
        P::machine().set_pending_state(state.get_info(P::machine()), false, state.take_data());
    }
    void set_state(StateInfo &current, void *data = nullptr)
    {
        this->state_info_.machine().set_pending_state(current, true, data);
    }

protected:
    using LinkType = Link<C, P>;

    Link(StateInfo &info); // NOLINT: states are made from their info
    virtual void on_entry() { }
    virtual void on_init() { }
    virtual void on_exit() { }
    static StateInfo &get_info(MachineBase &machine);
    void delete_data(StateInfo &info);
    void save_history(StateInfo &self, StateInfo & /* shallow */, StateInfo &deep)
    {
        this->set_history_super(self, deep);
    }
    void *local_data();

protected:
    friend class StateBase;
    friend class Machine<TOP>;
    friend class State<C>;

    StateInfo &state_info_;
    static KeyInit<TOP> the_key_;
};

template<class C, class P> KeyInit<typename P::TOP> Link<C, P>::the_key_;

/*! The info of the root, the invisible state above the top state. */
class RootStateInfo : public StateInfo
{
public:
    RootStateInfo(MachineBase &machine, StateInfo *parent)
        : StateInfo(machine, parent)
    {
        instance_ = new StateBase(*this);
    }
    Key key() override { return 0; }
    void create_data() override { }
    void delete_data() override { }
    void clone_data(void * /* data */) override { }
    const char *name() const override { return "Root"; }
    StateInfo *create(MachineBase &machine, StateInfo *parent) override
    {
        return new RootStateInfo(machine, parent);
    }
};

/*! The info of state class @p S. */
template<class S> class SubStateInfo : public StateInfo
{
public:
    using Data = typename S::Data;

    SubStateInfo(MachineBase &machine, StateInfo *parent)
        : StateInfo(machine, parent)
    {
        assert(parent);
        this->instance_ = new S(*this);
    }
    ~SubStateInfo() override
    {
        if (this->data_ != nullptr)
            delete_data();
    }
    const char *name() const override { return S::state_name(); }
    Key key() override { return S::key(); }
    StateInfo *create(MachineBase &machine, StateInfo *parent) override
    {
        return new SubStateInfo<S>(machine, parent);
    }
    void clone_data(void *data) override
    {
        assert(!data_);
        data_ = new Data(*static_cast<Data *>(data));
    }
    void create_data() override { this->data_ = new Data(); }
    void delete_data() override
    {
        delete static_cast<Data *>(this->data_);
        data_ = nullptr;
    }
};

/*! An event: a call to make on the current state. */
class EventBase
{
public:
    virtual ~EventBase() = default;
    virtual void dispatch(StateInfo &) = 0;
};

/*! An event of machine @p TOP (what Event() returns). */
template<class TOP> class EventParamBase : protected EventBase
{
    friend class Machine<TOP>;
    friend class TopState<TOP>;
};

/*! A call of a four-argument handler. */
template<class TOP, class ROOT, class P1, class P2, class P3, class P4>
class EventWith4Params : public EventParamBase<TOP>
{
    using Signature = ROOT (TOP::*)(P1, P2, P3, P4);

public:
    EventWith4Params(Signature handler, P1 p1, P2 p2, P3 p3, P4 p4)
        : handler_(handler)
        , param1_(p1)
        , param2_(p2)
        , param3_(p3)
        , param4_(p4)
    {
        assert(handler);
    }

protected:
    void dispatch(StateInfo &info)
    {
        (static_cast<TOP &>(info.instance()).*handler_)(param1_, param2_, param3_, param4_);
    }
    Signature handler_;
    P1 param1_;
    P2 param2_;
    P3 param3_;
    P4 param4_;
};

/*! A call of a three-argument handler. */
template<class TOP, class ROOT, class P1, class P2, class P3> class EventWith3Params : public EventParamBase<TOP>
{
    using Signature = ROOT (TOP::*)(P1, P2, P3);

public:
    EventWith3Params(Signature handler, P1 p1, P2 p2, P3 p3)
        : handler_(handler)
        , param1_(p1)
        , param2_(p2)
        , param3_(p3)
    {
        assert(handler);
    }

protected:
    void dispatch(StateInfo &info)
    {
        (static_cast<TOP &>(info.instance()).*handler_)(param1_, param2_, param3_);
    }
    Signature handler_;
    P1 param1_;
    P2 param2_;
    P3 param3_;
};

/*! A call of a two-argument handler. */
template<class TOP, class ROOT, class P1, class P2> class EventWith2Params : public EventParamBase<TOP>
{
    using Signature = ROOT (TOP::*)(P1, P2);

public:
    EventWith2Params(ROOT (TOP::*handler)(P1, P2), P1 p1, P2 p2)
        : handler_(handler)
        , param1_(p1)
        , param2_(p2)
    {
        assert(handler);
    }

protected:
    void dispatch(StateInfo &info) { (static_cast<TOP &>(info.instance()).*handler_)(param1_, param2_); }
    Signature handler_;
    P1 param1_;
    P2 param2_;
};

/*! A call of a one-argument handler. */
template<class TOP, class ROOT, class P1> class EventWith1Params : public EventParamBase<TOP>
{
    using Signature = ROOT (TOP::*)(P1);

public:
    EventWith1Params(ROOT (TOP::*handler)(P1), P1 p1)
        : handler_(handler)
        , param1_(p1)
    {
        assert(handler);
    }

protected:
    void dispatch(StateInfo &info) { (static_cast<TOP &>(info.instance()).*handler_)(param1_); }
    Signature handler_;
    P1 param1_;
};

/*! A call of a handler without arguments. */
template<class TOP, class ROOT> class EventWithoutParams : public EventParamBase<TOP>
{
    using Signature = ROOT (TOP::*)();

public:
    EventWithoutParams(ROOT (TOP::*handler)())
        : handler_(handler)
    {
        assert(handler);
    }

protected:
    void dispatch(StateInfo &info) { (static_cast<TOP &>(info.instance()).*handler_)(); }
    Signature handler_;
};

/*! An event calling @p handler with the given arguments (copied); the machine deletes it. */
template<class TOP, class ROOT, class P1, class P2, class P3, class P4>
inline EventParamBase<TOP> *Event(ROOT (TOP::*handler)(P1, P2, P3, P4), P1 p1, P2 p2, P3 p3, P4 p4)
{
    return new EventWith4Params<TOP, ROOT, P1, P2, P3, P4>(handler, p1, p2, p3, p4);
}

template<class TOP, class ROOT, class P1, class P2, class P3>
inline EventParamBase<TOP> *Event(ROOT (TOP::*handler)(P1, P2, P3), P1 p1, P2 p2, P3 p3)
{
    return new EventWith3Params<TOP, ROOT, P1, P2, P3>(handler, p1, p2, p3);
}

template<class TOP, class ROOT, class P1, class P2>
inline EventParamBase<TOP> *Event(ROOT (TOP::*handler)(P1, P2), P1 p1, P2 p2)
{
    return new EventWith2Params<TOP, ROOT, P1, P2>(handler, p1, p2);
}

template<class TOP, class ROOT, class P1>
inline EventParamBase<TOP> *Event(ROOT (TOP::*handler)(P1), P1 p1)
{
    return new EventWith1Params<TOP, ROOT, P1>(handler, p1);
}

template<class TOP, class ROOT> inline EventParamBase<TOP> *Event(ROOT (TOP::*handler)())
{
    return new EventWithoutParams<TOP, ROOT>(handler);
}

template<class T> inline void TopState<T>::dispatch(EventParamBase<TOP> *event)
{
    assert(event);
    state_info_.machine().set_pending_event(event);
}

template<class T> inline void TopState<T>::defer(EventParamBase<TOP> *event, const std::string &name)
{
    assert(event);
    state_info_.machine().add_deferred_event(event, name);
}

template<class C, class P>
inline Link<C, P>::Link(StateInfo &info)
    : P(P::get_info(info.machine()))
    , state_info_(info)
{ }

template<class C, class P> inline StateInfo &Link<C, P>::get_info(MachineBase &machine)
{
    // A state's info is made on first use, after its superstate's.
    StateInfo *&info = machine.get_info(key());
    if (info == nullptr)
        info = new SubStateInfo<C>(machine, &P::get_info(machine));
    return *info;
}

template<class C, class P> inline void *Link<C, P>::local_data()
{
    return state_info_.data();
}

template<class C, class P> inline void Link<C, P>::delete_data(StateInfo &info)
{
    info.delete_data();
}

/*! State @p S as a value (a StateAlias), optionally with Data for it. */
template<class S> class State : public StateAlias
{
public:
    explicit State(typename S::Data *data = 0)
        : StateAlias(&the_character_, data)
    { }

private:
    static StateInfo &get_info(MachineBase &machine) { return S::get_info(machine); }
    static void destroy(void *data) { delete static_cast<typename S::Data *>(data); }
    static void *clone(void *data)
    {
        using Data = typename S::Data;
        return new Data(*static_cast<Data *>(data));
    }

    static StateCharacter the_character_;
};

/*! A copy of a machine's state (current state, histories, Data), to restore it later. */
template<class TOP> class Snapshot : public MachineBase
{
public:
    Snapshot(const Machine<TOP> &machine); // NOLINT: a snapshot is taken of a machine
    ~Snapshot() { free(Machine<TOP>::the_state_count_); }

private:
    friend class Machine<TOP>;
    Snapshot(const Snapshot<TOP> &other) = delete;
    Snapshot &operator=(const Snapshot<TOP> &other) = delete;
};

/*! A state machine with top state @p TOP. */
template<class TOP> class Machine : public MachineBase
{
public:
    /*! Calls through operator->, taking the resulting transition when the call returns. */
    struct AfterAdvice
    {
        AfterAdvice(Machine<TOP> &m) // NOLINT: made by operator->
            : machine_(m)
        { }
        ~AfterAdvice() { machine_.perform_pending(); }
        TOP *operator->() { return static_cast<TOP *>(&(machine_.current_state_->instance())); }

    private:
        Machine<TOP> &machine_;
    };
    friend struct AfterAdvice;

    /*! Enters the top state (with @p data as its Data when given, owned by the machine). */
    Machine(typename TOP::Data *data = 0) // NOLINT: implicit as in HRTM
    {
        static_assert(std::is_base_of<TopState<TOP>, TOP>::value, "declare the top state with TOPSTATE()");
        allocate(the_state_count_);
        start(TOP::get_info(*this), data);
    }
    /*! Enters @p state directly. */
    Machine(const StateAlias &state) // NOLINT: implicit as in HRTM
    {
        static_assert(std::is_base_of<TopState<TOP>, TOP>::value, "declare the top state with TOPSTATE()");
        allocate(the_state_count_);
        start(state.get_info(*this), state.take_data());
    }
    /*! A machine in the state @p snapshot recorded (no actions run). */
    Machine(const Snapshot<TOP> &snapshot) // NOLINT: implicit as in HRTM
    {
        allocate(the_state_count_);
        copy(snapshot.states_, the_state_count_);
        current_state_ = get_info(snapshot.current_state_->key());
    }
    /*! Returns to the state @p snapshot recorded; the current states are left first. */
    Machine<TOP> &operator=(const Snapshot<TOP> &snapshot)
    {
        assert(!pending_state_);
        assert(!pending_event_);
        current_state_->shutdown();
        free(the_state_count_);
        copy(snapshot.states_, the_state_count_);
        current_state_ = get_info(0);
        StateInfo *current = get_info(snapshot.current_state_->key());
        current->restore(*current);
        perform_pending();
        return *this;
    }
    /*! Leaves every state (exit actions run), then frees them. */
    ~Machine()
    {
        current_state_->shutdown();
        free(the_state_count_);
    }

    /*! Calls an event handler on the current state: `machine->handler(args)`. */
    AfterAdvice operator->()
    {
        assert(current_state_);
        assert(!pending_state_);
        return AfterAdvice(*this);
    }
    /*! Handles @p event now (deleting it unless @p destroy is false). */
    void dispatch(EventParamBase<TOP> *event, bool destroy = true)
    {
        assert(event);
        event->dispatch(*current_state_);
        if (destroy)
            delete event;
        perform_pending();
    }
    /*! The top state's Data. */
    const typename TOP::Data &data() const
    {
        assert(current_state_);
        return static_cast<TOP &>(current_state_->instance()).TOP::data();
    }
    void clear_history_deep(StateInfo &state)
    {
        for (unsigned int i = 0; i < the_state_count_; ++i) {
            StateInfo *s = states_[i];
            if (s != nullptr && s->is_child(state))
                s->set_history(nullptr);
        }
    }

    /*! Number of state classes of this machine, plus one for the root. */
    static Key the_state_count_;

private:
    Machine(const Machine<TOP> &other) = delete;
    Machine<TOP> &operator=(const Machine<TOP> &other) = delete;
    friend class Snapshot<TOP>;
};

template<class TOP> Snapshot<TOP>::Snapshot(const Machine<TOP> &machine)
{
    assert(!machine.pending_state_);
    assert(!machine.pending_event_);
    assert(machine.current_state_);
    allocate(Machine<TOP>::the_state_count_);
    copy(machine.states_, Machine<TOP>::the_state_count_);
    current_state_ = get_info(machine.current_state_->key());
}

template<class TOP> Key Machine<TOP>::the_state_count_ = 1;

template<class S> StateCharacter State<S>::the_character_ = {State<S>::get_info, State<S>::destroy, State<S>::clone};
} // namespace sc
} // namespace hrtm

#endif // HRTM_STATECHART_H_
