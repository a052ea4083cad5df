// SPDX-License-Identifier: MIT
// HRTM's API in the component SDK: components written against hrtm::DataFlowComponent, with
// hrtm ports, made by hrtm::ComponentManager and run in one process; and hrtm::sc statecharts.
#include <hrtm/component_manager.h>
#include <hrtm/data_flow_component.h>
#include <hrtm/idls/BasicDataType.h>
#include <hrtm/in_port.h>
#include <hrtm/logger.h>
#include <hrtm/out_port.h>
#include <hrtm/properties.h>
#include <hrtm/statechart.h>
#include <hrtm/version.h>

#include <QtTest>

#include <atomic>
#include <mutex>
#include <set>
#include <string>
#include <vector>

// ---------------------------------------------------------------- a statechart
//
//   Top
//   ├── Off
//   └── On (HISTORY)
//       ├── Low
//       └── High (PERSISTENT Data)

namespace {
std::vector<std::string> trail;
void note(const std::string &line)
{
    trail.push_back(line);
}
} // namespace

TOPSTATE(Top)
{
    struct Data
    {
        int presses = 0;
    };
    STATE(Top)
    virtual void press() { ++data().presses; }
    virtual void power() { }
    virtual void hold(int amount) { note("Top:hold " + std::to_string(amount)); }
    virtual void reset();

private:
    void on_entry() override { note("Top:entry"); }
    void on_init() override;
    void on_exit() override { note("Top:exit"); }
};

SUBSTATE(Off, Top)
{
    STATE(Off)
    void press() override;
    void hold(int amount) override
    {
        // Not now: handled once the machine has moved on.
        note("Off:defer " + std::to_string(amount));
        defer(hrtm::sc::Event(&Top::hold, amount), "hold");
    }

private:
    void on_entry() override { note("Off:entry"); }
    void on_exit() override { note("Off:exit"); }
};

SUBSTATE(On, Top)
{
    STATE(On)
    HISTORY()
    void power() override;
    void hold(int amount) override { note("On:hold " + std::to_string(amount)); }

private:
    void on_entry() override { note("On:entry"); }
    void on_init() override;
    void on_exit() override { note("On:exit"); }
};

SUBSTATE(Low, On)
{
    STATE(Low)
    void press() override;

private:
    void on_entry() override { note("Low:entry"); }
    void on_exit() override { note("Low:exit"); }
};

SUBSTATE(High, On)
{
    struct Data
    {
        int visits = 0;
    };
    STATE(High)
    PERSISTENT()
    void press() override { Low::set_state(machine()); }

private:
    void on_entry() override
    {
        ++data().visits;
        note("High:entry " + std::to_string(data().visits));
    }
    void on_exit() override { note("High:exit"); }
};

void Top::on_init()
{
    note("Top:init");
    Off::set_state(machine());
}

void Top::reset()
{
    On::set_state_direct(machine());
}

void Off::press()
{
    Top::press();
    On::set_state(machine());
}

void On::power()
{
    Off::set_state(machine());
}

void On::on_init()
{
    note("On:init");
    Low::set_state(machine());
}

void Low::press()
{
    Top::press();
    High::set_state(machine());
}

// ---------------------------------------------------------------- components

