// SPDX-License-Identifier: MIT
/*!
 * @file logger.h
 * @brief HRTM's logging macros and hrtm::utils::Logger (RTC::Logger).
 *
 * HRTM_<LEVEL>(name, text) writes @p text (a stream expression: `"value " << x`) at that level
 * through a logger named @p name, with the manager's logging settings; the _STR forms are the
 * RTC_<LEVEL>_STR macros, which use the `rtclog` in scope (every component has one).
 */
#ifndef HRTM_LOGGER_H
#define HRTM_LOGGER_H

#include <rtm/SystemLogger.h>

#include <ostream>

/*! Writes the stream expression @p text at level @p LV through a logger named @p name. */
#define HRTM_LOG_(LV, name, text)                                                                                      \
    do {                                                                                                               \
        ::RTC::Logger hrtm_logger_(name);                                                                              \
        if (hrtm_logger_.isValid(LV)) {                                                                                \
            hrtm_logger_.lock();                                                                                       \
            hrtm_logger_.level(LV) << text << std::endl;                                                               \
            hrtm_logger_.unlock();                                                                                     \
        }                                                                                                              \
    } while (0)

#define HRTM_ERROR(name, text) HRTM_LOG_(::RTC::Logger::RTL_ERROR, name, text)
#define HRTM_ERROR_STR RTC_ERROR_STR
#define HRTM_WARNING(name, text) HRTM_LOG_(::RTC::Logger::RTL_WARN, name, text)
#define HRTM_WARN_STR RTC_WARN_STR
// HRTM's NORMAL level has no RTC counterpart: it is written as INFO.
#define HRTM_NORMAL(name, text) HRTM_LOG_(::RTC::Logger::RTL_INFO, name, text)
#define HRTM_NORMAL_STR RTC_INFO_STR
#define HRTM_INFO(name, text) HRTM_LOG_(::RTC::Logger::RTL_INFO, name, text)
#define HRTM_INFO_STR RTC_INFO_STR
#define HRTM_DEBUG(name, text) HRTM_LOG_(::RTC::Logger::RTL_DEBUG, name, text)
#define HRTM_DEBUG_STR RTC_DEBUG_STR
#define HRTM_TRACE(name, text) HRTM_LOG_(::RTC::Logger::RTL_TRACE, name, text)
#define HRTM_TRACE_STR RTC_TRACE_STR
#define HRTM_VERBOSE(name, text) HRTM_LOG_(::RTC::Logger::RTL_VERBOSE, name, text)
#define HRTM_VERBOSE_STR RTC_VERBOSE_STR
#define HRTM_PARANOID(name, text) HRTM_LOG_(::RTC::Logger::RTL_PARANOID, name, text)
#define HRTM_PARANOID_STR RTC_PARANOID_STR

namespace hrtm {
namespace utils {
#ifndef CXX11
/*! A named logger (see RTC::Logger). */
class Logger : public RTC::Logger
{
public:
};
#else
using Logger = RTC::Logger;
#endif
} // namespace utils
} // namespace hrtm

#endif // HRTM_LOGGER_H
