// SPDX-License-Identifier: MIT
// Callback objects a data port calls around its reads and writes and its connections.
#ifndef RTC_PORTCALLBACK_H
#define RTC_PORTCALLBACK_H

#include <rtm/RTC.h>

class cdrStream;

namespace RTC {
/// Called with a connector profile at a step of connecting (PortBase::setOnConnected, …).
class ConnectionCallback
{
public:
    virtual ~ConnectionCallback() = default;
    virtual void operator()(RTC::ConnectorProfile &profile) = 0;
};

/// Called with the id of a connector being removed.
class DisconnectCallback
{
public:
    virtual ~DisconnectCallback() = default;
    virtual void operator()(const char *connector_id) = 0;
};

/// OutPort<DataType>::setOnWrite: called with each value just before it is written.
template<class DataType> class OnWrite
{
public:
    virtual ~OnWrite() = default;
    virtual void operator()(const DataType &value) = 0;
};

/// OutPort<DataType>::setOnWriteConvert: returns the value sent in place of the one written.
template<class DataType> struct OnWriteConvert
{
    virtual ~OnWriteConvert() = default;
    virtual DataType operator()(const DataType &value) = 0;
};

/// InPort<DataType>::setOnRead: called before each read.
template<class DataType> struct OnRead
{
    virtual ~OnRead() = default;
    virtual void operator()() = 0;
};

/// InPort<DataType>::setOnReadConvert: returns the value the bound variable gets in place of the
/// one read.
template<class DataType> struct OnReadConvert
{
    virtual ~OnReadConvert() = default;
    virtual DataType operator()(const DataType &value) = 0;
};

// The callbacks below are OpenRTM-aist 0.4's, which 2.x no longer declares; RT Studio keeps
// them so that components of that time still build (InPort::setOnUnderflow, OutPort::setOnOverflow,
// …).

/// InPort<DataType>::setOnUnderflow: a read that finds no data gives the bound variable what this
/// returns.
template<class DataType> struct OnUnderflow
{
    virtual ~OnUnderflow() = default;
    virtual DataType operator()() = 0;
};

/// OutPort<DataType>::setOnOverflow: called with a value a connection's buffer had no room for.
template<class DataType> struct OnOverflow
{
    virtual ~OnOverflow() = default;
    virtual void operator()(const DataType &value) = 0;
};

/// OutPort<DataType>::setOnWriteTimeout: called with a value whose sending timed out.
template<class DataType> struct OnWriteTimeout
{
    virtual ~OnWriteTimeout() = default;
    virtual void operator()(const DataType &value) = 0;
};

/// InPort<DataType>::setOnReadTimeout: a read that timed out gives the bound variable what this
/// returns.
template<class DataType> struct OnReadTimeout
{
    virtual ~OnReadTimeout() = default;
    virtual DataType operator()() = 0;
};
} // namespace RTC

#endif // RTC_PORTCALLBACK_H
