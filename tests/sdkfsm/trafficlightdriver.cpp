// SPDX-License-Identifier: MIT
#include "trafficlightdriver.h"

#include "componentstatus.h"
#include "rtctlrunner.h"

#include <RTC.hh>

#include <QTest>

namespace SdkFsmTest {

namespace {

const char *const buttons[] = {"OnButton", "GoButton", "FaultButton", "RepairButton", "OffButton"};

} // namespace

QList<TrafficStep> trafficScenario()
{
    return {{"OnButton", [](long v) { return v == 1; }, "Red", "on: Dark -> Running, whose init chooses Red"},
            {"GoButton", [](long v) { return v == 2; }, "Green", "go: Red -> Green"},
            {"FaultButton", [](long v) { return v > 1000; }, "Flashing",
             "fault (the connector's name) with ConsoleIn's count as code, kept in the top state's box"},
            {"RepairButton", [](long v) { return v == 2; }, "Green", "repair: Running's history, Green"},
            {"OffButton", [](long v) { return v == 0; }, "Dark", "off: Dark"},
            {"OnButton", [](long v) { return v == 1; }, "Red", "on again: a plain transition runs Running's init"}};
}

QString TrafficLightDriver::precreate()
{
    QStringList components;
    for (const char *button : buttons)
        components << QStringLiteral("ConsoleIn?instance_name=%1&exec_cxt.periodic.rate=20").arg(button);
    components << QStringLiteral("ConsoleOut?instance_name=StateView");
    return "manager.components.precreate=" + components.join(',');
}

TrafficLightDriver::TrafficLightDriver(CORBA::ORB_ptr orb, const QString &namingServer, const QString &ours,
                                       const QString &light)
    : m_orb(CORBA::ORB::_duplicate(orb))
    , m_namingServer(namingServer)
    , m_ours(ours)
    , m_light(light)
{
}

QString TrafficLightDriver::path(const QString &name) const
{
    return QStringLiteral("/%1/%2.host_cxt/%3.rtc").arg(m_namingServer, m_ours, name);
}

QString TrafficLightDriver::run(const QStringList &arguments) const
{
    const RtctlResult r = runRtctl(arguments, {{QStringLiteral("RTCTREE_NAMESERVERS"), QString()}});
    return r.code == 0 ? QString() : arguments.join(' ') + ": " + r.out + r.err;
}

QString TrafficLightDriver::connectAll()
{
    const QString event = m_light + ":event";
    // Events named by the connector property, as OpenRTM-aist's preconnect writes it, except
    // "fault", named by the connector's name.
    const QList<QStringList> connections{
        {path("OnButton") + ":out", event, "-p", "dataport.fsm_event_name=on"},
        {path("GoButton") + ":out", event, "-p", "dataport.fsm_event_name=go"},
        {path("FaultButton") + ":out", event, "-n", "fault"},
        {path("RepairButton") + ":out", event, "-p", "dataport.fsm_event_name=repair"},
        {path("OffButton") + ":out", event, "-p", "dataport.fsm_event_name=off"},
        {m_light + ":state", view() + ":in"}};
    for (const QStringList &connection : connections) {
        const QString error = run(QStringList{"con"} + connection);
        if (!error.isEmpty())
            return error;
    }
    return {};
}

QString TrafficLightDriver::activate()
{
    return run({"act", m_light, view()});
}

bool TrafficLightDriver::press(const QString &button, const std::function<bool(long)> &wanted, QString *seen)
{
    QStringList values;
    QString error = run({"act", path(button)});
    const bool found = error.isEmpty() && QTest::qWaitFor(
                                              [&] {
                                                  const QString value = lastValue();
                                                  if (values.isEmpty() || values.last() != value)
                                                      values << value;
                                                  return !value.isEmpty() && wanted(value.toLong());
                                              },
                                              20000);
    const QString released = run({"deact", path(button)});
    *seen = error + released + values.mid(qMax(0, int(values.size()) - 20)).join(' ');
    return found && released.isEmpty();
}

QString TrafficLightDriver::status(const QString &path, const char *name) const
{
    return LiveTest::componentStatus(
        m_orb, QStringLiteral("corbaname::%1#%2").arg(m_namingServer, path.section('/', 2)), name);
}

} // namespace SdkFsmTest
