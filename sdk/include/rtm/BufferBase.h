// SPDX-License-Identifier: MIT
// The interface of OpenRTM-aist's data buffers.
#ifndef RTM_BUFFERBASE_H
#define RTM_BUFFERBASE_H

#include <rtm/BufferStatus.h>

#include <coil/Properties.h>

#include <chrono>
#include <cstddef>

namespace RTC
{
/**
 * A FIFO of @p DataType with a write and a read position. put()/get() and the pointer
 * operations do not wait; write()/read() follow the buffer's full and empty policies.
 */
template <class DataType>
class BufferBase
{
public:
    virtual ~BufferBase() = default;
    /// Applies `length`, `write.full_policy`, `write.timeout`, `read.empty_policy`, `read.timeout`.
    virtual void init(const coil::Properties &prop) = 0;
    virtual size_t length() const = 0;
    virtual BufferStatus length(size_t n) = 0;
    /// Empties the buffer.
    virtual BufferStatus reset() = 0;
    /// The slot @p n places after the write position.
    virtual DataType *wptr(long int n = 0) = 0;
    virtual BufferStatus advanceWptr(long int n = 1, bool unlock_enable = true) = 0;
    /// Stores @p value at the write position without advancing it.
    virtual BufferStatus put(const DataType &value) = 0;
    /// Appends @p value, waiting up to @p timeout (negative: the configured one) when full and blocking.
    virtual BufferStatus write(const DataType &value, std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1)) = 0;
    virtual size_t writable() const = 0;
    virtual bool full() const = 0;
    /// The slot @p n places after the read position.
    virtual DataType *rptr(long int n = 0) = 0;
    virtual BufferStatus advanceRptr(long int n = 1, bool unlock_enable = true) = 0;
    /// Copies the value at the read position without advancing it.
    virtual BufferStatus get(DataType &value) = 0;
    virtual DataType &get() = 0;
    /// Takes the oldest value, waiting up to @p timeout (negative: the configured one) when empty and blocking.
    virtual BufferStatus read(DataType &value, std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1)) = 0;
    virtual size_t readable() const = 0;
    virtual bool empty() const = 0;
};
} // namespace RTC

#endif // RTM_BUFFERBASE_H
