// SPDX-License-Identifier: MIT
// How instance numbers are given to new components.
#ifndef RTC_NUMBERINGPOLICYBASE_H
#define RTC_NUMBERINGPOLICYBASE_H

#include <string>
#include <vector>

#include <coil/Factory.h>

namespace RTM
{
/// Gives each new object a number (as text), and takes it back when the object goes.
class NumberingPolicyBase
{
public:
    /// Thrown by policies asked about an object they do not know.
    struct ObjectNotFound
    {
    };
    virtual ~NumberingPolicyBase() = default;
    /// The number for @p obj (an RTC::RTObject_impl* for the manager's policies).
    virtual std::string onCreate(void *obj) = 0;
    virtual void onDelete(void *obj) = 0;
};

/**
 * The numbering policies by name — the values of `manager.components.naming_policy`:
 * `process_unique`, `node_unique`, `ns_unique` (registered by RTM::FactoryInit()) and what
 * programs add. The runtime's manager itself numbers as process_unique does.
 */
using NumberingPolicyFactory = coil::GlobalFactory<NumberingPolicyBase>;
} // namespace RTM

#endif // RTC_NUMBERINGPOLICYBASE_H
