// SPDX-License-Identifier: MIT
// Static FSM components in one process: the Macho state machine semantics (a lamp machine whose
// trace is compared with sdkfsm/lamp.trace, which OpenRTM-aist's own Macho produces as well),
// the component's FSM hooks and FSM action listeners, an EventInPort fed by OutPorts of another
// component (events named by connector property or connector name, TimedLong arguments), and
// the event queue's RingBuffer.
#include "sdkinprocess.h"
#include "lampmachine.h"

#include "../sdkmodules/trafficlight/TrafficLightFsm.h"

#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataOutPort.h>
#include <rtm/EventPort.h>
#include <rtm/Manager.h>
#include <rtm/RingBuffer.h>

#include <portbase.h>

#include <QtTest>

#include <mutex>

namespace {

using Light = RTC::Machine<TrafficLightFsm::Top>;

const char *const probeSpec[] = {"implementation_id", "FsmProbe", "type_name", "FsmProbe", "max_instance", "0", ""};
const char *const sourceSpec[] = {"implementation_id", "EventSource", "type_name", "EventSource", "max_instance", "0", ""};

/// Every FSM hook call of a component, as "PRE_ON_ENTRY Red" / "POST_ON_INIT Red 0".
class HookLog
{
public:
    void add(const QString &line)
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_lines << line;
    }
    QStringList take()
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        QStringList lines;
        lines.swap(m_lines);
        return lines;
    }

private:
    std::mutex m_mutex;
    QStringList m_lines;
};

class PreRecorder : public RTC::PreFsmActionListener
{
public:
    PreRecorder(HookLog *log, RTC::PreFsmActionListenerType type)
        : m_log(log)
        , m_type(type)
    {
    }
    void operator()(const char *state) override { m_log->add(QString("%1 %2").arg(toString(m_type), state)); }

private:
    HookLog *m_log;
    RTC::PreFsmActionListenerType m_type;
};

class PostRecorder : public RTC::PostFsmActionListener
{
public:
    PostRecorder(HookLog *log, RTC::PostFsmActionListenerType type)
        : m_log(log)
        , m_type(type)
    {
    }
    void operator()(const char *state, RTC::ReturnCode_t ret) override
    {
        m_log->add(QString("%1 %2 %3").arg(toString(m_type), state).arg(int(ret)));
    }

private:
    HookLog *m_log;
    RTC::PostFsmActionListenerType m_type;
};

