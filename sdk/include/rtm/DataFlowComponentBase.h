// SPDX-License-Identifier: MIT
// The base class of data-flow components (the kind the Builder generates).
#ifndef RTM_DATAFLOWCOMPONENTBASE_H
#define RTM_DATAFLOWCOMPONENTBASE_H

#include <rtm/RTObject.h>

namespace RTC
{
/// A data-flow component: RTObject_impl driven by a periodic execution context.
class DataFlowComponentBase : public RTObject_impl
{
public:
    explicit DataFlowComponentBase(Manager *manager);
    ~DataFlowComponentBase() override;
    /// Kept for sources that call it; the manager initializes components itself.
    void init() {}
};
} // namespace RTC

#endif // RTM_DATAFLOWCOMPONENTBASE_H
