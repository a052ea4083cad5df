// SPDX-License-Identifier: MIT
// EventInPort: the port through which an FSM component receives its events. Its data type is
// "any", so an OutPort of any type connects to it; each connection carries one event, named by
// the connector property `fsm_event_name` (`dataport.fsm_event_name` in the connector profile) or
// else by the connector's name. A received sample becomes an event in the machine's queue, with
// the sample (decoded as the handler's argument type) as argument when the handler takes one;
// onExecute runs the queue with run_event().
//
//   RTC::Machine<Top> m_fsm;  RTC::EventInPort<RTC::Machine<Top> > m_eventIn;   // m_fsm(this), m_eventIn("event", m_fsm)
//   addInPort("event", m_eventIn);
//   m_eventIn.bindEvent("open", &Top::open);        // void Top::open()
//   m_eventIn.bindEvent("minute", &Top::minute);    // void Top::minute(RTC::TimedLong)
#ifndef RTM_EVENTPORT_H
#define RTM_EVENTPORT_H

#include <rtm/EventBase.h>
#include <rtm/InPortBase.h>
#include <rtm/RTC.h>
#include <rtm/RingBuffer.h>
#include <rtm/StaticFSM.h>
#include <rtm/Timestamp.h>

#include <iostream>
#include <mutex>
#include <string>
#include <sys/utsname.h>
#include <type_traits>
#include <vector>

namespace RTC
{
/// True when a sample that came through the connection @p info is the event @p eventName.
inline bool isFsmEvent(const ConnectorInfo &info, const std::string &eventName)
{
    return info.properties.getProperty("fsm_event_name") == eventName || info.name == eventName;
}

/// Queues @p event in @p buffer; an event that finds the queue full is dropped.
inline void queueFsmEvent(RingBuffer<EventBase *> &buffer, EventBase *event)
{
    if (buffer.full() || buffer.write(event) != BufferStatus::OK)
        delete event;
}

/// Turns each sample of the connections of one event into a call of a handler without argument.
template <class FSM, class TOP, class R>
class EventBinder0 : public ConnectorDataListener, public EventBinderBase0
{
public:
    USE_CONNLISTENER_STATUS;
    EventBinder0(FSM &fsm, const char *event_name, R (TOP::*handler)(), RingBuffer<EventBase *> &buffer)
        : m_fsm(fsm)
        , m_eventName(event_name)
        , m_handler(handler)
        , m_buffer(buffer)
    {
    }
    ~EventBinder0() override = default;

    ReturnCode operator()(ConnectorInfo &info, ByteData &data, const std::string &marshalingtype) override
    {
        (void)data;
        (void)marshalingtype;
        if (isFsmEvent(info, m_eventName))
            queueFsmEvent(m_buffer, new Event0(this));
        return NO_CHANGE;
    }
    void run() override { m_fsm.dispatch(Macho::Event(m_handler)); }

    FSM &m_fsm;
    std::string m_eventName;
    R (TOP::*m_handler)();
    RingBuffer<EventBase *> &m_buffer;
};

/// Turns each sample of the connections of one event into a call of a handler taking the sample.
template <class FSM, class TOP, class R, class P0>
class EventBinder1 : public ConnectorDataListenerT<typename std::decay<P0>::type>,
                     public EventBinderBase1<typename std::decay<P0>::type>
{
public:
    USE_CONNLISTENER_STATUS;
    using DataType = typename std::decay<P0>::type;
    EventBinder1(FSM &fsm, const char *event_name, R (TOP::*handler)(P0), RingBuffer<EventBase *> &buffer)
        : m_fsm(fsm)
        , m_eventName(event_name)
        , m_handler(handler)
        , m_buffer(buffer)
    {
    }
    ~EventBinder1() override = default;

    using ConnectorDataListenerT<DataType>::operator();
    ReturnCode operator()(ConnectorInfo &info, DataType &data) override
    {
        if (isFsmEvent(info, m_eventName))
            queueFsmEvent(m_buffer, new Event1<DataType>(this, data));
        return NO_CHANGE;
    }
    void run(DataType &data) override { m_fsm.dispatch(Macho::Event(m_handler, data)); }

    FSM &m_fsm;
    std::string m_eventName;
    R (TOP::*m_handler)(P0);
    RingBuffer<EventBase *> &m_buffer;
};

/// Applies a new connection's buffer properties (`buffer.*`, `inport.buffer.*`) to the event queue.
class EventConnListener : public ConnectorListener
{
public:
    USE_CONNLISTENER_STATUS;
    explicit EventConnListener(RingBuffer<EventBase *> &buffer)
        : m_buffer(buffer)
    {
    }
    ~EventConnListener() override = default;

    ReturnCode operator()(ConnectorInfo &info) override
    {
        coil::Properties prop(info.properties.getNode("buffer"));
        prop << info.properties.getNode("inport.buffer");
        m_buffer.init(prop);
        return NO_CHANGE;
    }

    RingBuffer<EventBase *> &m_buffer;
};

/**
 * The InPort of an FSM component's events (data type "any"), for a machine of type @p FsmType
 * (an RTC::Machine<TOP>). Bind each event name to a handler of the top state with bindEvent().
 */
template <class FsmType>
class EventInPort : public InPortBase
{
public:
    EventInPort(const char *name, FsmType &fsm)
        : InPortBase(name, "any")
        , m_name(name)
        , m_fsm(fsm)
        , m_buffer(fsm.getBuffer())
    {
        addConnectorListener(ConnectorListenerType::ON_CONNECT, new EventConnListener(m_buffer));
    }
    ~EventInPort() override = default;

    virtual const char *name() { return m_name.c_str(); }

    /// Samples of the connections of event @p name call @p handler with the sample.
    template <class TOP, class R, class P0>
    void bindEvent(const char *name, R (TOP::*handler)(P0))
    {
        addConnectorDataListener(ConnectorDataListenerType::ON_RECEIVED,
                                 new EventBinder1<FsmType, TOP, R, P0>(m_fsm, name, handler, m_buffer));
    }
    /// Samples of the connections of event @p name call @p handler.
    template <class TOP, class R>
    void bindEvent(const char *name, R (TOP::*handler)())
    {
        addConnectorDataListener(ConnectorDataListenerType::ON_RECEIVED,
                                 new EventBinder0<FsmType, TOP, R>(m_fsm, name, handler, m_buffer));
    }

    /// Events are taken as they arrive: there is nothing to read.
    bool read(std::string name = "") override
    {
        (void)name;
        return true;
    }

private:
    std::string m_name;
    FsmType &m_fsm;
    RingBuffer<EventBase *> &m_buffer;
};
} // namespace RTC

#endif // RTM_EVENTPORT_H
