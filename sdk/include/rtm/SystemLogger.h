// SPDX-License-Identifier: MIT
// Component logging with OpenRTM-aist's levels and macros: RTC_INFO(("format %d", value)) and
// RTC_INFO_STR(text) write through the logger named `rtclog` in scope (every component has one).
#ifndef RTM_SYSTEMLOGGER_H
#define RTM_SYSTEMLOGGER_H

#include <coil/Logger.h>
#include <coil/Properties.h>
#include <coil/stringutil.h>

#include <mutex>
#include <ostream>
#include <sstream>
#include <string>

namespace RTC
{
/// Where the loggers' lines go besides the configured files (RTC::Manager::getLogStreamBuf()).
using LogStreamBuf = ::coil::LogStreamBuffer;
/// The level-filtering stream class OpenRTM-aist's Logger derives from.
using LogStream = ::coil::LogStream;

/**
 * A named log stream. Lines go where the manager's configuration says (`logger.enable`,
 * `logger.log_level`, `logger.file_name`; standard error when no file is named), each with the
 * time, the level and the logger's name.
 */
class Logger
{
public:
    enum
    {
        RTL_SILENT,
        RTL_FATAL,
        RTL_ERROR,
        RTL_WARN,
        RTL_INFO,
        RTL_DEBUG,
        RTL_TRACE,
        RTL_VERBOSE,
        RTL_PARANOID
    };

    explicit Logger(const char *name = "");
    explicit Logger(const std::string &name);
    ~Logger();
    Logger(const Logger &) = delete;
    Logger &operator=(const Logger &) = delete;

    void setName(const char *name);
    /// True when lines of @p level are written.
    bool isValid(int level) const;
    /// Starts a line of @p level; what was streamed is written when the logger is unlocked.
    std::ostream &level(int level);
    void lock();
    void unlock();
    /// Writes @p mes as one line of @p level (when lines of that level are written).
    void write(int level, const std::string &mes);
    /// Writes each property of @p prop (`key: value`) as a line of @p level.
    void write(int level, const coil::Properties &prop);
    /// Overrides the manager's level for this logger.
    void setLevel(int level);
    int getLevel() const;

    /// Level number of a name (`INFO`, `DEBUG`, …; RTL_SILENT when unknown).
    static int strToLevel(const std::string &name);

private:
    std::string m_name;
    int m_level;
    int m_lineLevel;
    std::mutex m_mutex;
    std::ostringstream m_line;
};
} // namespace RTC

#define RTC_LOG(LV, fmt)                                                                                       \
    if (rtclog.isValid(LV)) {                                                                                  \
        std::string rtclog_line_ = ::coil::sprintf fmt;                                                        \
        rtclog.lock();                                                                                         \
        rtclog.level(LV) << rtclog_line_ << std::endl;                                                         \
        rtclog.unlock();                                                                                       \
    }
#define RTC_LOG_STR(LV, str)                                                                                   \
    if (rtclog.isValid(LV)) {                                                                                  \
        rtclog.lock();                                                                                         \
        rtclog.level(LV) << str << std::endl;                                                                  \
        rtclog.unlock();                                                                                       \
    }

#define RTC_FATAL(fmt) RTC_LOG(::RTC::Logger::RTL_FATAL, fmt)
#define RTC_FATAL_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_FATAL, str)
#define RTC_ERROR(fmt) RTC_LOG(::RTC::Logger::RTL_ERROR, fmt)
#define RTC_ERROR_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_ERROR, str)
#define RTC_WARN(fmt) RTC_LOG(::RTC::Logger::RTL_WARN, fmt)
#define RTC_WARN_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_WARN, str)
#define RTC_INFO(fmt) RTC_LOG(::RTC::Logger::RTL_INFO, fmt)
#define RTC_INFO_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_INFO, str)
#define RTC_DEBUG(fmt) RTC_LOG(::RTC::Logger::RTL_DEBUG, fmt)
#define RTC_DEBUG_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_DEBUG, str)
#define RTC_TRACE(fmt) RTC_LOG(::RTC::Logger::RTL_TRACE, fmt)
#define RTC_TRACE_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_TRACE, str)
#define RTC_VERBOSE(fmt) RTC_LOG(::RTC::Logger::RTL_VERBOSE, fmt)
#define RTC_VERBOSE_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_VERBOSE, str)
#define RTC_PARANOID(fmt) RTC_LOG(::RTC::Logger::RTL_PARANOID, fmt)
#define RTC_PARANOID_STR(str) RTC_LOG_STR(::RTC::Logger::RTL_PARANOID, str)

#endif // RTM_SYSTEMLOGGER_H
