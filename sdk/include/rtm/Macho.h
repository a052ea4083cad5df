// SPDX-License-Identifier: MIT
// Hierarchical state machines with the API of Macho ("Machine Objects"), the library OpenRTM-aist
// bundles for its static FSM components. States are classes: a substate derives from its
// superstate through Link<State, Superstate>, events are virtual member functions of the top state
// (the current state's override handles them, else the nearest superstate's), and entry(), exit()
// and init() run as transitions enter and leave states.
//
// Semantics, as Macho defines them:
//  - setState<S>() inside a handler or an entry/init action only records the transition; it is
//    taken when the action returns: the states from the current one up to (not including) the
//    innermost common superstate are left (exit, innermost first), the states down to S entered
//    (entry, outermost first; S itself is always left and entered again when it is current or a
//    superstate of the current state), then S's init() runs, and may choose a substate.
//  - dispatch(Event(...)) from inside a handler queues the event; it is handled after the pending
//    transition.
//  - HISTORY() / DEEPHISTORY() make a state remember its last active direct substate / innermost
//    active state; setStateHistory<S>() enters it (S's init() when S has none). Entering a state
//    through init() consumes its history.
//  - A state's Box (its data) exists while the state is active; PERSISTENT() keeps it.
#ifndef RTM_MACHO_H
#define RTM_MACHO_H

#include <cassert>
#include <deque>
#include <memory>
#include <new>
#include <tuple>
#include <type_traits>
#include <vector>

/// The top state @p TOP of a machine (Macho's own spelling; FSM components use FSM_TOPSTATE).
#define TOPSTATE(TOP) struct TOP : public ::Macho::Link<TOP, ::Macho::TopBase<TOP> >
/// State @p STATE inside @p SUPERSTATE.
#define SUBSTATE(STATE, SUPERSTATE) struct STATE : public ::Macho::Link<STATE, SUPERSTATE>

