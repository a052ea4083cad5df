// SPDX-License-Identifier: MIT
// The execution context of a composite whose members run in layers after their owner.
#ifndef RTC_MULTILAYERCOMPOSITEEC_H
#define RTC_MULTILAYERCOMPOSITEEC_H

#include <coil/PeriodicTask.h>
#include <rtm/PeriodicExecutionContext.h>

#include <vector>

namespace RTC_impl
{
class RTObjectStateMachine;
}

namespace RTC_exp
{
/**
 * OpenRTM-aist's MultilayerCompositeEC (type name `MultilayerCompositeEC`): a periodic context
 * whose owner is a composite component; addTask() adds one layer of members. Each cycle runs the
 * owner, then every layer in the order added, each member in the order given. OpenRTM-aist runs
 * each layer in a thread of its own; the runtime's engine runs them in the context's one thread,
 * in the same order, so members see each layer's results as they would there.
 */
class MultilayerCompositeEC : public virtual RTC_exp::PeriodicExecutionContext
{
public:
    MultilayerCompositeEC();
    ~MultilayerCompositeEC() override;

    void init(coil::Properties &props) override;
    /// The engine runs the cycles: refused here (logged, -1).
    virtual int svc();
    RTC::ReturnCode_t bindComponent(RTC::RTObject_impl *rtc) override;
    /// Participant state machines are the engine's own: refused here (logged, null).
    virtual RTC_impl::RTObjectStateMachine *findComponent(RTC::LightweightRTObject_ptr comp);
    /// Adds @p rtcs as the next layer of members.
    virtual void addTask(std::vector<RTC::LightweightRTObject_ptr> rtcs);

protected:
    /// The layers added so far (references owned).
    std::vector<std::vector<RTC::LightweightRTObject_ptr>> m_layers;
};
} // namespace RTC_exp

extern "C" {
/// Registers `MultilayerCompositeEC` with the manager's context factory.
void MultilayerCompositeECInit(RTC::Manager *manager);
}

#endif // RTC_MULTILAYERCOMPOSITEEC_H