namespace {
const char *const sourceSpec[] = {"implementation_id", "HrtmSource", "type_name", "HrtmSource",
                                  "description", "counter", "version", "1.0.0", "vendor", "RTStudioTests",
                                  "category", "test", "activity_type", "PERIODIC", "kind", "DataFlowComponent",
                                  "max_instance", "0", "language", "C++", "lang_type", "compile",
                                  "exec_cxt.periodic.rate", "200", ""};
const char *const sinkSpec[] = {"implementation_id", "HrtmSink", "type_name", "HrtmSink", "version", "1.0.0",
                                "vendor", "RTStudioTests", "category", "test", "language", "C++",
                                "exec_cxt.periodic.rate", "200", ""};

class HrtmSource : public hrtm::DataFlowComponent
{
public:
    HrtmSource()
        : m_outPort("out", m_out)
    { }
    RTC::ReturnCode_t onInitialize() override
    {
        m_out.data = 0;
        addOutPort("out", m_outPort);
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        ++m_out.data;
        m_outPort.write();
        return RTC::RTC_OK;
    }

private:
    RTC::TimedLong m_out;
    hrtm::OutPort<RTC::TimedLong> m_outPort;
};

class HrtmSink;
HrtmSink *theSink = nullptr;

// The sink's own machine: the parity of the last value read, reported as the component's FSM state.
TOPSTATE(Parity)
{
    STATE(Parity)
    virtual void value(long v);

private:
    void on_init() override;
};

SUBSTATE(Even, Parity)
{
    STATE(Even)

private:
    void on_entry() override;
};

SUBSTATE(Odd, Parity)
{
    STATE(Odd)

private:
    void on_entry() override;
};

class HrtmSink : public hrtm::DataFlowComponent
{
public:
    HrtmSink()
        : m_inPort("in", m_in)
    { }
    RTC::ReturnCode_t onInitialize() override
    {
        addInPort("in", m_inPort);
        theSink = this;
        m_machine = new hrtm::sc::Machine<Parity>();
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onFinalize() override
    {
        delete m_machine;
        m_machine = nullptr;
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        while (m_inPort.isNew()) {
            m_inPort.read();
            ++received;
            m_machine->dispatch(hrtm::sc::Event(&Parity::value, static_cast<long>(m_in.data)));
        }
        return RTC::RTC_OK;
    }
    void entered(const char *state)
    {
        updateFsmStatus(RTC::FSM_STATUS, state);
        std::lock_guard<std::mutex> lock(mutex);
        statesSeen.insert(state);
    }

    std::atomic<int> received {0};
    std::mutex mutex;
    std::set<std::string> statesSeen;

private:
    RTC::TimedLong m_in;
    hrtm::InPort<RTC::TimedLong> m_inPort;
    hrtm::sc::Machine<Parity> *m_machine = nullptr;
};

void Parity::value(long v)
{
    if (v % 2 == 0 && !Even::is_current_direct(machine()))
        Even::set_state(machine());
    else if (v % 2 != 0 && !Odd::is_current_direct(machine()))
        Odd::set_state(machine());
}

void Parity::on_init()
{
    Even::set_state(machine());
}

void Even::on_entry()
{
    theSink->entered(state_name());
}

void Odd::on_entry()
{
    theSink->entered(state_name());
}

std::atomic<int> initCalls {0};
hrtm::ComponentManager *initManager = nullptr;

void moduleInit(hrtm::ComponentManager *manager)
{
    ++initCalls;
    initManager = manager;
    hrtm::utils::Properties source(sourceSpec);
    hrtm::utils::Properties sink(sinkSpec);
    manager->regist<HrtmSource>(&source, 0, 0);
    manager->regist<HrtmSink>(&sink, 0, 0);
}

RTC::PortService_ptr portNamed(RTC::RTObject_impl *component, const std::string &name)
{
    RTC::RTObject_var self = component->getObjRef();
    RTC::PortServiceList_var ports = self->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        if (std::string(profile->name) == std::string(component->getInstanceName()) + '.' + name)
            return RTC::PortService::_duplicate(ports[i]);
    }
    return RTC::PortService::_nil();
}

RTC::ReturnCode_t connectPorts(RTC::PortService_ptr a, RTC::PortService_ptr b)
{
    RTC::ConnectorProfile profile;
    profile.name = CORBA::string_dup("test");
    profile.connector_id = CORBA::string_dup("");
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(a);
    profile.ports[1] = RTC::PortService::_duplicate(b);
    const char *const pairs[][2] = {{"dataport.interface_type", "corba_cdr"},
                                    {"dataport.dataflow_type", "push"},
                                    {"dataport.subscription_type", "flush"},
                                    {"dataport.data_type", "IDL:RTC/TimedLong:1.0"}};
    profile.properties.length(4);
    for (CORBA::ULong i = 0; i < 4; ++i) {
        profile.properties[i].name = CORBA::string_dup(pairs[i][0]);
        profile.properties[i].value <<= pairs[i][1];
    }
    return a->connect(profile);
}
} // namespace

