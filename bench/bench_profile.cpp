// SPDX-License-Identifier: MIT
// Load/save/validate times of a large generated RTS profile (1,000 components, 1,500 connectors).
// Target: each of load and save within 100 ms on a 2-core machine (Release build).
#include "profileio.h"
#include "rtsvalidator.h"
#include "rtsxml.h"
#include "rtsyaml.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTextStream>

#include <algorithm>
#include <functional>
#include <vector>

using namespace Profile;

namespace {

constexpr int Components = 1000;
constexpr int Connectors = 1500;
constexpr int Runs = 7;

QString componentId(int i)
{
    return QStringLiteral("RTC:Bench:example:Type%1:1.0.0").arg(i % 20);
}

/// Each component has an InPort `in` and OutPorts `out0`/`out1`; connector k joins
/// out(k%2) of component k/2... so that 1,500 connectors spread over the system.
QByteArray generateSystem()
{
    QString xml;
    QTextStream s(&xml);
    s << R"(<?xml version="1.0" encoding="UTF-8" standalone="yes"?>
<rts:RtsProfile xmlns:rts="http://www.openrtp.org/namespaces/rts" xmlns:rtsExt="http://www.openrtp.org/namespaces/rts_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rts:id="RTSystem:Bench:Large:1.0" rts:version="0.2" rts:creationDate="2026-11-21T09:00:00" rts:updateDate="2026-11-21T09:00:00">
)";
    for (int i = 0; i < Components; ++i) {
        const QString name = QStringLiteral("Comp%1").arg(i);
        s << "<rts:Components xsi:type=\"rtsExt:component_ext\" rts:id=\"" << componentId(i)
          << "\" rts:pathUri=\"localhost/" << name << ".rtc\" rts:instanceName=\"" << name
          << "\" rts:activeConfigurationSet=\"default\" rts:compositeType=\"None\" rts:isRequired=\"true\">\n";
        for (const char *port : {"in", "out0", "out1"}) {
            s << "  <rts:DataPorts xsi:type=\"rtsExt:dataport_ext\" rts:name=\"" << name << '.'
              << port << "\"/>\n";
        }
        s << "  <rts:ConfigurationSets rts:id=\"default\"><rts:ConfigurationData rts:name=\"gain\" "
             "rts:data=\"1.5\"/><rts:ConfigurationData rts:name=\"mode\" rts:data=\"fast\"/>"
             "</rts:ConfigurationSets>\n";
        s << "  <rts:ExecutionContexts xsi:type=\"rtsExt:execution_context_ext\" rts:id=\"0\" "
             "rts:kind=\"PeriodicExecutionContext\" rts:rate=\"1000.0\"/>\n";
        s << "  <rtsExt:Location rtsExt:x=\"" << (i % 40) * 200 << "\" rtsExt:y=\"" << (i / 40) * 150
          << "\" rtsExt:height=\"-1\" rtsExt:width=\"-1\" rtsExt:direction=\"RIGHT\"/>\n";
        s << "  <rtsExt:Properties rtsExt:name=\"COMPONENT_PATH_ID\" rtsExt:value=\"localhost/" << name
          << ".rtc\"/>\n</rts:Components>\n";
    }
    for (int k = 0; k < Connectors; ++k) {
        const int from = k % Components;
        const int to = (k * 7 + 1) % Components;
        const QString source = QStringLiteral("Comp%1").arg(from);
        const QString target = QStringLiteral("Comp%1").arg(to);
        const QString port = QStringLiteral("out%1").arg(k / Components);
        s << "<rts:DataPortConnectors xsi:type=\"rtsExt:dataport_connector_ext\" rts:connectorId=\"conn"
          << k << "\" rts:name=\"" << port << "_in\" rts:dataType=\"IDL:RTC/TimedLong:1.0\" "
          << "rts:interfaceType=\"corba_cdr\" rts:dataflowType=\"push\" rts:subscriptionType=\"flush\">\n"
          << "  <rts:sourceDataPort xsi:type=\"rtsExt:target_port_ext\" rts:componentId=\""
          << componentId(from) << "\" rts:instanceName=\"" << source << "\" rts:portName=\"" << source
          << '.' << port << "\"/>\n"
          << "  <rts:targetDataPort xsi:type=\"rtsExt:target_port_ext\" rts:componentId=\""
          << componentId(to) << "\" rts:instanceName=\"" << target << "\" rts:portName=\"" << target
          << ".in\"/>\n"
          << "  <rtsExt:Properties rtsExt:name=\"dataport.outport.buffer.length\" rtsExt:value=\"8\"/>\n"
          << "</rts:DataPortConnectors>\n";
    }
    s << "</rts:RtsProfile>\n";
    s.flush();
    return xml.toUtf8();
}

