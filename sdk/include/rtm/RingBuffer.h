// SPDX-License-Identifier: MIT
// A fixed-length ring of values with OpenRTM-aist's buffer policies (FSM components queue their
// events in one).
#ifndef RTM_RINGBUFFER_H
#define RTM_RINGBUFFER_H

#include <rtm/BufferBase.h>

#include <coil/stringutil.h>

#include <algorithm>
#include <condition_variable>
#include <iostream>
#include <mutex>
#include <string>
#include <vector>

#define RINGBUFFER_DEFAULT_LENGTH 8

namespace RTC
{
/**
 * A thread-safe ring buffer. When full, write() overwrites the oldest value (`write.full_policy`
 * overwrite, the default), refuses (do_nothing) or waits up to `write.timeout` seconds (block).
 * When empty, read() gives the last value read again (`read.empty_policy` readback, the
 * default), refuses (do_nothing) or waits up to `read.timeout` seconds (block).
 */
template <class DataType>
class RingBuffer : public BufferBase<DataType>
{
public:
    explicit RingBuffer(long int length = RINGBUFFER_DEFAULT_LENGTH)
        : m_buffer(static_cast<size_t>(std::max(length, 1L)))
    {
    }
    ~RingBuffer() override = default;

    void init(const coil::Properties &prop) override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        long int length = 0;
        if (coil::stringTo(length, prop.getProperty("length").c_str()) && length > 0) {
            m_buffer.assign(static_cast<size_t>(length), DataType());
            clear();
        }
        m_fullPolicy = policy(prop.getProperty("write.full_policy"), m_fullPolicy, "overwrite");
        m_emptyPolicy = policy(prop.getProperty("read.empty_policy"), m_emptyPolicy, "readback");
        seconds(prop.getProperty("write.timeout"), &m_writeTimeout);
        seconds(prop.getProperty("read.timeout"), &m_readTimeout);
    }

    size_t length() const override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_buffer.size();
    }
    BufferStatus length(size_t n) override
    {
        if (n == 0)
            return BufferStatus::BUFFER_ERROR;
        std::lock_guard<std::mutex> lock(m_mutex);
        m_buffer.assign(n, DataType());
        clear();
        return BufferStatus::OK;
    }
    BufferStatus reset() override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        clear();
        return BufferStatus::OK;
    }

    DataType *wptr(long int n = 0) override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return &m_buffer[slot(m_write, n)];
    }
    BufferStatus advanceWptr(long int n = 1, bool unlock_enable = true) override
    {
        (void)unlock_enable;
        std::lock_guard<std::mutex> lock(m_mutex);
        return advanceWrite(n);
    }
    BufferStatus put(const DataType &value) override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_buffer[m_write] = value;
        return BufferStatus::OK;
    }
    BufferStatus write(const DataType &value, std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1)) override
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        if (m_fill == m_buffer.size()) {
            if (m_fullPolicy == DoNothing)
                return BufferStatus::FULL;
            if (m_fullPolicy == Overwrite) {
                advanceRead(1);
            } else if (!m_notFull.wait_for(lock, timeout.count() < 0 ? m_writeTimeout : timeout,
                                           [this] { return m_fill < m_buffer.size(); })) {
                return BufferStatus::TIMEOUT;
            }
        }
        m_buffer[m_write] = value;
        advanceWrite(1);
        return BufferStatus::OK;
    }
    size_t writable() const override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_buffer.size() - m_fill;
    }
    bool full() const override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_fill == m_buffer.size();
    }

    DataType *rptr(long int n = 0) override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return &m_buffer[slot(m_read, n)];
    }
    BufferStatus advanceRptr(long int n = 1, bool unlock_enable = true) override
    {
        (void)unlock_enable;
        std::lock_guard<std::mutex> lock(m_mutex);
        return advanceRead(n);
    }
    BufferStatus get(DataType &value) override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        value = m_buffer[m_read];
        return BufferStatus::OK;
    }
    DataType &get() override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_buffer[m_read];
    }
    BufferStatus read(DataType &value, std::chrono::nanoseconds timeout = std::chrono::nanoseconds(-1)) override
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        if (m_fill == 0) {
            if (m_emptyPolicy == DoNothing)
                return BufferStatus::EMPTY;
            if (m_emptyPolicy == Overwrite) { // readback: the last value read once more
                if (!m_everRead)
                    return BufferStatus::EMPTY;
                value = m_buffer[slot(m_read, -1)];
                return BufferStatus::OK;
            }
            if (!m_notEmpty.wait_for(lock, timeout.count() < 0 ? m_readTimeout : timeout,
                                     [this] { return m_fill > 0; }))
                return BufferStatus::TIMEOUT;
        }
        value = m_buffer[m_read];
        advanceRead(1);
        m_everRead = true;
        return BufferStatus::OK;
    }
    size_t readable() const override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_fill;
    }
    bool empty() const override
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_fill == 0;
    }

private:
    // Overwrite stands for readback on the read side: the policy that never refuses or waits.
    enum Policy
    {
        Overwrite,
        DoNothing,
        Block
    };

    static Policy policy(std::string text, Policy current, const char *never)
    {
        text = coil::normalize(text);
        if (text == never)
            return Overwrite;
        if (text == "do_nothing")
            return DoNothing;
        if (text == "block")
            return Block;
        return current;
    }
    static void seconds(const std::string &text, std::chrono::nanoseconds *timeout)
    {
        double value = 0.0;
        if (!text.empty() && coil::stringTo(value, text.c_str()) && value >= 0.0)
            *timeout = std::chrono::nanoseconds(static_cast<long long>(value * 1e9));
    }

    size_t slot(size_t from, long int n) const
    {
        const long int size = static_cast<long int>(m_buffer.size());
        return static_cast<size_t>(((static_cast<long int>(from) + n) % size + size) % size);
    }
    void clear()
    {
        m_read = m_write = m_fill = 0;
        m_everRead = false;
    }
    BufferStatus advanceWrite(long int n)
    {
        const long int fill = static_cast<long int>(m_fill);
        if (n > static_cast<long int>(m_buffer.size()) - fill || -n > fill)
            return BufferStatus::PRECONDITION_NOT_MET;
        m_write = slot(m_write, n);
        m_fill = static_cast<size_t>(fill + n);
        m_notEmpty.notify_all();
        return BufferStatus::OK;
    }
    BufferStatus advanceRead(long int n)
    {
        const long int fill = static_cast<long int>(m_fill);
        if (n > fill || -n > static_cast<long int>(m_buffer.size()) - fill)
            return BufferStatus::PRECONDITION_NOT_MET;
        m_read = slot(m_read, n);
        m_fill = static_cast<size_t>(fill - n);
        m_notFull.notify_all();
        return BufferStatus::OK;
    }

    mutable std::mutex m_mutex;
    std::condition_variable m_notFull;
    std::condition_variable m_notEmpty;
    std::vector<DataType> m_buffer;
    size_t m_read = 0;
    size_t m_write = 0;
    size_t m_fill = 0;
    bool m_everRead = false;
    Policy m_fullPolicy = Overwrite;
    Policy m_emptyPolicy = Overwrite;
    std::chrono::nanoseconds m_writeTimeout = std::chrono::nanoseconds(0);
    std::chrono::nanoseconds m_readTimeout = std::chrono::nanoseconds(0);
};
} // namespace RTC

#endif // RTM_RINGBUFFER_H
