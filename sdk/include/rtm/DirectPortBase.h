// SPDX-License-Identifier: MIT
// The common base of ports that hand samples over inside one process.
#ifndef RTC_DIRECTPORTBASE_H
#define RTC_DIRECTPORTBASE_H

namespace RTC {
/// A port as a direct (in-process, unmarshalled) sender or receiver of samples.
class DirectPortBase
{
public:
    virtual ~DirectPortBase() = default;
};
} // namespace RTC

#endif // RTC_DIRECTPORTBASE_H
