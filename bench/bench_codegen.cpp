// SPDX-License-Identifier: MIT
// Code generation time for a 50-port component in all three languages (C++, Python, Java).
// Target: ≤ 100 ms for the three together.
#include "codegenerator.h"
#include "idlparser.h"
#include "rtcprofile.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QTextStream>

#include <algorithm>
#include <functional>
#include <vector>

using namespace Profile;

namespace {

constexpr int Ports = 50;
constexpr int Runs = 7;

/// Half in, half out, cycling through data types of different shapes (basic, sequence, struct).
RtcProfile fiftyPortComponent()
{
    RtcProfile profile = RtcProfile::createDefault();
    profile.basicInfo.name = QStringLiteral("FiftyPorts");
    profile.id = profile.idFromBasicInfo();
    const QStringList types = {QStringLiteral("RTC::TimedLong"), QStringLiteral("RTC::TimedDouble"),
                               QStringLiteral("RTC::TimedString"), QStringLiteral("RTC::TimedLongSeq"),
                               QStringLiteral("RTC::TimedPose2D")};
    for (int i = 0; i < Ports; ++i) {
        RtcDataPort port;
        const bool in = i % 2 == 0;
        port.portType = in ? QStringLiteral("DataInPort") : QStringLiteral("DataOutPort");
        port.name = QStringLiteral("%1%2").arg(in ? QStringLiteral("in") : QStringLiteral("out")).arg(i);
        port.type = types.at(i % types.size());
        port.idlFile = i % types.size() == 4 ? QStringLiteral("ExtendedDataTypes.idl")
                                             : QStringLiteral("BasicDataType.idl");
        port.position = in ? QStringLiteral("LEFT") : QStringLiteral("RIGHT");
        profile.dataPorts.append(port);
    }
    return profile;
}

double medianMs(const std::function<bool()> &work, bool *ok)
{
    std::vector<double> times;
    for (int i = 0; i < Runs; ++i) {
        QElapsedTimer timer;
        timer.start();
        *ok = work() && *ok;
        times.push_back(double(timer.nsecsElapsed()) / 1e6);
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);

    Codegen::IdlParser parser;
    parser.addSearchDirectory(QStringLiteral(RTSTUDIO_IDL_DIR));
    const QDir idl(QStringLiteral(RTSTUDIO_IDL_DIR));
    if (!parser.parseFiles({idl.filePath(QStringLiteral("BasicDataType.idl")),
                            idl.filePath(QStringLiteral("ExtendedDataTypes.idl"))})) {
        out << "the bundled IDL did not parse: " << parser.diagnostics().value(0).toString() << '\n';
        return 1;
    }
    const RtcProfile profile = fiftyPortComponent();
    const Codegen::CodeGenerator generator(profile, parser.model());
    const QList<Codegen::TargetLanguage> all = {Codegen::TargetLanguage::Cpp,
                                                Codegen::TargetLanguage::Python,
                                                Codegen::TargetLanguage::Java};

    struct Row
    {
        QString what;
        QList<Codegen::TargetLanguage> languages;
    };
    const std::vector<Row> rows = {{QStringLiteral("C++"), {Codegen::TargetLanguage::Cpp}},
                                   {QStringLiteral("Python"), {Codegen::TargetLanguage::Python}},
                                   {QStringLiteral("Java"), {Codegen::TargetLanguage::Java}},
                                   {QStringLiteral("all three"), all}};

    out << QStringLiteral("Component with %1 data ports; median of %2 runs (in memory, no disk)\n\n")
               .arg(Ports)
               .arg(Runs);
    out << "| languages  |       ms | files | target ms |\n";
    out << "|------------|----------|-------|-----------|\n";
    for (const Row &row : rows) {
        bool ok = true;
        qsizetype files = 0;
        const double ms = medianMs(
            [&] {
                Diagnostics diagnostics;
                const auto generated = generator.generate(row.languages, &diagnostics);
                files = generated ? generated->size() : 0;
                return generated.has_value();
            },
            &ok);
        if (!ok) {
            out << "generation failed for " << row.what << '\n';
            return 1;
        }
        out << QStringLiteral("| %1 | %2 | %3 | %4 |\n")
                   .arg(row.what, -10)
                   .arg(ms, 8, 'f', 1)
                   .arg(files, 5)
                   .arg(row.languages.size() == 3 ? QStringLiteral("<= 100") : QStringLiteral("-"), 9);
    }
    return 0;
}
