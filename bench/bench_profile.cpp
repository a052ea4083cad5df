// SPDX-License-Identifier: MIT
// Load/save/validate times of a large generated RTS profile (1,000 components, 1,500 connectors).
// Target: each of load and save within 100 ms on a 2-core machine (Release build).
#include "benchsystem.h"
#include "profileio.h"
#include "rtsvalidator.h"
#include "rtsxml.h"
#include "rtsyaml.h"

#include <QCoreApplication>
#include <QTextStream>

#include <functional>

using namespace Profile;

namespace {

constexpr int Components = 1000;
constexpr int Connectors = 1500;
constexpr int Runs = 7;

double medianMs(const std::function<void()> &work)
{
    return Bench::medianMs(work, Runs);
}

long peakRssKiB()
{
    return Bench::peakRssKiB();
}

QByteArray generateSystem()
{
    return Bench::generateSystem(Components, Connectors);
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
