// SPDX-License-Identifier: MIT
#include <hrtm/data_flow_component.h>

namespace hrtm {
DataFlowComponent::DataFlowComponent()
    : RTC::DataFlowComponentBase(&RTC::Manager::instance())
{ }

DataFlowComponent::~DataFlowComponent() = default;

RTC::ReturnCode_t DataFlowComponent::initialize()
{
    return RTC::DataFlowComponentBase::initialize();
}

RTC::ReturnCode_t DataFlowComponent::initialize(ComponentManager * /*manager*/)
{
    // initialize() names the instance: a named component has been initialized.
    const char *name = getInstanceName();
    if (name != nullptr && *name != '\0')
        return RTC::RTC_OK;
    return initialize();
}

void DataFlowComponent::updateFsmStatus(RTC::StatusKind /*status_kind*/, const char *state)
{
    postOnFsmStateChange(state, RTC::RTC_OK);
}
} // namespace hrtm
