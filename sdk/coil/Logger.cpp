// SPDX-License-Identifier: MIT
#include <coil/Logger.h>

#include <algorithm>

namespace coil {
LogStreamBuffer::LogStreamBuffer() = default;

LogStreamBuffer::~LogStreamBuffer()
{
    for (Stream &s : m_streams) {
        if (s.cleanup_)
            delete s.stream_;
    }
}

// Stream's copy constructor drops ownership (so that only one entry ever deletes a buffer), and
// the vector copies entries when it grows or erases: these two note and restore the owners.
static std::vector<bool> owners(const std::vector<LogStreamBuffer::Stream> &streams)
{
    std::vector<bool> result;
    for (const LogStreamBuffer::Stream &s : streams)
        result.push_back(s.cleanup_);
    return result;
}

static void restoreOwners(std::vector<LogStreamBuffer::Stream> &streams, const std::vector<bool> &flags)
{
    for (size_t i = 0; i < streams.size() && i < flags.size(); ++i)
        streams[i].cleanup_ = flags[i];
}

void LogStreamBuffer::addStream(LogStreamBuffer *stream, bool cleanup)
{
    std::vector<bool> flags = owners(m_streams);
    flags.push_back(cleanup);
    m_streams.emplace_back(stream, cleanup);
    restoreOwners(m_streams, flags);
}

bool LogStreamBuffer::removeStream(LogStreamBuffer *stream)
{
    for (size_t i = 0; i < m_streams.size(); ++i) {
        if (m_streams[i].stream_ != stream)
            continue;
        std::vector<bool> flags = owners(m_streams);
        flags.erase(flags.begin() + static_cast<std::ptrdiff_t>(i));
        m_streams.erase(m_streams.begin() + static_cast<std::ptrdiff_t>(i));
        restoreOwners(m_streams, flags);
        return true;
    }
    return false;
}

std::vector<LogStreamBuffer *> LogStreamBuffer::getBuffers()
{
    std::vector<LogStreamBuffer *> buffers;
    buffers.reserve(m_streams.size());
    for (const Stream &s : m_streams)
        buffers.push_back(s.stream_);
    return buffers;
}

void LogStreamBuffer::write(int level, const std::string &name, const std::string &date,
                            const std::string &mes)
{
    for (Stream &s : m_streams) {
        std::lock_guard<std::mutex> guard(s.mutex_);
        s.stream_->write(level, name, date, mes);
    }
}

void LogStreamBuffer::flush()
{
    for (Stream &s : m_streams) {
        std::lock_guard<std::mutex> guard(s.mutex_);
        s.stream_->flush();
    }
}

bool LogStream::m_lockEnable = true;
std::mutex LogStream::m_mutex;

LogStream::LogStream(LogStreamBuffer *sb, int levelmin, int levelmax, int level)
    : ostream_type(sb)
    , m_minLevel(levelmin)
    , m_maxLevel(levelmax)
    , m_logLevel(std::min(std::max(level, levelmin), levelmax))
{ }

bool LogStream::setLevel(int level)
{
    if (level < m_minLevel || level > m_maxLevel)
        return false;
    m_logLevel = level;
    return true;
}

int LogStream::getLevel() const
{
    return m_logLevel;
}

void LogStream::enableLock()
{
    m_lockEnable = true;
}

void LogStream::disableLock()
{
    m_lockEnable = false;
}

void LogStream::flush()
{
    if (ostream_type != nullptr)
        ostream_type->flush();
}
} // namespace coil
