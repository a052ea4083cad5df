// SPDX-License-Identifier: MIT
// Instance numbers unique within this process.
#ifndef RTC_NUMBERINGPOLICY_H
#define RTC_NUMBERINGPOLICY_H

#include <string>
#include <vector>
#include <rtm/RTC.h>
#include <rtm/NumberingPolicyBase.h>

namespace RTM
{
/**
 * `process_unique`: the lowest number no living object of this policy holds, so numbers of
 * deleted objects are given out again (Name0, Name1, delete Name0, the next is Name0 again).
 */
class ProcessUniquePolicy : public NumberingPolicyBase
{
public:
    ProcessUniquePolicy() {}
    ~ProcessUniquePolicy() override = default;
    std::string onCreate(void *obj) override;
    /// Frees @p obj's number; throws ObjectNotFound for an object it never numbered.
    void onDelete(void *obj) override;

protected:
    /// The number of @p obj; throws ObjectNotFound when it has none.
    long int find(void *obj);

private:
    int m_num{0};
    std::vector<void *> m_objects;
};
} // namespace RTM

extern "C" {
/// Registers `process_unique` with the numbering policy factory.
void ProcessUniquePolicyInit();
}

#endif // RTC_NUMBERINGPOLICY_H