/// The traffic light's machine behind an EventInPort, run by the test (the component stays inactive).
class FsmProbe : public RTC::DataFlowComponentBase
{
public:
    explicit FsmProbe(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_fsm(this)
        , m_eventIn("event", m_fsm)
    {
    }
    RTC::ReturnCode_t onInitialize() override
    {
        addInPort("event", m_eventIn);
        m_eventIn.bindEvent("on", &TrafficLightFsm::Top::on);
        m_eventIn.bindEvent("go", &TrafficLightFsm::Top::go);
        m_eventIn.bindEvent("fault", &TrafficLightFsm::Top::fault);
        m_eventIn.bindEvent("repair", &TrafficLightFsm::Top::repair);
        for (int i = 0; i < int(RTC::PreFsmActionListenerType::PRE_FSM_ACTION_LISTENER_NUM); ++i) {
            addPreFsmActionListener(RTC::PreFsmActionListenerType(i),
                                    new PreRecorder(&hooks, RTC::PreFsmActionListenerType(i)));
            addPostFsmActionListener(RTC::PostFsmActionListenerType(i),
                                     new PostRecorder(&hooks, RTC::PostFsmActionListenerType(i)));
        }
        return RTC::RTC_OK;
    }

    HookLog hooks;
    Light m_fsm;
    RTC::EventInPort<Light> m_eventIn;
};

/// One TimedLong OutPort per event, written by the test.
class EventSource : public RTC::DataFlowComponentBase
{
public:
    explicit EventSource(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_onOut("on", m_value)
        , m_goOut("go", m_value)
        , m_faultOut("fault", m_value)
        , m_repairOut("repair", m_value)
    {
    }
    RTC::ReturnCode_t onInitialize() override
    {
        addOutPort("on", m_onOut);
        addOutPort("go", m_goOut);
        addOutPort("fault", m_faultOut);
        addOutPort("repair", m_repairOut);
        return RTC::RTC_OK;
    }
    void send(RTC::OutPort<RTC::TimedLong> &port, CORBA::Long value)
    {
        m_value.data = value;
        port.write();
    }

    RTC::TimedLong m_value;
    RTC::OutPort<RTC::TimedLong> m_onOut;
    RTC::OutPort<RTC::TimedLong> m_goOut;
    RTC::OutPort<RTC::TimedLong> m_faultOut;
    RTC::OutPort<RTC::TimedLong> m_repairOut;
};

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

/// Connects @p out to @p in as rtctl would (push, the OutPort's data type) with @p extra properties.
RTC::ReturnCode_t connectEvent(RTC::PortService_ptr out, RTC::PortService_ptr in, const char *name,
                          const QList<QPair<QByteArray, QByteArray>> &extra)
{
    QList<QPair<QByteArray, QByteArray>> pairs{{"dataport.interface_type", "corba_cdr"},
                                               {"dataport.dataflow_type", "push"},
                                               {"dataport.subscription_type", "flush"},
                                               {"dataport.data_type", "IDL:RTC/TimedLong:1.0"}};
    pairs += extra;
    RTC::ConnectorProfile profile;
    profile.name = CORBA::string_dup(name);
    profile.connector_id = CORBA::string_dup("");
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(out);
    profile.ports[1] = RTC::PortService::_duplicate(in);
    profile.properties.length(CORBA::ULong(pairs.size()));
    for (CORBA::ULong i = 0; i < profile.properties.length(); ++i) {
        profile.properties[i].name = CORBA::string_dup(pairs[int(i)].first.constData());
        profile.properties[i].value <<= pairs[int(i)].second.constData();
    }
    return out->connect(profile);
}

} // namespace

class TestSdkFsm : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void lampFollowsMachoSemantics();
    void eventPortDrivesTheMachine();
    void anyTypeMatchesEveryType_data();
    void anyTypeMatchesEveryType();
    void ringBufferPolicies();

private:
    /// Runs the probe's queued events until @p done (5 s at most).
    bool runUntil(FsmProbe *probe, const std::function<bool()> &done);

    RTC::Manager *m_manager = nullptr;
};

void TestSdkFsm::initTestCase()
{
    m_manager = SdkTest::startInProcessManager("tst_sdkfsm");
    QVERIFY(m_manager != nullptr);
    coil::Properties probe(probeSpec), source(sourceSpec);
    QVERIFY(m_manager->registerFactory(probe, RTC::Create<FsmProbe>, RTC::Delete<FsmProbe>));
    QVERIFY(m_manager->registerFactory(source, RTC::Create<EventSource>, RTC::Delete<EventSource>));
}

void TestSdkFsm::cleanupTestCase()
{
    QVERIFY(SdkTest::stopInProcessManager(m_manager));
}

