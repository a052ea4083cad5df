// SPDX-License-Identifier: MIT
// What buffer operations return.
#ifndef RTM_BUFFERSTATUS_H
#define RTM_BUFFERSTATUS_H

#include <cstdint>

namespace RTC
{
/// Result of a buffer operation (RingBuffer).
enum class BufferStatus : uint8_t
{
    OK = 0,
    BUFFER_ERROR,
    FULL,
    EMPTY,
    NOT_SUPPORTED,
    TIMEOUT,
    PRECONDITION_NOT_MET
};

/// The status's name (`BUFFER_OK`, `BUFFER_FULL`, …).
inline const char *toString(BufferStatus status)
{
    static const char *const names[] = {"BUFFER_OK",     "BUFFER_ERROR", "BUFFER_FULL",         "BUFFER_EMPTY",
                                        "NOT_SUPPORTED", "TIMEOUT",      "PRECONDITION_NOT_MET"};
    const unsigned index = static_cast<unsigned>(status);
    return index < sizeof(names) / sizeof(names[0]) ? names[index] : "";
}
} // namespace RTC

#endif // RTM_BUFFERSTATUS_H
