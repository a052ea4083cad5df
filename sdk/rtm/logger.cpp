// SPDX-License-Identifier: MIT
#include <rtm/SystemLogger.h>

#include "loggersink.h"

#include <namingregistrar.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <iomanip>
#include <sstream>

namespace RTC {

Logger::Logger(const char *name)
    : m_name(name ? name : "")
    , m_level(-1)
    , m_lineLevel(RTL_INFO)
{
}

Logger::Logger(const std::string &name)
    : Logger(name.c_str())
{
}

Logger::~Logger() = default;

void Logger::setName(const char *name)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_name = name ? name : "";
}

bool Logger::isValid(int level) const
{
    const int limit = m_level >= 0 ? m_level : Sdk::LoggerSink::instance().level();
    return level > RTL_SILENT && level <= limit;
}

std::ostream &Logger::level(int level)
{
    m_lineLevel = level;
    m_line.str(std::string());
    return m_line;
}

void Logger::lock()
{
    m_mutex.lock();
}

void Logger::unlock()
{
    std::string text = m_line.str();
    m_line.str(std::string());
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
        text.pop_back();
    if (!text.empty())
        Sdk::LoggerSink::instance().write(m_lineLevel, m_name, text);
    m_mutex.unlock();
}

void Logger::write(int level, const std::string &mes)
{
    if (!isValid(level))
        return;
    lock();
    this->level(level) << mes;
    unlock();
}

void Logger::write(int level, const coil::Properties &prop)
{
    if (!isValid(level))
        return;
    for (const std::string &key : prop.propertyNames())
        write(level, key + ": " + prop.getProperty(key));
}

void Logger::setLevel(int level)
{
    m_level = level;
}

int Logger::getLevel() const
{
    return m_level >= 0 ? m_level : Sdk::LoggerSink::instance().level();
}

int Logger::strToLevel(const std::string &name)
{
    static const char *const names[] = {"SILENT", "FATAL", "ERROR", "WARN", "INFO",
                                        "DEBUG", "TRACE", "VERBOSE", "PARANOID"};
    std::string upper = name;
    std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    for (int i = 0; i <= RTL_PARANOID; ++i) {
        if (upper == names[i])
            return i;
    }
    return RTL_SILENT;
}

namespace Sdk {

LoggerSink &LoggerSink::instance()
{
    static LoggerSink sink;
    return sink;
}

void LoggerSink::configure(const Runtime::Properties &config)
{
    Runtime::Properties values = config;
    values.set("manager_name", config.value("manager.name", "manager"));
    std::lock_guard<std::mutex> lock(m_mutex);
    m_enabled = config.isYes("logger.enable", true);
    m_level = Logger::strToLevel(config.value("logger.log_level", "INFO"));
    m_dateFormat = config.value("logger.date_format", defaultDateFormat);
    m_files.clear();
    m_stdout = false;
    m_stderr = false;
    for (const std::string &name : Runtime::NamingRegistrar::expand(config.value("logger.file_name"), values)) {
        std::string lower = name;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (lower == "stdout") {
            m_stdout = true;
        } else if (lower == "stderr") {
            m_stderr = true;
        } else if (!name.empty()) {
            auto file = std::make_unique<std::ofstream>(name, std::ios::app);
            if (*file)
                m_files.push_back(std::move(file));
            else
                std::cerr << "logger: cannot open '" << name << "' (logger.file_name); its lines go to standard error"
                          << std::endl;
        }
    }
    if (m_files.empty() && !m_stdout)
        m_stderr = true;
}

int LoggerSink::level()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_enabled ? m_level : Logger::RTL_SILENT;
}

std::string LoggerSink::formatDate(const std::string &format, std::chrono::system_clock::time_point now)
{
    const auto sinceEpoch = now.time_since_epoch();
    const auto micros = std::chrono::duration_cast<std::chrono::microseconds>(sinceEpoch).count() % 1000000;
    // %Q and %q first (strftime does not know them), then the rest.
    std::string pattern;
    for (std::size_t i = 0; i < format.size(); ++i) {
        if (format[i] == '%' && i + 1 < format.size() && (format[i + 1] == 'Q' || format[i + 1] == 'q')) {
            char digits[8];
            if (format[i + 1] == 'Q')
                std::snprintf(digits, sizeof digits, "%03d", int(micros / 1000));
            else
                std::snprintf(digits, sizeof digits, "%06d", int(micros));
            pattern += digits;
            ++i;
        } else if (format[i] == '%' && i + 1 < format.size()) {
            pattern += format.substr(i, 2);
            ++i;
        } else {
            pattern += format[i];
        }
    }
    const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
    std::tm local{};
    localtime_r(&seconds, &local);
    std::ostringstream date;
    date << std::put_time(&local, pattern.c_str());
    return date.str();
}

bool LoggerSink::reachesStandardError(int level)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_enabled && m_stderr && level <= m_level;
}

void LoggerSink::write(int level, const std::string &name, const std::string &text)
{
    static const char *const names[] = {"SILENT", "FATAL", "ERROR", "WARNING", "INFO",
                                        "DEBUG", "TRACE", "VERBOSE", "PARANOID"};
    const auto now = std::chrono::system_clock::now();
    std::lock_guard<std::mutex> lock(m_mutex);
    const std::string date = formatDate(m_dateFormat, now);
    std::ostringstream line;
    line << date << ' ' << names[std::clamp(level, 0, 8)] << ": " << name << ": " << text << '\n';
    const std::string bytes = line.str();
    m_streams.write(level, name, date, text);
    for (const auto &file : m_files)
        file->write(bytes.data(), std::streamsize(bytes.size())).flush();
    if (m_stdout)
        std::cout.write(bytes.data(), std::streamsize(bytes.size())).flush();
    if (m_stderr)
        std::cerr.write(bytes.data(), std::streamsize(bytes.size())).flush();
}

} // namespace Sdk
} // namespace RTC
