// SPDX-License-Identifier: MIT
/*!
 * @file Logger.h
 * @brief coil::LogStreamBuffer and coil::LogStream: the base of OpenRTM-aist's logging.
 *
 * A LogStreamBuffer receives finished log lines (level, logger name, date, message) and hands
 * them on to the buffers added to it; subclasses override write() to put lines somewhere (a
 * file, a console, a remote log service). A LogStream filters lines by level and writes the
 * ones that pass through its buffer; RTC::Logger is one.
 */
#ifndef LOGGER_H
#define LOGGER_H

#include <climits>
#include <cstring>
#include <fstream>
#include <iostream>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace coil {
/*! Receives log lines and fans them out to the buffers added to it. */
class LogStreamBuffer
{
public:
    LogStreamBuffer();
    virtual ~LogStreamBuffer();
    /*! Adds @p stream as a destination; with @p cleanup this buffer deletes it when done. */
    void addStream(LogStreamBuffer *stream, bool cleanup = false);
    /*! Removes @p stream (not deleting it); false when it was not added. */
    bool removeStream(LogStreamBuffer *stream);
    /*! The destinations, in the order they were added. */
    std::vector<LogStreamBuffer *> getBuffers();
    /*! Writes one line to every destination. */
    virtual void write(int level, const std::string &name, const std::string &date,
                       const std::string &mes);
    /*! Flushes every destination. */
    virtual void flush();

    /*! A destination and whether its buffer owns it. Copies never own. */
    struct Stream
    {
        explicit Stream(LogStreamBuffer *stream, bool cleanup = false) noexcept
            : stream_(stream)
            , cleanup_(cleanup)
        { }
        virtual ~Stream() = default;
        Stream(const Stream &x) noexcept
            : stream_(x.stream_)
            , cleanup_(false)
        { }
        Stream &operator=(const Stream &x)
        {
            Stream tmp(x);
            tmp.swap(*this);
            return *this;
        }
        void swap(Stream &x)
        {
            std::swap(stream_, x.stream_);
            std::swap(cleanup_, x.cleanup_);
        }
        mutable std::mutex mutex_;
        LogStreamBuffer *stream_;
        bool cleanup_;
    };

private:
    LogStreamBuffer(const LogStreamBuffer &x);
    LogStreamBuffer &operator=(const LogStreamBuffer &x);

    std::vector<Stream> m_streams;
};

/*!
 * A level-filtered log stream over a LogStreamBuffer. Levels are numbers between the minimum
 * and maximum given at construction; a line of level L is written when
 * minimum <= L <= the current level. Subclasses format lines in write().
 */
class LogStream
{
public:
    LogStream(LogStreamBuffer *sb, int levelmin, int levelmax, int level);
    /*! Sets the current level; false (level unchanged) when outside [min, max]. */
    bool setLevel(int level);
    int getLevel() const;
    /*! Writes @p mes at @p level (called only for valid levels). */
    virtual void write(int level, const std::string &mes) = 0;
    /*! Makes lock()/unlock() take the process-wide log lock (the default). */
    static void enableLock();
    /*! Makes lock()/unlock() do nothing, for single-threaded programs. */
    static void disableLock();
    /*! Flushes the buffer. */
    void flush();
    /*! True when lines of @p level are written. */
    inline bool isValid(int level) const { return m_minLevel <= level && level <= m_logLevel; }
    static inline void lock()
    {
        if (m_lockEnable)
            m_mutex.lock();
    }
    static inline void unlock()
    {
        if (m_lockEnable)
            m_mutex.unlock();
    }

protected:
    virtual ~LogStream() = default;
    /*! The buffer lines are written to. */
    LogStreamBuffer *ostream_type;

private:
    LogStream(const LogStream &x);
    LogStream &operator=(const LogStream &x);

    int m_minLevel, m_maxLevel;
    int m_logLevel;

public:
    static bool m_lockEnable;
    static std::mutex m_mutex;
};
} // namespace coil

#endif // LOGGER_H