class TestSdkHrtm : public QObject
{
    Q_OBJECT

private slots:
    void statechartTransitions();
    void statechartHistoryAndData();
    void statechartSnapshot();
    void specProperties();
    void initTestCase();
    void cleanupTestCase();
    void managerIsTheProcessManager();
    void componentsRunWithHrtmPorts();

private:
    hrtm::ComponentManager *m_manager = nullptr;
};

void TestSdkHrtm::statechartTransitions()
{
    trail.clear();
    {
        hrtm::sc::Machine<Top> machine;
        QCOMPARE(trail, (std::vector<std::string> {"Top:entry", "Top:init", "Off:entry"}));
        QVERIFY(Off::is_current(machine));
        QVERIFY(Top::is_current(machine));
        QVERIFY(!On::is_current(machine));

        trail.clear();
        machine->press(); // Off → On → (init) Low
        QCOMPARE(trail, (std::vector<std::string> {"Off:exit", "On:entry", "On:init", "Low:entry"}));
        QVERIFY(Low::is_current_direct(machine));
        QVERIFY(On::is_current(machine));
        QVERIFY(!On::is_current_direct(machine));

        trail.clear();
        machine.dispatch(hrtm::sc::Event(&Top::power)); // handled by On, the superstate
        QCOMPARE(trail, (std::vector<std::string> {"Low:exit", "On:exit", "Off:entry"}));

        // Deferred in Off, handled by On after the next transition.
        trail.clear();
        machine->hold(3);
        machine->hold(4); // the same name again before the transition: dropped
        QCOMPARE(trail, (std::vector<std::string> {"Off:defer 3", "Off:defer 4"}));
        machine->press();
        QCOMPARE(trail.back(), std::string("On:hold 3"));
        QCOMPARE(std::count(trail.begin(), trail.end(), std::string("On:hold 4")), 0L);
        QCOMPARE(machine.data().presses, 2);
        trail.clear();
    }
    // Destroying the machine leaves every state, innermost first.
    QCOMPARE(trail, (std::vector<std::string> {"Low:exit", "On:exit", "Top:exit"}));
}

void TestSdkHrtm::statechartHistoryAndData()
{
    hrtm::sc::Machine<Top> machine;
    machine->press(); // On/Low
    machine->press(); // On/High
    QVERIFY(High::is_current_direct(machine));
    machine->power(); // Off; On remembers High

    trail.clear();
    machine->press(); // back to On through its history: High, not On's init
    QVERIFY(High::is_current_direct(machine));
    QCOMPARE(std::count(trail.begin(), trail.end(), std::string("On:init")), 0L);
    // High's Data is persistent: its visit count survived leaving it.
    QCOMPARE(trail.back(), std::string("High:entry 2"));

    machine->power();
    On::clear_history(machine);
    trail.clear();
    machine->press();
    QVERIFY(Low::is_current_direct(machine));
    QVERIFY(std::count(trail.begin(), trail.end(), std::string("On:init")) == 1);

    // set_state_direct ignores a history: On's init chooses Low.
    machine->press(); // High
    machine->power();
    trail.clear();
    machine->reset();
    QVERIFY(Low::is_current_direct(machine));
    QVERIFY(std::count(trail.begin(), trail.end(), std::string("On:init")) == 1);
}

void TestSdkHrtm::statechartSnapshot()
{
    hrtm::sc::Machine<Top> machine;
    machine->press();
    machine->press(); // On/High
    hrtm::sc::Snapshot<Top> snapshot(machine);
    machine->power();
    QVERIFY(Off::is_current_direct(machine));
    trail.clear();
    machine = snapshot;
    QVERIFY(High::is_current_direct(machine));
    QCOMPARE(machine.data().presses, 2);
    hrtm::sc::Machine<Top> copy(snapshot);
    QVERIFY(High::is_current_direct(copy));
}

void TestSdkHrtm::specProperties()
{
    hrtm::utils::Properties profile(sourceSpec);
    QCOMPARE(profile.getProperty("type_name"), std::string("HrtmSource"));
    QCOMPARE(profile.getProperty("exec_cxt.periodic.rate"), std::string("200"));
    hrtm::utils::Properties firstTwo(sourceSpec, 4);
    QCOMPARE(firstTwo.getProperty("type_name"), std::string("HrtmSource"));
    QVERIFY(firstTwo.getProperty("description").empty());
    QCOMPARE(HRTM_VERSION_MAJOR, 0);
}

