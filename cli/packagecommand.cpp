// SPDX-License-Identifier: MIT
#include "packagecommand.h"

#include "componentpackager.h"

namespace Cli {

namespace {

/// Reads the command line into @p options; the usage problem, or an empty string.
QString parseArguments(const QStringList &arguments, Packages::PackageOptions *options)
{
    for (int i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        const bool takesValue = arg == QLatin1String("-o") || arg == QLatin1String("--output")
            || arg == QLatin1String("--build-dir") || arg == QLatin1String("--name")
            || arg == QLatin1String("--maintainer") || arg == QLatin1String("--depends");
        if (takesValue) {
            if (i + 1 >= arguments.size())
                return QStringLiteral("%1 needs a value").arg(arg);
            const QString value = arguments.at(++i);
            if (arg == QLatin1String("--build-dir"))
                options->buildDir = value;
            else if (arg == QLatin1String("--name"))
                options->packageName = value;
            else if (arg == QLatin1String("--maintainer"))
                options->maintainer = value;
            else if (arg == QLatin1String("--depends"))
                options->depends << value;
            else
                options->output = value;
        } else if (arg.startsWith(QLatin1Char('-'))) {
            return QStringLiteral("unknown option '%1'").arg(arg);
        } else if (options->projectDir.isEmpty()) {
            options->projectDir = arg;
        } else {
            return QStringLiteral("more than one project folder given");
        }
    }
    return options->projectDir.isEmpty() ? QStringLiteral("missing the project folder") : QString();
}

} // namespace

QString PackageCommand::summary() const
{
    return QStringLiteral("make the Debian package (.deb) of a built component project");
}

QString PackageCommand::usage() const
{
    return QStringLiteral(
        "Usage:\n"
        "  rtctl package DIR [-o OUT] [options]\n\n"
        "Makes a Debian binary package of the component project DIR (RTC.xml at its top, built\n"
        "with CMake into DIR/build) with dpkg-deb; Depends comes from dpkg-shlibdeps.\n\n"
        "  -o, --output OUT   a .deb file name, or a folder for <package>_<version>_<arch>.deb\n"
        "                     (default: the current folder)\n"
        "  --build-dir DIR    where the project was built (default DIR/build)\n"
        "  --name PACKAGE     package name instead of rtc-<vendor>-<category>-<name>\n"
        "  --maintainer TEXT  \"Name <address>\" instead of the profile's creator or vendor\n"
        "  --depends PACKAGE  one more Depends entry, e.g. another component's package\n"
        "                     (repeatable)\n\n"
        "The package installs <Name>.so and <Name>Comp into\n"
        "/usr/lib/<multiarch>/rtstudio/components/<package>/ and RTC.xml, the *.conf files and\n"
        "idl/*.idl into /usr/share/rtstudio/components/<package>/. Besides the usual fields its\n"
        "control data has X-RTC-Types (the component type), X-RTC-Profile-Id,\n"
        "X-RTC-Profile-SHA256 (of RTC.xml) and X-RTStudio-SDK-ABI (the SDK library it links).\n"
        "Libraries from no Debian package are left out of Depends with a warning.\n"
        "Exit codes: 0 made, 1 refused (no RTC.xml, not built, invalid name or version, a tool\n"
        "failed), 2 usage error.\n");
}

int PackageCommand::run(const QStringList &arguments, Streams streams)
{
    Packages::PackageOptions options;
    const QString problem = parseArguments(arguments, &options);
    if (!problem.isEmpty())
        return usageError(problem, streams);
    QString error;
    const std::optional<Packages::PackageResult> result
        = Packages::ComponentPackager(options).build(&error);
    if (!result) {
        streams.err << "rtctl package: " << error << '\n';
        return ExitProblems;
    }
    for (const QString &warning : result->warnings)
        streams.err << "warning: " << warning << '\n';
    streams.out << result->debFile << '\n' << QString::fromUtf8(result->control.toText());
    return ExitOk;
}

} // namespace Cli
