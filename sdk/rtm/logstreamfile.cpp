// SPDX-License-Identifier: MIT
// The `file` log stream: lines to a file or the console.
#include <rtm/LogstreamFile.h>

#include <algorithm>
#include <mutex>

namespace RTC {

namespace {

const char *levelName(int level)
{
    static const char *const names[] = {"SILENT", "FATAL", "ERROR", "WARNING", "INFO",
                                        "DEBUG", "TRACE", "VERBOSE", "PARANOID"};
    return level >= 0 && level < 9 ? names[level] : "";
}

// Red for the failures, yellow for warnings, the terminal's colour for the rest.
const char *levelColour(int level)
{
    switch (level) {
    case 1:
    case 2:
        return "\x1b[31m";
    case 3:
        return "\x1b[33m";
    default:
        return "";
    }
}

std::mutex filesMutex;

} // namespace

coil::vstring LogstreamFile::s_files;

void FileStreamBase::header(int level, const std::string &name, const std::string &date, bool es_enable)
{
    if (m_stream == nullptr)
        return;
    if (es_enable)
        *m_stream << levelColour(level);
    *m_stream << date << " " << levelName(level) << ": " << name << ": ";
}

void FileStreamBase::flush()
{
    if (m_stream != nullptr)
        m_stream->flush();
}

void FileStreamBase::enableEscapeSequence()
{
    m_esEnable = true;
}

void FileStreamBase::disableEscapeSequence()
{
    m_esEnable = false;
}

void FileStreamBase::write(int level, const std::string &name, const std::string &date, const std::string &mes)
{
    if (m_stream == nullptr)
        return;
    header(level, name, date, m_esEnable);
    *m_stream << mes;
    if (m_esEnable && *levelColour(level) != '\0')
        *m_stream << "\x1b[0m";
    *m_stream << std::endl;
}

StdoutStream::StdoutStream()
{
    m_stream = &std::cout;
}

StdoutStream::~StdoutStream() = default;

StderrStream::StderrStream()
{
    m_stream = &std::cerr;
}

StderrStream::~StderrStream() = default;

FileStream::FileStream(const std::string &filename)
{
    if (m_fileout.open(filename.c_str(), std::ios::out | std::ios::app) != nullptr)
        m_stream = new std::ostream(&m_fileout);
}

FileStream::~FileStream()
{
    close();
}

bool FileStream::is_open()
{
    return m_fileout.is_open();
}

void FileStream::close()
{
    if (m_stream != nullptr) {
        m_stream->flush();
        delete m_stream;
        m_stream = nullptr;
    }
    m_fileout.close();
}

LogstreamFile::LogstreamFile() = default;

LogstreamFile::~LogstreamFile()
{
    delete m_stdout;
    delete m_fileout;
    std::lock_guard<std::mutex> lock(filesMutex);
    s_files.erase(std::remove(s_files.begin(), s_files.end(), m_fileName), s_files.end());
}

bool LogstreamFile::init(const coil::Properties &prop)
{
    std::string name = coil::eraseBothEndsBlank(prop.getProperty("file_name"));
    if (name.empty())
        return false;
    {
        std::lock_guard<std::mutex> lock(filesMutex);
        if (std::find(s_files.begin(), s_files.end(), name) != s_files.end())
            return false;
        s_files.push_back(name);
    }
    m_fileName = name;
    const std::string lower = coil::normalize(name);
    if (lower == "stdout" || lower == "stderr") {
        m_stdout = lower == "stdout" ? static_cast<FileStreamBase *>(new StdoutStream)
                                     : static_cast<FileStreamBase *>(new StderrStream);
        if (coil::toBool(prop.getProperty("escape_sequence_enable"), "YES", "NO", false))
            m_stdout->enableEscapeSequence();
        return true;
    }
    m_fileout = new FileStream(name);
    if (m_fileout->is_open())
        return true;
    delete m_fileout;
    m_fileout = nullptr;
    std::lock_guard<std::mutex> lock(filesMutex);
    s_files.erase(std::remove(s_files.begin(), s_files.end(), name), s_files.end());
    m_fileName.clear();
    return false;
}

coil::LogStreamBuffer *LogstreamFile::getStreamBuffer()
{
    if (m_stdout != nullptr)
        return m_stdout;
    return m_fileout;
}

} // namespace RTC

extern "C" void LogstreamFileInit()
{
    RTC::LogstreamFactory::instance().addFactory("file", coil::Creator<RTC::LogstreamBase, RTC::LogstreamFile>,
                                                 coil::Destructor<RTC::LogstreamBase, RTC::LogstreamFile>);
}
