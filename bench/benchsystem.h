// SPDX-License-Identifier: MIT
#pragma once

// Shared by the benchmarks: a large generated RTS profile, median timing and peak memory.

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QString>
#include <QTextStream>

#include <algorithm>
#include <functional>
#include <vector>

namespace Bench {

/// The type id of generated component `i` (20 types shared by all components).
inline QString componentId(int i)
{
    return QStringLiteral("RTC:Bench:example:Type%1:1.0.0").arg(i % 20);
}

inline void writeComponent(QTextStream &s, int i, bool withLocation)
{
    const QString name = QStringLiteral("Comp%1").arg(i);
    s << "<rts:Components xsi:type=\"rtsExt:component_ext\" rts:id=\"" << componentId(i)
      << "\" rts:pathUri=\"localhost/" << name << ".rtc\" rts:instanceName=\"" << name
      << "\" rts:activeConfigurationSet=\"default\" rts:compositeType=\"None\" "
         "rts:isRequired=\"true\">\n";
    for (const char *port : {"in", "out0", "out1"})
        s << "  <rts:DataPorts xsi:type=\"rtsExt:dataport_ext\" rts:name=\"" << name << '.'
          << port << "\"/>\n";
    s << "  <rts:ConfigurationSets rts:id=\"default\"><rts:ConfigurationData rts:name=\"gain\" "
         "rts:data=\"1.5\"/><rts:ConfigurationData rts:name=\"mode\" rts:data=\"fast\"/>"
         "</rts:ConfigurationSets>\n";
    s << "  <rts:ExecutionContexts xsi:type=\"rtsExt:execution_context_ext\" rts:id=\"0\" "
         "rts:kind=\"PeriodicExecutionContext\" rts:rate=\"1000.0\"/>\n";
    if (withLocation) // a grid of 40 columns
        s << "  <rtsExt:Location rtsExt:x=\"" << (i % 40) * 200 << "\" rtsExt:y=\""
          << (i / 40) * 150
          << "\" rtsExt:height=\"-1\" rtsExt:width=\"-1\" rtsExt:direction=\"RIGHT\"/>\n";
    s << "  <rtsExt:Properties rtsExt:name=\"COMPONENT_PATH_ID\" rtsExt:value=\"localhost/"
      << name << ".rtc\"/>\n</rts:Components>\n";
}

/// Connector k joins out(k / components) of component k % components to the `in` port of
/// component (7k + 1) % components, so that the connectors spread over the whole system.
inline void writeConnector(QTextStream &s, int k, int components)
{
    const int from = k % components;
    const int to = (k * 7 + 1) % components;
    const QString source = QStringLiteral("Comp%1").arg(from);
    const QString target = QStringLiteral("Comp%1").arg(to);
    const QString port = QStringLiteral("out%1").arg((k / components) % 2);
    s << "<rts:DataPortConnectors xsi:type=\"rtsExt:dataport_connector_ext\" "
         "rts:connectorId=\"conn"
      << k << "\" rts:name=\"" << port << "_in\" rts:dataType=\"IDL:RTC/TimedLong:1.0\" "
      << "rts:interfaceType=\"corba_cdr\" rts:dataflowType=\"push\" "
         "rts:subscriptionType=\"flush\">\n"
      << "  <rts:sourceDataPort xsi:type=\"rtsExt:target_port_ext\" rts:componentId=\""
      << componentId(from) << "\" rts:instanceName=\"" << source << "\" rts:portName=\""
      << source << '.' << port << "\"/>\n"
      << "  <rts:targetDataPort xsi:type=\"rtsExt:target_port_ext\" rts:componentId=\""
      << componentId(to) << "\" rts:instanceName=\"" << target << "\" rts:portName=\""
      << target << ".in\"/>\n"
      << "  <rtsExt:Properties rtsExt:name=\"dataport.outport.buffer.length\" "
         "rtsExt:value=\"8\"/>\n"
      << "</rts:DataPortConnectors>\n";
}

/**
 * An RTS profile (XML) of `components` components, each with an InPort `in` and OutPorts
 * `out0`/`out1`, a configuration set and an execution context, and `connectors` data
 * connectors; with `withLocations` the components sit on a grid (`rtsExt:Location`).
 */
inline QByteArray generateSystem(int components, int connectors, bool withLocations = true)
{
    QString xml;
    QTextStream s(&xml);
    s << R"(<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rts:id="RTSystem:Bench:Large:1.0" rts:version="0.2" rts:creationDate="2026-11-21T09:00:00" rts:updateDate="2026-11-21T09:00:00">
)";
    for (int i = 0; i < components; ++i)
        writeComponent(s, i, withLocations);
    for (int k = 0; k < connectors; ++k)
        writeConnector(s, k, components);
    s << "</rts:RtsProfile>\n";
    s.flush();
    return xml.toUtf8();
}

/// Wall time of one call, in milliseconds.
inline double timeMs(const std::function<void()> &work)
{
    QElapsedTimer timer;
    timer.start();
    work();
    return double(timer.nsecsElapsed()) / 1e6;
}

/// Median wall time of `runs` calls, in milliseconds.
inline double medianMs(const std::function<void()> &work, int runs)
{
    std::vector<double> times;
    for (int i = 0; i < runs; ++i)
        times.push_back(timeMs(work));
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

/// The peak resident set size of this process (VmHWM), in KiB; -1 when unknown.
inline long peakRssKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n')) {
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').first().toLong();
    }
    return -1;
}

} // namespace Bench
