// SPDX-License-Identifier: MIT
// What data port operations (and their connectors, publishers, providers, consumers) return.
#ifndef RTC_DATAPORTSTATUS_H
#define RTC_DATAPORTSTATUS_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace RTC {
/// The result of a data port operation, with OpenRTM-aist 2.x's enumerators.
enum class DataPortStatus : uint8_t {
    PORT_OK = 0,
    PORT_ERROR,
    BUFFER_ERROR,
    BUFFER_FULL,
    BUFFER_EMPTY,
    BUFFER_TIMEOUT,
    SEND_FULL,
    SEND_TIMEOUT,
    RECV_EMPTY,
    RECV_TIMEOUT,
    INVALID_ARGS,
    PRECONDITION_NOT_MET,
    CONNECTION_LOST,
    UNKNOWN_ERROR
};

/// The status's enumerator name (`PORT_OK`, `BUFFER_FULL`, …).
inline const char *toString(DataPortStatus status)
{
    static const char *const names[]
        = {"PORT_OK",         "PORT_ERROR",     "BUFFER_ERROR", "BUFFER_FULL",
           "BUFFER_EMPTY",    "BUFFER_TIMEOUT", "SEND_FULL",    "SEND_TIMEOUT",
           "RECV_EMPTY",      "RECV_TIMEOUT",   "INVALID_ARGS", "PRECONDITION_NOT_MET",
           "CONNECTION_LOST", "UNKNOWN_ERROR"};
    const std::size_t index = static_cast<std::size_t>(status);
    return index < sizeof(names) / sizeof(names[0]) ? names[index] : "";
}

/// One status per connector (OutPort::getStatusList()).
using DataPortStatusList = std::vector<DataPortStatus>;
} // namespace RTC

#endif // RTC_DATAPORTSTATUS_H
