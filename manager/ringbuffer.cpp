// SPDX-License-Identifier: MIT
#include "ringbuffer.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace Runtime {

namespace {

std::string lower(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

/// A timeout in seconds; one that is not a number keeps @p fallback.
std::chrono::milliseconds timeout(const Properties &p, const std::string &key, std::chrono::milliseconds fallback)
{
    const double seconds = p.number(key, std::nan(""));
    if (std::isnan(seconds))
        return fallback;
    return std::chrono::ceil<std::chrono::milliseconds>(boundedSeconds(seconds));
}

} // namespace

RingBuffer::RingBuffer(const Properties &p)
{
    try {
        const long length = std::stol(p.value("length", "8"));
        m_length = size_t(std::max(1L, length));
    } catch (...) {
        m_length = 8;
    }
    const std::string full = lower(p.value("write.full_policy", "overwrite"));
    m_fullPolicy = full == "block" ? FullPolicy::Block
                   : full == "do_nothing" ? FullPolicy::DoNothing
                                           : FullPolicy::Overwrite;
    const std::string empty = lower(p.value("read.empty_policy", "readback"));
    m_emptyPolicy = empty == "block" ? EmptyPolicy::Block
                    : empty == "do_nothing" ? EmptyPolicy::DoNothing
                                             : EmptyPolicy::Readback;
    m_writeTimeout = timeout(p, "write.timeout", m_writeTimeout);
    m_readTimeout = timeout(p, "read.timeout", m_readTimeout);
}

RingBuffer::Status RingBuffer::write(CdrBytes data)
{
    return write(std::make_shared<const CdrSample>(std::move(data)));
}

RingBuffer::Status RingBuffer::write(SharedCdr data)
{
    std::unique_lock lock(m_mutex);
    if (m_samples.size() >= m_length) {
        switch (m_fullPolicy) {
        case FullPolicy::Overwrite:
            m_samples.pop_front();
            break;
        case FullPolicy::DoNothing:
            return Status::Full;
        case FullPolicy::Block:
            if (!m_changed.wait_for(lock, m_writeTimeout,
                                    [this] { return m_closed || m_samples.size() < m_length; })
                || m_closed)
                return Status::Timeout;
            break;
        }
    }
    m_samples.push_back(std::move(data));
    m_changed.notify_all();
    return Status::Ok;
}

RingBuffer::Status RingBuffer::read(SharedCdr *data)
{
    std::unique_lock lock(m_mutex);
    if (m_samples.empty()) {
        switch (m_emptyPolicy) {
        case EmptyPolicy::Readback:
            if (!m_last)
                return Status::Empty;
            *data = m_last;
            return Status::Ok;
        case EmptyPolicy::DoNothing:
            return Status::Empty;
        case EmptyPolicy::Block:
            if (!m_changed.wait_for(lock, m_readTimeout, [this] { return m_closed || !m_samples.empty(); })
                || m_samples.empty())
                return Status::Timeout;
            break;
        }
    }
    m_last = std::move(m_samples.front());
    m_samples.pop_front();
    *data = m_last;
    m_changed.notify_all();
    return Status::Ok;
}

RingBuffer::Status RingBuffer::read(CdrBytes *data)
{
    SharedCdr sample;
    const Status status = read(&sample);
    if (status == Status::Ok)
        *data = sample->view().bytes();
    return status;
}

size_t RingBuffer::readable() const
{
    std::lock_guard lock(m_mutex);
    return m_samples.size();
}

void RingBuffer::close()
{
    std::lock_guard lock(m_mutex);
    m_closed = true;
    m_changed.notify_all();
}

} // namespace Runtime
