// SPDX-License-Identifier: MIT
// Logging as OpenRTM-aist components do it: the RTC_* macros with printf-style arguments and the
// _STR forms on the component's logger (rtclog), at several levels.
#include "StyleProfile.h"

#include <rtm/DataFlowComponentBase.h>
#include <rtm/SystemLogger.h>

namespace {
SDKSTYLES_SPEC(LoggingComp);

class LoggingComp : public RTC::DataFlowComponentBase
{
public:
    explicit LoggingComp(RTC::Manager *manager) : RTC::DataFlowComponentBase(manager), m_cycles(0) {}

    RTC::ReturnCode_t onInitialize() override
    {
        RTC_INFO(("LoggingComp initialized with %d ports", 0));
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onActivated(RTC::UniqueId) override
    {
        RTC_WARN_STR("LoggingComp activated");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        if (++m_cycles == 3)
            RTC_ERROR(("LoggingComp cycle %ld reached", m_cycles));
        RTC_PARANOID(("LoggingComp cycle %ld", m_cycles));
        return RTC::RTC_OK;
    }

private:
    long m_cycles;
};
} // namespace

extern "C" {
DLL_EXPORT void LoggingCompInit(RTC::Manager *manager)
{
    registerStyle<LoggingComp>(manager, LoggingComp_spec);
}
}
