// SPDX-License-Identifier: MIT
// Log lines to a file, standard output or standard error.
#ifndef RTC_LOGSTREAMFILE_H
#define RTC_LOGSTREAMFILE_H

#include <string>
#include <fstream>
#include <iostream>
#include <coil/stringutil.h>
#include <rtm/LogstreamBase.h>

namespace RTC
{
/// Writes lines as `date LEVEL: name: message` to a std::ostream, optionally coloured by level.
class FileStreamBase : public coil::LogStreamBuffer
{
public:
    FileStreamBase() = default;
    ~FileStreamBase() override = default;
    /// Writes the line's prefix (date, level and logger name).
    void header(int level, const std::string &name, const std::string &date, bool es_enable = false);
    void flush() override;
    /// Colours lines by level with ANSI escape sequences (for terminals).
    void enableEscapeSequence();
    void disableEscapeSequence();
    void write(int level, const std::string &name, const std::string &date, const std::string &mes) override;

protected:
    std::basic_ostream<char> *m_stream{nullptr};
    bool m_esEnable{false};
};

/// Lines to standard output.
class StdoutStream : public FileStreamBase
{
public:
    StdoutStream();
    ~StdoutStream() override;
};

/// Lines to standard error.
class StderrStream : public FileStreamBase
{
public:
    StderrStream();
    ~StderrStream() override;
};

/// Lines appended to a file.
class FileStream : public FileStreamBase
{
public:
    FileStream(const std::string &filename);
    ~FileStream() override;
    bool is_open();
    void close();

private:
    std::filebuf m_fileout;
};

/**
 * The `file` log stream: `file_name` is `stdout`, `stderr` or a file path (appended to). Each
 * file is open in one stream of the process at a time; a second stream for the same file is
 * refused by init().
 */
class LogstreamFile : public LogstreamBase
{
public:
    LogstreamFile();
    ~LogstreamFile() override;
    bool init(const coil::Properties &prop) override;
    coil::LogStreamBuffer *getStreamBuffer() override;

protected:
    static coil::vstring s_files;
    std::string m_fileName;
    FileStreamBase *m_stdout{nullptr};
    FileStream *m_fileout{nullptr};
};
} // namespace RTC

extern "C" {
/// Registers LogstreamFile with RTC::LogstreamFactory as `file`.
void LogstreamFileInit();
}

#endif // RTC_LOGSTREAMFILE_H
