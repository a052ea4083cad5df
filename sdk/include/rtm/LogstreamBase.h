// SPDX-License-Identifier: MIT
// Where the logger's lines go: log stream plug-ins by name.
#ifndef RTC_LOGSTREAMBASE_H
#define RTC_LOGSTREAMBASE_H

#include <coil/Properties.h>
#include <coil/Factory.h>
#include <coil/Logger.h>
#include <rtm/RTC.h>

#include <chrono>

namespace RTC
{
using StreambufType = coil::LogStreamBuffer;

/// A destination of log lines (a file, the console, …), set up from its properties.
class LogstreamBase
{
public:
    virtual ~LogstreamBase() = default;
    /// Sets the stream up from @p prop (e.g. `file_name`); false when it cannot be used.
    virtual bool init(const coil::Properties &prop) = 0;
    /// The buffer log lines are written to (owned by the stream).
    virtual StreambufType *getStreamBuffer() = 0;
};

/// The log stream types by name (`file` is LogstreamFile, LogstreamFileInit()).
using LogstreamFactory = coil::GlobalFactory<LogstreamBase>;
} // namespace RTC

#endif // RTC_LOGSTREAMBASE_H
