// SPDX-License-Identifier: MIT
#pragma once

#include <properties.h>

#include <fstream>
#include <iostream>
#include <mutex>
#include <string>
#include <unistd.h>

namespace RTC::Sdk {

/// Where every component logger writes: standard error or `logger.file_name`, from `logger.log_level` down.
class LoggerSink
{
public:
    static LoggerSink &instance();
    /// Applies the manager's `logger.*` keys.
    void configure(const Runtime::Properties &config);
    int level();
    void write(int level, const std::string &name, const std::string &text);

private:
    std::mutex m_mutex;
    bool m_enabled = true;
    int m_level = 4; // INFO
    std::ofstream m_file;
};

} // namespace RTC::Sdk
