// SPDX-License-Identifier: MIT
// Counts its cycles and reports each on standard output: driven by an ExtTrigExecutionContext, it
// runs exactly once per tick.
#include "StyleProfile.h"

#include <rtm/DataFlowComponentBase.h>

namespace {
SDKSTYLES_SPEC(TickCounter);

class TickCounter : public RTC::DataFlowComponentBase
{
public:
    explicit TickCounter(RTC::Manager *manager) : RTC::DataFlowComponentBase(manager), m_cycles(0) {}

    RTC::ReturnCode_t onActivated(RTC::UniqueId) override
    {
        m_cycles = 0;
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        std::cout << getInstanceName() << " cycle " << ++m_cycles << std::endl;
        return RTC::RTC_OK;
    }

private:
    long m_cycles;
};
} // namespace

extern "C" {
DLL_EXPORT void TickCounterInit(RTC::Manager *manager)
{
    registerStyle<TickCounter>(manager, TickCounter_spec);
}
}
