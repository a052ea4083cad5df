// SPDX-License-Identifier: MIT
// Time stamps of data samples.
#ifndef RTM_TIMESTAMP_H
#define RTM_TIMESTAMP_H

#include <rtm/ConnectorListener.h>

#include <chrono>
#include <string>

/// Sets `data.tm` (seconds and nanoseconds since the epoch) to the current time.
template <class DataType>
void setTimestamp(DataType &data)
{
    const std::chrono::nanoseconds since =
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch());
    data.tm.sec = static_cast<decltype(data.tm.sec)>(since.count() / 1000000000);
    data.tm.nsec = static_cast<decltype(data.tm.nsec)>(since.count() % 1000000000);
}

namespace RTC
{
/// A data listener that stamps samples when the connector's `timestamp_policy` equals its type.
template <class DataType>
class Timestamp : public ConnectorDataListenerT<DataType>
{
    USE_CONNLISTENER_STATUS;

public:
    explicit Timestamp(const char *ts_type) : m_tstype(ts_type) {}
    ReturnCode operator()(ConnectorInfo &info, DataType &data) override
    {
        if (info.properties.getProperty("timestamp_policy") != m_tstype)
            return NO_CHANGE;
        setTimestamp(data);
        return DATA_CHANGED;
    }

private:
    std::string m_tstype;
};
} // namespace RTC

#endif // RTM_TIMESTAMP_H