/// The members every state class has; the first thing in a TOPSTATE / SUBSTATE body.
#define MACHO_STATE_MEMBERS_(S, LINKBASE)                                                                      \
public:                                                                                                        \
    using SELF = S;                                                                                            \
    S(::Macho::_StateInstance &instance)                                                                       \
        : LINKBASE<S, SUPER>(instance)                                                                         \
    {                                                                                                          \
    }                                                                                                          \
    ~S() override {}                                                                                           \
    static const char *_state_name() { return #S; }                                                           \
    Box &box() { return *static_cast<Box *>(this->_box()); }                                                  \
    friend class ::Macho::_InitAccess

#define STATE(S) MACHO_STATE_MEMBERS_(S, ::Macho::Link)

/// The state remembers its last active direct substate (see setStateHistory()).
#define HISTORY()                                                                                              \
private:                                                                                                       \
    int _historyKind() const override { return ::Macho::_ShallowHistory; }                                    \
                                                                                                               \
public:                                                                                                        \
    static_assert(true, "")

/// The state remembers its innermost active substate (see setStateHistory()).
#define DEEPHISTORY()                                                                                          \
private:                                                                                                       \
    int _historyKind() const override { return ::Macho::_DeepHistory; }                                       \
                                                                                                               \
public:                                                                                                        \
    static_assert(true, "")

/// The state's Box survives the state being left.
#define PERSISTENT()                                                                                           \
private:                                                                                                       \
    bool _persistentBox() const override { return true; }                                                     \
                                                                                                               \
public:                                                                                                        \
    static_assert(true, "")

namespace Macho
{
using ID = unsigned int;
using Key = void *;

class _MachineBase;
class _StateInstance;
class _StateSpecification;
class _InitAccess;
class Alias;
template <class TOP>
class Machine;
template <class TOP>
class TopBase;
template <class C, class P>
class Link;

enum
{
    _NoHistory = 0,
    _ShallowHistory = 1,
    _DeepHistory = 2
};

/// The Box of a state that declares none.
struct _EmptyBox
{
};

/// What a Key points to: how to find a state class's instance in a machine and what it is.
struct _KeyData
{
    _StateInstance &(*instance)(_MachineBase &);
    bool (*isChild)(Key);
    const char *(*name)();
    ID id;
};

/**
 * The identifier of state class @p S within its machine. Every state's value is defined once in a
 * source file (FSM_INIT_VALUE(S) does it).
 */
template <class S>
class StateID
{
public:
    static const ID value;
};

/// Where a transition goes on after the target's entry: init(), its history, or init(args...).
class _Initializer
{
public:
    virtual ~_Initializer() {}
    virtual void execute(_StateInstance &instance) = 0;
    /// The state an alias built with this initializer stands for.
    virtual Key adapt(Key key) const { return key; }
};

/// Base of every state class: the actions and the transition requests a state can make.
class _StateSpecification
{
public:
    virtual ~_StateSpecification() {}
    static bool isChild(Key) { return false; }

protected:
    explicit _StateSpecification(_StateInstance &instance)
        : m_specInstance(instance)
    {
    }

    /// Transition to @p S (taken when the current action returns).
    template <class S>
    void setState();
    /// Transition to @p S whose init(args...) then runs instead of init().
    template <class S, class... Args>
    void setState(const Args &...args);
    /// Transition to the history of @p S (or to @p S when it has none).
    template <class S>
    void setStateHistory();
    void setState(const Alias &state);
    /// Transition to @p S with @p box (allocated with new) as its Box, entering its history.
    template <class S>
    void setStateBox(typename S::Box *box = nullptr);
    /// Transition to @p S with @p box (allocated with new) as its Box.
    template <class S>
    void setStateDirect(typename S::Box *box = nullptr);

    /// The machine this state object belongs to.
    _MachineBase &_machine() const;

    virtual int _historyKind() const { return _NoHistory; }
    virtual bool _persistentBox() const { return false; }

private:
    virtual void entry() {}
    virtual void exit() {}
    virtual void init() {}

    static _StateInstance &_getInstance(_MachineBase &machine);

    template <class T>
    friend class TopBase;
    template <class C, class P>
    friend class Link;
    friend class _StateInstance;
    friend class _RootInstance;
    friend class _MachineBase;

    _StateInstance &m_specInstance;
};

/**
 * One state of one machine: the state object, its Box, its history and its superstate. Created
 * when the machine first needs the state, kept until the machine goes.
 */
class _StateInstance
{
public:
    virtual ~_StateInstance() { delete m_spec; }

    _MachineBase &machine() const { return m_machine; }
    _StateSpecification &specification() const
    {
        assert(m_spec);
        return *m_spec;
    }
    _StateInstance *parent() const { return m_parent; }
    /// True when this is @p other or one of its substates.
    bool isChild(const _StateInstance &other) const
    {
        for (const _StateInstance *s = this; s != nullptr; s = s->m_parent) {
            if (s == &other)
                return true;
        }
        return false;
    }
    void *box()
    {
        assert(m_box);
        return m_box;
    }
    void setBox(void *box)
    {
        discardBox();
        m_box = box;
    }
    _StateInstance *history() const { return m_history; }
    void setHistory(_StateInstance *history) const { m_history = history; }

    virtual ID id() const = 0;
    virtual Key key() const = 0;
    virtual const char *name() const = 0;

    /// Enters this state and the superstates @p previous is not in (all when @p target).
    void entry(_StateInstance &previous, bool target = true)
    {
        if (m_parent == nullptr || (!target && previous.isChild(*this)))
            return;
        m_parent->entry(previous, false);
        if (m_box == nullptr)
            m_box = createBox();
        m_spec->entry();
    }
    /// Leaves this state and its superstates up to the innermost one that contains @p next.
    void exit(_StateInstance &next)
    {
        if (m_parent == nullptr || (this != &next && next.isChild(*this)))
            return;
        m_spec->exit();
        if (!m_spec->_persistentBox())
            discardBox();
        m_parent->exit(next);
    }
    /// Runs init(), or goes on to the history state when @p useHistory and there is one.
    void init(bool useHistory);
    /// Records this state, just left, in the history of the superstates that keep one.
    void saveHistory()
    {
        _StateInstance *child = this;
        for (_StateInstance *s = m_parent; s != nullptr; child = s, s = s->m_parent) {
            const int kind = s->m_spec ? s->m_spec->_historyKind() : _NoHistory;
            if (kind == _ShallowHistory)
                s->m_history = child;
            else if (kind == _DeepHistory)
                s->m_history = this;
        }
    }

protected:
    _StateInstance(_MachineBase &machine, _StateInstance *parent)
        : m_machine(machine)
        , m_parent(parent)
    {
    }
    virtual void *createBox() = 0;
    virtual void deleteBox(void *box) = 0;
    void discardBox()
    {
        if (m_box != nullptr)
            deleteBox(m_box);
        m_box = nullptr;
    }

    _MachineBase &m_machine;
    _StateInstance *m_parent;
    _StateSpecification *m_spec = nullptr;
    void *m_box = nullptr;
    mutable _StateInstance *m_history = nullptr;
};

/// Creates and deletes the Box of a state; states without one share a single empty box.
template <class B>
struct _BoxMaker
{
    static void *create() { return new B(); }
    static void destroy(void *box) { delete static_cast<B *>(box); }
};
template <>
struct _BoxMaker<_EmptyBox>
{
    static void *create()
    {
        static _EmptyBox empty;
        return &empty;
    }
    static void destroy(void *) {}
};

/// The machine's outermost, invisible state: the superstate of the top state.
class _RootInstance : public _StateInstance
{
public:
    _RootInstance(_MachineBase &machine)
        : _StateInstance(machine, nullptr)
    {
        m_spec = new _StateSpecification(*this);
    }
    ID id() const override { return 0; }
    Key key() const override
    {
        static _KeyData data = {&_StateSpecification::_getInstance, &_StateSpecification::isChild, &rootName, 0};
        return &data;
    }
    const char *name() const override { return rootName(); }

private:
    static const char *rootName() { return "Root"; }
    void *createBox() override { return _BoxMaker<_EmptyBox>::create(); }
    void deleteBox(void *) override {}
};

template <class S>
class _SubstateInstance : public _StateInstance
{
public:
    using Box = typename S::Box;
    _SubstateInstance(_MachineBase &machine, _StateInstance *parent)
        : _StateInstance(machine, parent)
    {
        m_spec = new S(*this);
    }
    ~_SubstateInstance() override { discardBox(); }
    ID id() const override { return StateID<S>::value; }
    Key key() const override { return S::key(); }
    const char *name() const override { return S::_state_name(); }

private:
    void *createBox() override { return _BoxMaker<Box>::create(); }
    void deleteBox(void *box) override { _BoxMaker<Box>::destroy(box); }
};

class _DefaultInitializer : public _Initializer
{
public:
    void execute(_StateInstance &instance) override { instance.init(false); }
};

class _HistoryInitializer : public _Initializer
{
public:
    void execute(_StateInstance &instance) override { instance.init(true); }
};

inline std::shared_ptr<_Initializer> _defaultInit()
{
    static const std::shared_ptr<_Initializer> init = std::make_shared<_DefaultInitializer>();
    return init;
}

inline std::shared_ptr<_Initializer> _historyInit()
{
    static const std::shared_ptr<_Initializer> init = std::make_shared<_HistoryInitializer>();
    return init;
}

/// Compile-time index lists (C++11 has no std::index_sequence).
template <unsigned... I>
struct _Indices
{
};
template <unsigned N, unsigned... I>
struct _MakeIndices : _MakeIndices<N - 1, N - 1, I...>
{
};
template <unsigned... I>
struct _MakeIndices<0, I...>
{
    using type = _Indices<I...>;
};

/// Calls a state's init(args...) (states befriend this class, so their init may be private).
class _InitAccess
{
public:
    template <class S, class Tuple, unsigned... I>
    static void init(_StateInstance &instance, Tuple &args, _Indices<I...>)
    {
        static_cast<S &>(instance.specification()).init(std::get<I>(args)...);
    }
};

template <class S, class... Args>
class _ArgumentInitializer : public _Initializer
{
public:
    explicit _ArgumentInitializer(const Args &...args)
        : m_args(args...)
    {
    }
    void execute(_StateInstance &instance) override
    {
        _InitAccess::init<S>(instance, m_args, typename _MakeIndices<sizeof...(Args)>::type());
    }

private:
    std::tuple<typename std::decay<Args>::type...> m_args;
};

/// Makes an alias stand for the current history of its state (StateHistory()).
class _AdaptingInitializer : public _HistoryInitializer
{
public:
    explicit _AdaptingInitializer(const _MachineBase &machine)
        : m_machine(machine)
    {
    }
    Key adapt(Key key) const override;

private:
    const _MachineBase &m_machine;
};

class _IEventBase
{
public:
    virtual ~_IEventBase() {}
    virtual void dispatch(_StateInstance &instance) = 0;
};

/// An event for machines of top state @p TOP (made with Event()).
template <class TOP>
class IEvent : public _IEventBase
{
};

template <class TOP, class R, class... Params>
class _Event : public IEvent<TOP>
{
public:
    using Handler = R (TOP::*)(Params...);
    template <class... Args>
    _Event(Handler handler, const Args &...args)
        : m_handler(handler)
        , m_args(args...)
    {
    }
    void dispatch(_StateInstance &instance) override
    {
        call(static_cast<TOP &>(instance.specification()), typename _MakeIndices<sizeof...(Params)>::type());
    }

private:
    template <unsigned... I>
    void call(TOP &state, _Indices<I...>)
    {
        (state.*m_handler)(std::get<I>(m_args)...);
    }

    Handler m_handler;
    std::tuple<typename std::decay<Params>::type...> m_args;
};

/**
 * An event: @p handler (a member function of the top state) called with @p args on the state
 * that is current when the event is dispatched. The arguments are copied.
 */
template <class TOP, class R, class... Params, class... Args>
inline IEvent<TOP> *Event(R (TOP::*handler)(Params...), const Args &...args)
{
    static_assert(sizeof...(Params) == sizeof...(Args), "Event(): the handler takes another number of arguments");
    return new _Event<TOP, R, Params...>(handler, args...);
}

/// The machinery every Machine<TOP> shares: the states, the current one and what is pending.
class _MachineBase
{
public:
    /// The current state.
    Alias currentState() const;

    _StateInstance *&getInstance(ID id) { return m_instances.at(id); }
    const _StateInstance *getInstance(ID id) const { return m_instances.at(id); }

    void setPendingState(_StateInstance &instance, const std::shared_ptr<_Initializer> &init)
    {
        m_pendingState = &instance;
        m_pendingInit = init;
    }
    void setPendingEvent(_IEventBase *event)
    {
        assert(event);
        m_pendingEvents.push_back(std::unique_ptr<_IEventBase>(event));
    }
    void setPendingBox(void *box) { m_pendingBox = box; }

protected:
    _MachineBase() {}
    virtual ~_MachineBase()
    {
        for (size_t i = m_instances.size(); i > 0; --i)
            delete m_instances[i - 1];
    }
    _MachineBase(const _MachineBase &) = delete;
    _MachineBase &operator=(const _MachineBase &) = delete;

    void allocate(ID count) { m_instances.assign(count, nullptr); }
    void start(_StateInstance &instance)
    {
        m_current = &_StateSpecification::_getInstance(*this);
        setPendingState(instance, _defaultInit());
        rattleOn();
    }
    void start(const Alias &state);
    /// Leaves every state (exit actions run); the machine has no current state afterwards.
    void shutdown()
    {
        if (m_current == nullptr)
            return;
        m_pendingEvents.clear();
        setPendingState(_StateSpecification::_getInstance(*this), _defaultInit());
        rattleOn();
        m_current = nullptr;
    }
    /// Takes pending transitions and events until none is left.
    void rattleOn()
    {
        assert(m_current);
        while (m_pendingState != nullptr || !m_pendingEvents.empty()) {
            while (m_pendingState != nullptr)
                takeTransition();
            if (!m_pendingEvents.empty()) {
                std::unique_ptr<_IEventBase> event(m_pendingEvents.front().release());
                m_pendingEvents.pop_front();
                event->dispatch(*m_current);
            }
        }
    }
    void clearHistoryDeep(const _StateInstance &instance) const
    {
        for (_StateInstance *s : m_instances) {
            if (s != nullptr && s->isChild(instance))
                s->setHistory(nullptr);
        }
    }

    _StateInstance *m_current = nullptr;

private:
    void takeTransition()
    {
        _StateInstance *next = m_pendingState;
        std::shared_ptr<_Initializer> init = m_pendingInit;
        m_pendingInit.reset();
        m_current->exit(*next);
        m_current->saveHistory();
        _StateInstance *previous = m_current;
        m_current = next;
        if (m_pendingBox != nullptr) {
            next->setBox(m_pendingBox);
            m_pendingBox = nullptr;
        }
        next->entry(*previous);
        m_pendingState = nullptr;
        init->execute(*next);
    }

    template <class C, class P>
    friend class Link;
    friend class _StateSpecification;

    std::vector<_StateInstance *> m_instances;
    _StateInstance *m_pendingState = nullptr;
    std::shared_ptr<_Initializer> m_pendingInit;
    void *m_pendingBox = nullptr;
    std::deque<std::unique_ptr<_IEventBase> > m_pendingEvents;
};

/// A state as a value: its key and how it is to be initialised when a transition goes there.
class Alias
{
public:
    Alias(Key key, bool history = false)
        : m_key(key)
        , m_init(history ? _historyInit() : _defaultInit())
    {
        assert(key);
    }
    Alias(Key key, const std::shared_ptr<_Initializer> &init)
        : m_key(key)
        , m_init(init)
    {
        assert(key);
    }

    operator Key() const { return key(); }
    /// True when this state is the state of @p other or one of its substates.
    bool isChild(Key other) const { return data()->isChild(other); }
    /// True when the state of @p other is this state or one of its substates.
    bool isParent(Key other) const { return static_cast<_KeyData *>(other)->isChild(key()); }
    const char *name() const { return data()->name(); }
    ID id() const { return data()->id; }

    /// Makes this state the machine's pending transition.
    void setState(_MachineBase &machine) const
    {
        machine.setPendingState(data()->instance(machine), m_init);
    }

private:
    Key key() const { return m_init->adapt(m_key); }
    _KeyData *data() const { return static_cast<_KeyData *>(key()); }

    Key m_key;
    std::shared_ptr<_Initializer> m_init;
};

using StateAlias = Alias;

inline Alias _MachineBase::currentState() const
{
    assert(m_current);
    return Alias(m_current->key());
}

inline void _MachineBase::start(const Alias &state)
{
    m_current = &_StateSpecification::_getInstance(*this);
    state.setState(*this);
    rattleOn();
}

inline Key _AdaptingInitializer::adapt(Key key) const
{
    const _StateInstance *instance = m_machine.getInstance(static_cast<_KeyData *>(key)->id);
    const _StateInstance *history = instance != nullptr ? instance->history() : nullptr;
    return history != nullptr ? history->key() : key;
}

inline void _StateInstance::init(bool useHistory)
{
    if (useHistory && m_history != nullptr)
        m_machine.setPendingState(*m_history, _defaultInit());
    else
        m_spec->init();
    m_history = nullptr;
}

inline _StateInstance &_StateSpecification::_getInstance(_MachineBase &machine)
{
    _StateInstance *&instance = machine.getInstance(0);
    if (instance == nullptr)
        instance = new _RootInstance(machine);
    return *instance;
}

inline _MachineBase &_StateSpecification::_machine() const
{
    return m_specInstance.machine();
}

inline void _StateSpecification::setState(const Alias &state)
{
    state.setState(_machine());
}

/// Base of a machine's top state (TOPSTATE / FSM_TOPSTATE): the machine's event handling.
template <class T>
class TopBase : public _StateSpecification
{
public:
    using TOP = T;

protected:
    explicit TopBase(_StateInstance &instance)
        : _StateSpecification(instance)
    {
    }
    /// Queues @p event (from Event()); it is handled after the action that queued it returns.
    void dispatch(IEvent<TOP> *event) { _machine().setPendingEvent(event); }
    const Machine<TOP> &machine() { return static_cast<const Machine<TOP> &>(_machine()); }
};

/**
 * The link between state @p C and its superstate @p P; state classes derive from it (through
 * the TOPSTATE / SUBSTATE macros).
 */
template <class C, class P>
class Link : public P
{
public:
    using SUPER = P;
    using TOP = typename P::TOP;
    using Box = _EmptyBox;

    static Key key()
    {
        static _KeyData data = {&Link::_getInstance, &Link::isChild, &C::_state_name, StateID<C>::value};
        return &data;
    }
    static Alias alias() { return Alias(key()); }
    /// True when C is the state of @p other or one of its substates.
    static bool isChild(Key other) { return key() == other || SUPER::isChild(other); }
    /// True when the state of @p other is C or one of its substates.
    static bool isParent(Key other) { return static_cast<_KeyData *>(other)->isChild(key()); }
    /// True when C or one of its substates is the current state of @p machine.
    static bool isCurrent(const _MachineBase &machine) { return machine.currentState().isChild(key()); }
    /// True when C is the current state of @p machine.
    static bool isCurrentDirect(const _MachineBase &machine) { return key() == Key(machine.currentState()); }
    static void clearHistory(const _MachineBase &machine)
    {
        const _StateInstance *instance = machine.getInstance(StateID<C>::value);
        if (instance != nullptr)
            instance->setHistory(nullptr);
    }
    /// Clears the history of C and of all its substates.
    static void clearHistoryDeep(const _MachineBase &machine)
    {
        const _StateInstance *instance = machine.getInstance(StateID<C>::value);
        if (instance != nullptr)
            machine.clearHistoryDeep(*instance);
    }
    /// C's history state in @p machine (C itself when it has none).
    static Alias history(const _MachineBase &machine)
    {
        const _StateInstance *instance = machine.getInstance(StateID<C>::value);
        const _StateInstance *last = instance != nullptr ? instance->history() : nullptr;
        return Alias(last != nullptr ? last->key() : key());
    }

    static _StateInstance &_getInstance(_MachineBase &machine)
    {
        _StateInstance *&instance = machine.getInstance(StateID<C>::value);
        if (instance == nullptr)
            instance = new _SubstateInstance<C>(machine, &P::_getInstance(machine));
        return *instance;
    }

protected:
    using LINK = Link<C, P>;

    explicit Link(_StateInstance &instance)
        : P(P::_getInstance(instance.machine()))
        , m_linkInstance(instance)
    {
    }
    void entry() override {}
    void init() override {}
    void exit() override {}
    int _historyKind() const override { return _NoHistory; }
    bool _persistentBox() const override { return false; }
    /// C's Box in this machine.
    void *_box() { return m_linkInstance.box(); }

private:
    _StateInstance &m_linkInstance;
};

template <class S>
inline void _StateSpecification::setState()
{
    _MachineBase &m = _machine();
    m.setPendingState(S::_getInstance(m), _defaultInit());
}

template <class S, class... Args>
inline void _StateSpecification::setState(const Args &...args)
{
    _MachineBase &m = _machine();
    m.setPendingState(S::_getInstance(m), std::make_shared<_ArgumentInitializer<S, Args...> >(args...));
}

template <class S>
inline void _StateSpecification::setStateHistory()
{
    _MachineBase &m = _machine();
    m.setPendingState(S::_getInstance(m), _historyInit());
}

template <class S>
inline void _StateSpecification::setStateBox(typename S::Box *box)
{
    _MachineBase &m = _machine();
    m.setPendingBox(box);
    m.setPendingState(S::_getInstance(m), _historyInit());
}

template <class S>
inline void _StateSpecification::setStateDirect(typename S::Box *box)
{
    _MachineBase &m = _machine();
    m.setPendingBox(box);
    m.setPendingState(S::_getInstance(m), _defaultInit());
}

/// An alias of state @p S.
template <class S>
Alias State()
{
    return Alias(S::key());
}

/// An alias of state @p S entered with init(args...).
template <class S, class... Args>
Alias State(const Args &...args)
{
    return Alias(S::key(), std::make_shared<_ArgumentInitializer<S, Args...> >(args...));
}

/// An alias of the history of @p S in @p machine, resolved when the alias is used.
template <class S>
Alias StateHistory(const _MachineBase &machine)
{
    return Alias(S::key(), std::make_shared<_AdaptingInitializer>(machine));
}

/**
 * A running state machine of top state @p TOP. Construction enters TOP (and whatever its init()
 * chooses); destruction leaves every state.
 */
template <class TOP>
class Machine : public _MachineBase
{
public:
    /// Calls one handler of the current state and takes the transitions it asked for afterwards.
    class AfterAdvice
    {
    public:
        explicit AfterAdvice(Machine<TOP> &machine)
            : m_machine(&machine)
        {
        }
        AfterAdvice(AfterAdvice &&other)
            : m_machine(other.m_machine)
        {
            other.m_machine = nullptr;
        }
        AfterAdvice(const AfterAdvice &) = delete;
        AfterAdvice &operator=(const AfterAdvice &) = delete;
        ~AfterAdvice()
        {
            if (m_machine != nullptr)
                m_machine->rattleOn();
        }
        TOP *operator->() { return static_cast<TOP *>(&m_machine->m_current->specification()); }

    private:
        Machine<TOP> *m_machine;
    };

    Machine()
    {
        allocate(theStateCount);
        start(TOP::_getInstance(*this));
    }
    explicit Machine(const Alias &state)
    {
        allocate(theStateCount);
        start(state);
    }
    ~Machine() override { shutdown(); }

    /// `machine->event(args)`: the current state handles the event.
    AfterAdvice operator->()
    {
        assert(m_current);
        return AfterAdvice(*this);
    }
    /// Handles @p event (from Event()) in the current state, then the transitions it caused.
    void dispatch(IEvent<TOP> *event, bool destroy = true)
    {
        assert(event);
        event->dispatch(*m_current);
        if (destroy)
            delete event;
        rattleOn();
    }
    /// The top state's Box.
    const typename TOP::Box &box() const
    {
        return static_cast<TOP &>(TOP::_getInstance(const_cast<Machine &>(*this)).specification()).TOP::box();
    }

    /// The number of states of TOP's machines plus one; each FSM_INIT_VALUE counts one up.
    static ID theStateCount;
};

template <class TOP>
ID Machine<TOP>::theStateCount = 1;

} // namespace Macho

#endif // RTM_MACHO_H
