// SPDX-License-Identifier: MIT
#pragma once

#include <coil/Logger.h>

#include <properties.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace RTC::Sdk {

/**
 * Where every component logger writes, from `logger.log_level` down: each destination of
 * `logger.file_name` (comma-separated files, `stdout`, `stderr`; format codes such as `%p` and
 * `%h` and `${VAR}` expanded), standard error when it names none.
 */
class LoggerSink
{
public:
    static LoggerSink &instance();
    /// Applies the manager's `logger.*` keys; a file that cannot be opened is reported on standard error.
    void configure(const Runtime::Properties &config);
    int level();
    /// Whether a line of @p level reaches standard error (so that a caller need not print it there again).
    bool reachesStandardError(int level);
    void write(int level, const std::string &name, const std::string &text);
    /// The time @p now as @p format (`logger.date_format`) writes it.
    static std::string formatDate(const std::string &format, std::chrono::system_clock::time_point now);
    /// Receives every line written too (with its date apart), passing it to the streams added to it.
    coil::LogStreamBuffer &streams() { return m_streams; }

private:
    std::mutex m_mutex;
    bool m_enabled = true;
    int m_level = 4; // INFO
    std::vector<std::unique_ptr<std::ofstream>> m_files;
    bool m_stdout = false;
    bool m_stderr = true;
    /// `logger.date_format`: strftime's codes, `%Q` milliseconds and `%q` microseconds (OpenRTM-aist's).
    std::string m_dateFormat = defaultDateFormat;
    static constexpr const char *defaultDateFormat = "%b %d %H:%M:%S.%Q";
    coil::LogStreamBuffer m_streams;
};

} // namespace RTC::Sdk
