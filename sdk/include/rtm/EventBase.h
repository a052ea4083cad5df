// SPDX-License-Identifier: MIT
// Events queued by an FSM component's EventInPort until onExecute runs them.
#ifndef RTM_EVENTBASE_H
#define RTM_EVENTBASE_H

namespace RTC
{
/// Something that dispatches an event without an argument to a state machine.
class EventBinderBase0
{
public:
    EventBinderBase0() = default;
    virtual ~EventBinderBase0() = default;
    virtual void run() = 0;
};

/// Something that dispatches an event with an argument of type @p P0 to a state machine.
template <class P0>
class EventBinderBase1
{
public:
    EventBinderBase1() = default;
    virtual ~EventBinderBase1() = default;
    virtual void run(P0 &data) = 0;
};

/// A queued event; calling it dispatches it.
class EventBase
{
public:
    EventBase() = default;
    virtual ~EventBase() = default;
    virtual void operator()() = 0;
};

/// A queued event without an argument.
class Event0 : public EventBase
{
public:
    explicit Event0(EventBinderBase0 *eb)
        : m_eb(eb)
    {
    }
    ~Event0() override = default;
    void operator()() override { m_eb->run(); }

private:
    EventBinderBase0 *m_eb;
};

/// A queued event with a copy of the sample that raised it.
template <class P0>
class Event1 : public EventBase
{
public:
    Event1(EventBinderBase1<P0> *eb, P0 &data)
        : m_eb(eb)
        , m_data(data)
    {
    }
    ~Event1() override = default;
    void operator()() override { m_eb->run(m_data); }

private:
    EventBinderBase1<P0> *m_eb;
    P0 m_data;
};
} // namespace RTC

#endif // RTM_EVENTBASE_H