void TestSdkHrtm::initTestCase()
{
    // No name server and no master: the manager serves on a free loopback port only.
    const char *args[] = {"tst_sdkhrtm", "-o", "naming.enable:NO", "-o", "corba.master_manager:",
                          "-o", "corba.endpoints:127.0.0.1:", "-o", "logger.log_level:ERROR",
                          "-f", "/nonexistent/rtc.conf", "-i"};
    std::vector<char *> argv;
    for (const char *arg : args)
        argv.push_back(const_cast<char *>(arg));
    m_manager = &hrtm::ComponentManager::instance(int(argv.size()), argv.data());
    QCOMPARE(&hrtm::ComponentManager::instance(0, nullptr), m_manager);
    m_manager->set_init_proc(moduleInit);
    QVERIFY(m_manager->activate());
    QCOMPARE(initCalls.load(), 1);
    QCOMPARE(initManager, m_manager);
    m_manager->run(true);
}

void TestSdkHrtm::cleanupTestCase()
{
    if (!m_manager)
        return;
    for (RTC::RTObject_impl *component : m_manager->getComponents())
        m_manager->deleteComponent(component);
    QTRY_VERIFY_WITH_TIMEOUT(m_manager->getComponents().empty(), 5000);
    RTC::Manager::terminate();
    m_manager->join();
}

void TestSdkHrtm::managerIsTheProcessManager()
{
    // Components reach the manager as RTC::Manager::instance(): it is the hrtm one.
    QCOMPARE(&RTC::Manager::instance(), static_cast<RTC::Manager *>(m_manager));
    std::vector<std::string> types;
    for (coil::Properties &profile : m_manager->getFactoryProfiles())
        types.push_back(profile.getProperty("type_name"));
    QVERIFY(std::find(types.begin(), types.end(), "HrtmSource") != types.end());
    QVERIFY(std::find(types.begin(), types.end(), "HrtmSink") != types.end());
    QVERIFY(m_manager->create_component("NoSuchType") == nullptr);
}

void TestSdkHrtm::componentsRunWithHrtmPorts()
{
    hrtm::DataFlowComponent *source = m_manager->create_component("HrtmSource");
    hrtm::DataFlowComponent *sinkBase = m_manager->create_component("HrtmSink");
    QVERIFY(source && sinkBase);
    HrtmSink *sink = dynamic_cast<HrtmSink *>(sinkBase);
    QVERIFY(sink);
    QCOMPARE(std::string(source->getInstanceName()), std::string("HrtmSource0"));
    // Already initialized by the manager: the older call only confirms it.
    QCOMPARE(source->initialize(m_manager), RTC::RTC_OK);
    QCOMPARE(QString::fromStdString(sink->getFsmState()), QStringLiteral("Even")); // the machine started

    RTC::PortService_var out = portNamed(source, "out");
    RTC::PortService_var in = portNamed(sink, "in");
    QVERIFY(!CORBA::is_nil(out) && !CORBA::is_nil(in));
    QCOMPARE(connectPorts(out, in), RTC::RTC_OK);
    QCOMPARE(source->activate(0), RTC::RTC_OK);
    QCOMPARE(sink->activate(0), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(sink->received.load() > 5, 10000);
    // Values alternate in parity: the sink's statechart went both ways and said so.
    QTRY_VERIFY_WITH_TIMEOUT(([sink] {
                                 std::lock_guard<std::mutex> lock(sink->mutex);
                                 return sink->statesSeen.count("Odd") == 1 && sink->statesSeen.count("Even") == 1;
                             }()),
                             10000);
    const QString state = QString::fromStdString(sink->getFsmState());
    QVERIFY2(state == "Even" || state == "Odd", qPrintable(state));
    HRTM_INFO("tst_sdkhrtm", "received " << sink->received.load());

    QCOMPARE(source->deactivate(0), RTC::RTC_OK);
    QCOMPARE(sink->deactivate(0), RTC::RTC_OK);
    m_manager->deleteComponent(source);
    m_manager->deleteComponent(sink);
}

QTEST_GUILESS_MAIN(TestSdkHrtm)
#include "tst_sdkhrtm.moc"
