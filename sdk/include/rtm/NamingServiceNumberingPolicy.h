// SPDX-License-Identifier: MIT
// Instance numbers unique in the name services.
#ifndef RTC_NAMINGSERVICENUMBERINGPOLICY_H
#define RTC_NAMINGSERVICENUMBERINGPOLICY_H

#include <condition_variable>
#include <string>
#include <vector>
#include <rtm/RTC.h>
#include <rtm/NumberingPolicyBase.h>
#include <rtm/Manager.h>

namespace RTM
{
/**
 * `ns_unique`: for a component (RTC::RTObject_impl*), the lowest number N such that the
 * manager's name services (RTC::Manager::getNaming()) know no component `<type name>N` under
 * the manager's naming format.
 */
class NamingServiceNumberingPolicy : public NumberingPolicyBase
{
public:
    NamingServiceNumberingPolicy();
    ~NamingServiceNumberingPolicy() override = default;
    std::string onCreate(void *obj) override;
    void onDelete(void *obj) override;

protected:
    /// Whether the name services know a component named @p name.
    virtual bool find(std::string name);

private:
    std::vector<void *> m_objects;
    RTC::Manager *m_mgr;
};
} // namespace RTM

extern "C" {
/// Registers `ns_unique` with the numbering policy factory.
void NamingServiceNumberingPolicyInit();
}

#endif // RTC_NAMINGSERVICENUMBERINGPOLICY_H
