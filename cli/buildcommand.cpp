// SPDX-License-Identifier: MIT
#include "buildcommand.h"

#include "interruptsignals.h"
#include "projectbuilder.h"

#include <QEventLoop>

using namespace Codegen;
using namespace Profile;

namespace Cli {

namespace {

/// Reads the command line into `options`; returns the usage problem, or an empty string.
QString parseArguments(const QStringList &arguments, BuildOptions *options)
{
    options->prefixPath = ProjectBuilder::defaultSdkPrefix();
    for (int i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        const bool hasValue = i + 1 < arguments.size();
        if (arg == QLatin1String("--prefix") || arg == QLatin1String("--config")
            || arg == QLatin1String("-j")) {
            if (!hasValue)
                return QStringLiteral("%1 needs a value").arg(arg);
            const QString value = arguments.at(++i);
            if (arg == QLatin1String("--prefix")) {
                options->prefixPath = value;
            } else if (arg == QLatin1String("--config")) {
                if (value != QLatin1String("Release") && value != QLatin1String("Debug"))
                    return QStringLiteral("--config is Release or Debug, not '%1'").arg(value);
                options->configuration = value;
            } else {
                bool ok = false;
                options->jobs = value.toInt(&ok);
                if (!ok || options->jobs < 1)
                    return QStringLiteral("-j needs a number >= 1");
            }
        } else if (arg == QLatin1String("--clean")) {
            options->clean = true;
        } else if (arg.startsWith(QLatin1Char('-'))) {
            return QStringLiteral("unknown option '%1'").arg(arg);
        } else if (options->projectDir.isEmpty()) {
            options->projectDir = arg;
        } else {
            return QStringLiteral("more than one folder given");
        }
    }
    if (options->projectDir.isEmpty())
        return QStringLiteral("missing DIR");
    return QString();
}

} // namespace

QString BuildCommand::summary() const
{
    return QStringLiteral("build a generated C++ component project with CMake, or check a Python one");
}

QString BuildCommand::usage() const
{
    return QStringLiteral(
               "Usage:\n"
               "  rtctl build DIR [--prefix PREFIX] [--config Release|Debug] [--clean] [-j N]\n\n"
               "  DIR               the project folder (its CMakeLists.txt), built in DIR/build\n"
               "  --prefix PREFIX   CMAKE_PREFIX_PATH, where OpenRTM-aist or RT Studio's SDK is\n"
               "                    installed (default %1; '' for none)\n"
               "  --config TYPE     Release (default) or Debug\n"
               "  --clean           rebuild everything\n"
               "  -j N              parallel jobs (default: one per processor core)\n\n"
               "Runs cmake -S DIR -B DIR/build, then cmake --build DIR/build, and prints their\n"
               "output; then lists the errors and warnings found as\n"
               "FILE:LINE:COL: severity: message.\n"
               "A Python project (DIR/<Name>.py beside RTC.xml) has its own IDL compiled by its\n"
               "idlcompile.sh, then the module loaded into a manager process of its own (rtmanager\n"
               "--module-profile): it must import with RT Studio's packages and register <Name>.\n"
               "Exit codes: 0 built, 1 configure or build failed, 2 usage error.\n")
        .arg(ProjectBuilder::defaultSdkPrefix());
}

int BuildCommand::run(const QStringList &arguments, Streams streams)
{
    BuildOptions options;
    const QString problem = parseArguments(arguments, &options);
    if (!problem.isEmpty())
        return usageError(problem, streams);
    ProjectBuilder builder;
    QEventLoop loop;
    bool built = false;
    QString message;
    QObject::connect(&builder, &ProjectBuilder::output, &loop, [&streams](const QString &line) {
        streams.out << line << '\n';
        streams.out.flush();
    });
    QObject::connect(&builder, &ProjectBuilder::finished, &loop, [&](bool ok, const QString &text) {
        built = ok;
        message = text;
        loop.quit();
    });
    // Ctrl+C and SIGTERM cancel the build instead of ending rtctl at once: the build runs in a
    // process group of its own, which the terminal's signal does not reach, so rtctl stops it (and
    // waits for it) before it exits.
    const InterruptSignals interrupts;
    QObject::connect(&interrupts, &InterruptSignals::received, &builder, &ProjectBuilder::cancel);
    // A build that cannot start reports finished() before start() returns.
    if (builder.start(options))
        loop.exec();
    for (const Diagnostic &d : builder.problems())
        streams.err << d.toString() << '\n';
    if (!built)
        streams.err << "rtctl build: " << message << '\n';
    streams.err.flush();
    return built ? ExitOk : ExitProblems;
}

} // namespace Cli
