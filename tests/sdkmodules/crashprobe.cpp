// SPDX-License-Identifier: MIT
// A component written by hand in OpenRTM-aist 2.x style, used to show that a component crashing
// in onExecute takes down only the manager process it runs in. It counts on its OutPort and
// crashes (a null pointer write) once its configuration parameter `crash` is set to 1.
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/Manager.h>

static const char *const crashprobe_spec[] = {"implementation_id", "CrashProbe",
                                              "type_name", "CrashProbe",
                                              "description", "Counts, and crashes on request",
                                              "version", "1.0.0",
                                              "vendor", "RTStudioTests",
                                              "category", "test",
                                              "activity_type", "PERIODIC",
                                              "kind", "DataFlowComponent",
                                              "max_instance", "0",
                                              "language", "C++",
                                              "lang_type", "compile",
                                              "conf.default.crash", "0",
                                              ""};

class CrashProbe : public RTC::DataFlowComponentBase
{
public:
    explicit CrashProbe(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_countOut("count", m_count)
        , m_crash(0)
    {
    }

    RTC::ReturnCode_t onInitialize() override
    {
        addOutPort("count", m_countOut);
        bindParameter("crash", m_crash, "0");
        RTC_INFO(("%s ready", getInstanceName()));
        return RTC::RTC_OK;
    }

    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        if (m_crash == 1) {
            volatile int *nowhere = nullptr;
            *nowhere = 1;
        }
        m_count.data += 1;
        setTimestamp(m_count);
        m_countOut.write();
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_count;
    RTC::OutPort<RTC::TimedLong> m_countOut;
    int m_crash;
};

extern "C" {
DLL_EXPORT void CrashProbeInit(RTC::Manager *manager)
{
    coil::Properties profile(crashprobe_spec);
    manager->registerFactory(profile, RTC::Create<CrashProbe>, RTC::Delete<CrashProbe>);
}
}
