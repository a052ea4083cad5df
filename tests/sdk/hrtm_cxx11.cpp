// SPDX-License-Identifier: MIT
// Compiled as C++11 (gnu++11) by tests/sdkhrtm.cmake: every public hrtm header must build there, as
// in the HRTM projects OpenRTM-aist's examples come with.
#include <hrtm/component_manager.h>
#include <hrtm/data_flow_component.h>
#include <hrtm/defs.h>
#include <hrtm/idls/BasicDataType.h>
#include <hrtm/idls/ExtendedDataTypes.h>
#include <hrtm/idls/HRTM.h>
#include <hrtm/in_port.h>
#include <hrtm/logger.h>
#include <hrtm/out_port.h>
#include <hrtm/properties.h>
#include <hrtm/statechart.h>
#include <hrtm/utils.h>
#include <hrtm/version.h>

#if __cplusplus != 201103L
#error "this file checks the hrtm headers as C++11"
#endif

TOPSTATE(CheckTop)
{
    struct Data
    {
        Data()
            : count(0)
        { }
        int count;
    };
    STATE(CheckTop)
    virtual void go(int) { }

private:
    void on_init();
};

SUBSTATE(CheckSub, CheckTop)
{
    STATE(CheckSub)
    HISTORY()
    void go(int n) { data(); (void)n; }
};

void CheckTop::on_init()
{
    CheckSub::set_state(machine());
}

namespace {
class CheckComponent : public hrtm::DataFlowComponent
{
public:
    CheckComponent()
        : m_inPort("in", m_in)
        , m_outPort("out", m_out)
    { }

private:
    RTC::TimedLong m_in;
    RTC::TimedLong m_out;
    hrtm::InPort<RTC::TimedLong> m_inPort;
    hrtm::OutPort<RTC::TimedLong> m_outPort;
};

void checkInit(hrtm::ComponentManager *manager)
{
    static const char *const spec[] = {"type_name", "CheckComponent", ""};
    hrtm::utils::Properties profile(spec);
    manager->regist<CheckComponent>(&profile, 0, 0);
}
} // namespace

int sdkhrtm_cxx11_check(int argc, char **argv)
{
    hrtm::sc::Machine<CheckTop> machine;
    machine.dispatch(hrtm::sc::Event(&CheckTop::go, 1));
    machine->go(2);
    hrtm::sc::Snapshot<CheckTop> snapshot(machine);
    machine = snapshot;
    HRTM_DEBUG("check", "state " << machine.data().count);
    hrtm::ComponentManager &manager = hrtm::ComponentManager::instance(argc, argv);
    manager.set_init_proc(checkInit);
    return CheckSub::is_current(machine) && manager.activate() ? 0 : 1;
}
