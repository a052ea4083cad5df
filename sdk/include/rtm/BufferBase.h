// SPDX-License-Identifier: MIT
// The interface of OpenRTM-aist's data buffers.
#ifndef RTM_BUFFERBASE_H
#define RTM_BUFFERBASE_H

#include <rtm/BufferStatus.h>

#include <coil/Properties.h>

#include <chrono>
#include <cstddef>
#include <mutex>

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
/**
 * A buffer of one slot that never fills: each write replaces the value, each read gives the
 * latest value written (empty only before the first write or after reset()). Its length is 1
 * and cannot change.
 */
template <class DataType>
class NullBuffer : public BufferBase<DataType>
{
public:
    explicit NullBuffer(long int size = 1)
        : m_length(size)
        , m_data()
        , m_hasData(false)
    {
    }
    ~NullBuffer() override = default;

    void init(const coil::Properties &) override {}
    size_t length() const override { return 1; }
    BufferStatus length(size_t n) override { return n == 1 ? BufferStatus::OK : BufferStatus::NOT_SUPPORTED; }
    BufferStatus reset() override
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_hasData = false;
        return BufferStatus::OK;
    }
    DataType *wptr(long int = 0) override { return &m_data; }
    BufferStatus advanceWptr(long int = 1, bool = true) override
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_hasData = true;
        return BufferStatus::OK;
    }
    BufferStatus put(const DataType &value) override
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_data = value;
        return BufferStatus::OK;
    }
    BufferStatus write(const DataType &value, std::chrono::nanoseconds = std::chrono::nanoseconds(-1)) override
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        m_data = value;
        m_hasData = true;
        return BufferStatus::OK;
    }
    size_t writable() const override { return 1; }
    bool full() const override { return false; }
    DataType *rptr(long int = 0) override { return &m_data; }
    BufferStatus advanceRptr(long int = 1, bool = true) override { return BufferStatus::OK; }
    BufferStatus get(DataType &value) override
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        if (!m_hasData)
            return BufferStatus::EMPTY;
        value = m_data;
        return BufferStatus::OK;
    }
    DataType &get() override { return m_data; }
    BufferStatus read(DataType &value, std::chrono::nanoseconds = std::chrono::nanoseconds(-1)) override
    {
        return get(value);
    }
    size_t readable() const override
    {
        std::lock_guard<std::mutex> guard(m_mutex);
        return m_hasData ? 1 : 0;
    }
    bool empty() const override { return readable() == 0; }

private:
    long int m_length; // as given; the buffer holds one value whatever it is
    DataType m_data;
    bool m_hasData;
    mutable std::mutex m_mutex;
};
} // namespace RTC
#endif // RTM_BUFFERBASE_H