void TestSdkFsm::lampFollowsMachoSemantics()
{
    QFile expected(SDK_FSM_DIR + QStringLiteral("/lamp.trace"));
    QVERIFY(expected.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList wanted = QString::fromUtf8(expected.readAll()).split('\n', Qt::SkipEmptyParts);
    QStringList trace;
    for (const std::string &line : Lamp::runLampScenario())
        trace << QString::fromStdString(line);
    // Step by step, so that a difference names the step it is in.
    QString step;
    for (int i = 0; i < qMin(trace.size(), wanted.size()); ++i) {
        if (wanted[i].startsWith('#'))
            step = wanted[i];
        QVERIFY2(trace[i] == wanted[i], qPrintable(QString("%1, line %2: '%3', expected '%4'")
                                                       .arg(step).arg(i + 1).arg(trace[i], wanted[i])));
    }
    QCOMPARE(trace.size(), wanted.size());
}

bool TestSdkFsm::runUntil(FsmProbe *probe, const std::function<bool()> &done)
{
    return QTest::qWaitFor(
        [&] {
            probe->m_fsm.run_event();
            return done();
        },
        5000);
}

void TestSdkFsm::eventPortDrivesTheMachine()
{
    using namespace TrafficLightFsm;
    auto *probe = dynamic_cast<FsmProbe *>(m_manager->createComponent("FsmProbe?instance_name=probe"));
    auto *source = dynamic_cast<EventSource *>(m_manager->createComponent("EventSource?instance_name=buttons"));
    QVERIFY(probe != nullptr && source != nullptr);
    // The machine entered Dark while it was constructed: no hook ran, the state is known all the same.
    QCOMPARE(QString::fromStdString(probe->getFsmState()), QString("Dark"));
    QVERIFY(probe->hooks.take().isEmpty());

    RTC::PortService_var event = portNamed(probe, "event");
    // The EventInPort takes any data type; events are named by property (with or without the
    // dataport. prefix) or by the connector's name.
    QCOMPARE(connectEvent(portNamed(source, "on"), event, "c1", {{"dataport.fsm_event_name", "on"}}), RTC::RTC_OK);
    QCOMPARE(connectEvent(portNamed(source, "go"), event, "c2", {{"fsm_event_name", "go"}}), RTC::RTC_OK);
    QCOMPARE(connectEvent(portNamed(source, "fault"), event, "fault", {}), RTC::RTC_OK);
    QCOMPARE(connectEvent(portNamed(source, "repair"), event, "c4", {{"dataport.fsm_event_name", "repair"}}),
             RTC::RTC_OK);

    source->send(source->m_onOut, 1);
    QVERIFY(runUntil(probe, [&] { return Red::isCurrent(probe->m_fsm); }));
    const QStringList on{"PRE_ON_EXIT Dark",        "POST_ON_EXIT Dark 0",  "PRE_ON_STATE_CHANGE Dark",
                         "POST_ON_STATE_CHANGE Running 0", "PRE_ON_ENTRY Running", "POST_ON_ENTRY Running 0",
                         "PRE_ON_INIT Running",     "POST_ON_INIT Running 0", "POST_ON_STATE_CHANGE Red 0",
                         "PRE_ON_ENTRY Red",        "POST_ON_ENTRY Red 0",  "PRE_ON_INIT Red",
                         "POST_ON_INIT Red 0"};
    QCOMPARE(probe->hooks.take(), on);
    QCOMPARE(QString::fromStdString(probe->getFsmState()), QString("Red"));

    source->send(source->m_goOut, 2);
    QVERIFY(runUntil(probe, [&] { return Green::isCurrent(probe->m_fsm); }));
    // The sample is the handler's argument: fault keeps its code in the top state's box.
    source->send(source->m_faultOut, 42);
    QVERIFY(runUntil(probe, [&] { return Flashing::isCurrent(probe->m_fsm); }));
    QCOMPARE(probe->m_fsm.box().fault, CORBA::Long(42));
    source->send(source->m_faultOut, 43);
    QVERIFY(runUntil(probe, [&] { return probe->m_fsm.box().fault == 43; }));
    QVERIFY(Flashing::isCurrent(probe->m_fsm));
    probe->hooks.take();
    // repair goes to Running's history: Green is entered, Running's init does not run.
    source->send(source->m_repairOut, 0);
    QVERIFY(runUntil(probe, [&] { return Green::isCurrent(probe->m_fsm); }));
    const QStringList repair{"PRE_ON_EXIT Flashing",         "POST_ON_EXIT Flashing 0", "PRE_ON_STATE_CHANGE Flashing",
                             "POST_ON_STATE_CHANGE Running 0", "PRE_ON_ENTRY Running",  "POST_ON_ENTRY Running 0",
                             "POST_ON_STATE_CHANGE Green 0", "PRE_ON_ENTRY Green",      "POST_ON_ENTRY Green 0",
                             "PRE_ON_INIT Green",            "POST_ON_INIT Green 0"};
    QCOMPARE(probe->hooks.take(), repair);
    QCOMPARE(QString::fromStdString(probe->getFsmState()), QString("Green"));
    // An event the current state does not handle changes nothing.
    source->send(source->m_onOut, 3);
    QVERIFY(runUntil(probe, [&] { return probe->m_fsm.getBuffer().empty(); }));
    QVERIFY(Green::isCurrentDirect(probe->m_fsm));
    QVERIFY(probe->hooks.take().isEmpty());
    m_manager->deleteComponent(probe);
    m_manager->deleteComponent(source);
}

void TestSdkFsm::anyTypeMatchesEveryType_data()
{
    QTest::addColumn<QString>("a");
    QTest::addColumn<QString>("b");
    QTest::addColumn<bool>("same");
    QTest::newRow("any, repository id") << "any" << "IDL:RTC/TimedLong:1.0" << true;
    QTest::newRow("scoped, any") << "RTC::TimedDoubleSeq" << "any" << true;
    QTest::newRow("Any") << "Any" << "TimedString" << true;
    QTest::newRow("forms of one type") << "IDL:RTC/TimedLong:1.0" << "TimedLong" << true;
    QTest::newRow("two types") << "IDL:RTC/TimedLong:1.0" << "RTC::TimedDouble" << false;
    QTest::newRow("anything is not any") << "anything" << "RTC::TimedDouble" << false;
}

void TestSdkFsm::anyTypeMatchesEveryType()
{
    QFETCH(QString, a);
    QFETCH(QString, b);
    QFETCH(bool, same);
    QCOMPARE(Runtime::sameDataType(a.toStdString(), b.toStdString()), same);
}

void TestSdkFsm::ringBufferPolicies()
{
    RTC::RingBuffer<int> buffer(3);
    QCOMPARE(buffer.length(), size_t(3));
    for (int i = 1; i <= 4; ++i)
        QCOMPARE(buffer.write(i), RTC::BufferStatus::OK); // the fourth overwrites the oldest
    QVERIFY(buffer.full());
    int value = 0;
    QCOMPARE(buffer.read(value), RTC::BufferStatus::OK);
    QCOMPARE(value, 2);
    QCOMPARE(buffer.get(), 3);
    QCOMPARE(buffer.advanceRptr(), RTC::BufferStatus::OK);
    QCOMPARE(buffer.readable(), size_t(1));
    QCOMPARE(buffer.advanceRptr(2), RTC::BufferStatus::PRECONDITION_NOT_MET);
    QCOMPARE(buffer.read(value), RTC::BufferStatus::OK);
    QCOMPARE(value, 4);
    // Empty: readback gives the last value read again.
    QCOMPARE(buffer.read(value), RTC::BufferStatus::OK);
    QCOMPARE(value, 4);

    coil::Properties policies;
    policies.setProperty("length", "2");
    policies.setProperty("write.full_policy", "do_nothing");
    policies.setProperty("read.empty_policy", "block");
    policies.setProperty("read.timeout", "0.01");
    buffer.init(policies);
    QCOMPARE(buffer.length(), size_t(2));
    QVERIFY(buffer.empty());
    QCOMPARE(buffer.read(value), RTC::BufferStatus::TIMEOUT);
    QCOMPARE(buffer.write(7), RTC::BufferStatus::OK);
    QCOMPARE(buffer.write(8), RTC::BufferStatus::OK);
    QCOMPARE(buffer.write(9), RTC::BufferStatus::FULL);
    QCOMPARE(*buffer.rptr(1), 8);
    QCOMPARE(buffer.reset(), RTC::BufferStatus::OK);
    QCOMPARE(buffer.writable(), size_t(2));
}

QTEST_GUILESS_MAIN(TestSdkFsm)
#include "tst_sdkfsm.moc"
