// SPDX-License-Identifier: MIT
// Instance numbers unique among the managers of a node (a master and its slaves).
#ifndef RTC_NODENUMBERINGPOLICY_H
#define RTC_NODENUMBERINGPOLICY_H

#include <condition_variable>
#include <string>
#include <vector>
#include <rtm/RTC.h>
#include <rtm/NumberingPolicyBase.h>
#include <rtm/Manager.h>

namespace RTM
{
/**
 * `node_unique`: for a component (RTC::RTObject_impl*), the lowest number N such that no
 * component `<type name>N` runs in this manager, its master or their slaves.
 */
class NodeNumberingPolicy : public NumberingPolicyBase
{
public:
    NodeNumberingPolicy();
    ~NodeNumberingPolicy() override = default;
    std::string onCreate(void *obj) override;
    void onDelete(void *obj) override;

protected:
    /// Whether a component named @p name runs on the node.
    virtual bool find(std::string name);

private:
    std::vector<void *> m_objects;
    RTC::Manager *m_mgr;
};
} // namespace RTM

extern "C" {
/// Registers `node_unique` with the numbering policy factory.
void NodeNumberingPolicyInit();
}

#endif // RTC_NODENUMBERINGPOLICY_H
