// SPDX-License-Identifier: MIT
#include "profilecommand.h"

#include "profileio.h"
#include "rtcvalidator.h"
#include "rtsvalidator.h"

#include <algorithm>

using namespace Profile;

namespace Cli {

namespace {

void print(const Diagnostics &diagnostics, QTextStream &stream)
{
    for (const Diagnostic &d : diagnostics)
        stream << d.toString() << '\n';
}

/// Findings in file order, so that a reader can walk through them top to bottom.
Diagnostics sorted(Diagnostics diagnostics)
{
    std::stable_sort(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic &a, const Diagnostic &b) {
                         return std::tie(a.line, a.column) < std::tie(b.line, b.column);
                     });
    return diagnostics;
}

bool counts(const Diagnostic &d)
{
    return d.severity != Diagnostic::Severity::Info;
}

} // namespace

QString ProfileCommand::summary() const
{
    return QStringLiteral("check and convert RTC/RTS profile files");
}

QString ProfileCommand::usage() const
{
    return QStringLiteral(
        "Usage:\n"
        "  rtctl profile check FILE...   read and validate profiles; one line per finding\n"
        "  rtctl profile convert IN OUT  write IN as OUT; format by extension (.xml, .yaml)\n\n"
        "FILE may be an RTC Profile (RTC.xml) or an RTS Profile (system file), XML or YAML.\n"
        "check exits 0 when every file is valid, 1 when any finding was printed, 2 on usage "
        "errors.\n");
}

int ProfileCommand::run(const QStringList &arguments, Streams streams)
{
    if (arguments.isEmpty())
        return usageError(QStringLiteral("missing sub-command (check or convert)"), streams);
    const QString sub = arguments.first();
    if (sub == QLatin1String("check"))
        return check(arguments.mid(1), streams);
    if (sub == QLatin1String("convert"))
        return convert(arguments.mid(1), streams);
    return usageError(QStringLiteral("unknown sub-command '%1'").arg(sub), streams);
}

int ProfileCommand::check(const QStringList &files, Streams streams) const
{
    if (files.isEmpty())
        return usageError(QStringLiteral("check needs at least one file"), streams);
    bool anyFinding = false;
    for (const QString &file : files) {
        Diagnostics diagnostics;
        const auto loaded = loadProfileFile(file, &diagnostics);
        if (loaded) {
            diagnostics = loaded->diagnostics;
            if (loaded->rtc)
                diagnostics += validateRtcProfile(*loaded->rtc, file);
            else if (loaded->rts)
                diagnostics += validateRtsProfile(*loaded->rts, file);
        }
        diagnostics = sorted(diagnostics);
        print(diagnostics, streams.err);
        const bool findings = std::any_of(diagnostics.cbegin(), diagnostics.cend(), counts);
        anyFinding = anyFinding || findings;
        if (!findings)
            streams.out << file << ": ok\n";
    }
    return anyFinding ? ExitProblems : ExitOk;
}

int ProfileCommand::convert(const QStringList &arguments, Streams streams) const
{
    if (arguments.size() != 2)
        return usageError(QStringLiteral("convert needs exactly IN and OUT"), streams);
    const QString in = arguments.at(0);
    const QString out = arguments.at(1);
    Diagnostics diagnostics;
    const auto loaded = loadProfileFile(in, &diagnostics);
    bool saved = false;
    if (loaded && loaded->rtc)
        saved = saveRtcProfileFile(*loaded->rtc, out, &diagnostics);
    else if (loaded && loaded->rts)
        saved = saveRtsProfileFile(*loaded->rts, out, &diagnostics);
    print(sorted(diagnostics), streams.err);
    if (!saved)
        return ExitProblems;
    streams.out << in << " -> " << out << '\n';
    return ExitOk;
}

} // namespace Cli
