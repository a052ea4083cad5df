// SPDX-License-Identifier: MIT
#include "gencommand.h"

#include "codegenerator.h"
#include "idlsearchpath.h"
#include "idltypelibrary.h"
#include "installation.h"
#include "profileio.h"
#include "projectwriter.h"

#include <QDir>
#include <QFileInfo>

using namespace Codegen;
using namespace Profile;

namespace Cli {

namespace {

struct GenOptions
{
    QString profile;
    QString outputDir;
    QList<TargetLanguage> languages;
    QStringList idlDirs;
    QString templates;
    FileDecision decision = FileDecision::Keep;
    int backups = 3;
    bool testComponent = false;
};

void print(const Diagnostics &diagnostics, QTextStream &stream)
{
    for (const Diagnostic &d : diagnostics)
        stream << d.toString() << '\n';
}

void printReport(const WriteReport &report, QTextStream &out)
{
    auto list = [&out](const char *what, const QStringList &paths) {
        for (const QString &path : paths)
            out << what << ' ' << path << '\n';
    };
    list("created", report.created);
    list("merged", report.merged);
    list("overwritten", report.overwritten);
    list("kept", report.kept);
    list("unchanged", report.unchanged);
    list("backup", report.backups);
    list("pruned", report.pruned);
}

/// Reads the command line into `options`; returns the usage problem, or an empty string.
QString parseArguments(const QStringList &arguments, GenOptions *options)
{
    for (int i = 0; i < arguments.size(); ++i) {
        const QString &arg = arguments.at(i);
        const bool hasValue = i + 1 < arguments.size();
        if (arg == QLatin1String("--lang") || arg == QLatin1String("-o")
            || arg == QLatin1String("--output") || arg == QLatin1String("--idl-dir")
            || arg == QLatin1String("--templates") || arg == QLatin1String("--backups")) {
            if (!hasValue)
                return QStringLiteral("%1 needs a value").arg(arg);
            const QString value = arguments.at(++i);
            if (arg == QLatin1String("--lang")) {
                const std::optional<TargetLanguage> language = targetLanguageFromString(value);
                if (!language)
                    return QStringLiteral("unknown language '%1'").arg(value);
                if (!options->languages.contains(*language))
                    options->languages << *language;
            } else if (arg == QLatin1String("--idl-dir")) {
                options->idlDirs << value;
            } else if (arg == QLatin1String("--templates")) {
                options->templates = value;
            } else if (arg == QLatin1String("--backups")) {
                bool ok = false;
                options->backups = value.toInt(&ok);
                if (!ok || options->backups < 0)
                    return QStringLiteral("--backups needs a number >= 0");
            } else {
                options->outputDir = value;
            }
        } else if (arg == QLatin1String("--keep")) {
            options->decision = FileDecision::Keep;
        } else if (arg == QLatin1String("--merge")) {
            options->decision = FileDecision::Merge;
        } else if (arg == QLatin1String("--overwrite")) {
            options->decision = FileDecision::Overwrite;
        } else if (arg == QLatin1String("--test-component")) {
            options->testComponent = true;
        } else if (arg.startsWith(QLatin1Char('-'))) {
            return QStringLiteral("unknown option '%1'").arg(arg);
        } else if (options->profile.isEmpty()) {
            options->profile = arg;
        } else {
            return QStringLiteral("more than one profile given");
        }
    }
    if (options->profile.isEmpty())
        return QStringLiteral("missing RTC.xml");
    if (options->languages.isEmpty())
        return QStringLiteral("missing --lang");
    if (options->outputDir.isEmpty())
        return QStringLiteral("missing -o DIR");
    return QString();

}

} // namespace

QString GenCommand::summary() const
{
    return QStringLiteral("generate a component project (C++, Python, Java) from RTC.xml");
}

QString GenCommand::usage() const
{
    return QStringLiteral(
        "Usage:\n"
        "  rtctl gen RTC.xml --lang LANG [--lang LANG]... -o DIR [options]\n\n"
        "  --lang LANG       cpp, python or java (repeatable)\n"
        "  -o, --output DIR  project folder to write (created when missing)\n"
        "  --idl-dir DIR     more folders with IDL files (repeatable); OpenRTM's IDL, the\n"
        "                    profile's folder and its idl/ are always searched\n"
        "  --keep            keep existing files that differ (default)\n"
        "  --merge           refresh only the <rtc-template> regions of existing files\n"
        "  --overwrite       replace existing files that differ\n"
        "  --templates DIR   user template folder overriding the built-in templates\n"
        "  --backups N       backups kept per file (default 3)\n"
        "  --test-component  also write test/: the project of <N>Test (C++ with --lang cpp, else\n"
        "                    Python with --lang python), whose ports mirror the component's, to\n"
        "                    exercise it by connecting the two\n\n"
        "Merged and overwritten files are first renamed to <file>YYYYMMDDHHMMSS.\n"
        "Exit codes: 0 generated, 1 problems (nothing written), 2 usage error.\n");
}

int GenCommand::run(const QStringList &arguments, Streams streams)
{
    GenOptions options;
    const QString problem = parseArguments(arguments, &options);
    if (!problem.isEmpty())
        return usageError(problem, streams);
    Diagnostics diagnostics;
    const std::optional<LoadedProfile> loaded = loadProfileFile(options.profile, &diagnostics);
    if (!loaded || !loaded->rtc) {
        if (loaded && !loaded->rtc)
            diagnostics << Diagnostic::error(options.profile, 0, 0,
                                             QStringLiteral("not an RTC Profile"));
        print(diagnostics, streams.err);
        return ExitProblems;
    }
    const IdlTypeLibrary library(
        idlSearchDirs(*loaded->rtc, QFileInfo(options.profile).absolutePath(),
                      {Codegen::Installation::bundledIdlDirectory()}, options.idlDirs));
    CodeGenerator generator(*loaded->rtc, library.model());
    generator.setUserTemplateFolder(options.templates);
    generator.setTestComponent(options.testComponent);
    Diagnostics problems;
    const std::optional<QList<GeneratedFile>> files = generator.generate(options.languages, &problems);
    if (!files) {
        // IDL problems explain a missing interface type, so they are shown with the failure.
        print(library.diagnostics(), streams.err);
        print(problems, streams.err);
        return ExitProblems;
    }
    ProjectWriter writer(options.outputDir);
    const FileDecision decision = options.decision;
    writer.setDecisionCallback([decision](const QString &) { return decision; });
    writer.setBackupsKept(options.backups);
    const std::optional<WriteReport> report = writer.write(*files, &problems);
    print(problems, streams.err);
    if (!report)
        return ExitProblems;
    printReport(*report, streams.out);
    for (const QString &warning : report->warnings)
        streams.err << "warning: " << warning << '\n';
    return ExitOk;
}

} // namespace Cli