/// Median wall time of `runs` calls, in milliseconds.
double medianMs(const std::function<void()> &work, int runs = Runs)
{
    std::vector<double> times;
    for (int i = 0; i < runs; ++i) {
        QElapsedTimer timer;
        timer.start();
        work();
        times.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

long peakRssKiB()
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

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);

    const QByteArray xml = generateSystem();
    Diagnostics diagnostics;
    const auto profile = readRtsXml(xml, QStringLiteral("large.xml"), &diagnostics);
    if (!profile || hasErrors(diagnostics)) {
        out << "generated system did not load: " << diagnostics.value(0).toString() << '\n';
        return 1;
    }
    const QByteArray yaml = writeRtsYaml(*profile);

    struct Row
    {
        QString what;
        double ms;
        QString target;
    };
    // `bench_profile "load XML"` runs one operation only (for profilers).
    const QString only = app.arguments().value(1);
    std::vector<Row> rows;
    auto measure = [&only](const QString &what, const std::function<void()> &work) {
        return only.isEmpty() || only == what ? medianMs(work) : -1.0;
    };
    rows.push_back({QStringLiteral("load XML"), measure(QStringLiteral("load XML"), [&] {
                        Diagnostics d;
                        readRtsXml(xml, QStringLiteral("large.xml"), &d);
                    }),
                    QStringLiteral("<= 100")});
    rows.push_back({QStringLiteral("save XML"), measure(QStringLiteral("save XML"), [&] { writeRtsXml(*profile); }),
                    QStringLiteral("<= 100")});
    rows.push_back({QStringLiteral("load YAML"), measure(QStringLiteral("load YAML"), [&] {
                        Diagnostics d;
                        readRtsYaml(yaml, QStringLiteral("large.yaml"), &d);
                    }),
                    QStringLiteral("-")});
    rows.push_back({QStringLiteral("save YAML"), measure(QStringLiteral("save YAML"), [&] { writeRtsYaml(*profile); }),
                    QStringLiteral("-")});
    rows.push_back({QStringLiteral("validate"), measure(QStringLiteral("validate"), [&] {
                        validateRtsProfile(*profile, QStringLiteral("large.xml"));
                    }),
                    QStringLiteral("-")});

    out << QStringLiteral("RTS profile: %1 components, %2 connectors, XML %3 KiB, YAML %4 KiB; "
                          "median of %5 runs\n\n")
               .arg(Components)
               .arg(Connectors)
               .arg(xml.size() / 1024)
               .arg(yaml.size() / 1024)
               .arg(Runs);
    out << QStringLiteral("| %1 | %2 | %3 |\n").arg(QStringLiteral("operation"), -10).arg(QStringLiteral("ms"), 8).arg(QStringLiteral("target ms"), 9);
    out << "|------------|----------|-----------|\n";
    for (const Row &row : rows) {
        if (row.ms < 0)
            continue;
        out << QStringLiteral("| %1 | %2 | %3 |\n")
                   .arg(row.what, -10)
                   .arg(row.ms, 8, 'f', 1)
                   .arg(row.target, 9);
    }
    out << "\npeak memory: " << peakRssKiB() / 1024 << " MiB\n";
    return 0;
}
