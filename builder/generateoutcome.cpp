// SPDX-License-Identifier: MIT
#include "generateoutcome.h"

#include <QCoreApplication>
#include <QDir>

namespace Builder {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Builder::GenerateOutcome)
};

void addFiles(Profile::Diagnostics *rows, const QDir &folder, const QStringList &paths,
              const QString &what)
{
    for (const QString &path : paths) {
        Profile::Diagnostic row;
        row.severity = Profile::Diagnostic::Severity::Info;
        row.file = QDir::cleanPath(folder.filePath(path));
        row.message = what;
        rows->append(row);
    }
}

} // namespace

GenerateOutcome GenerateOutcome::fromReport(const QString &folder,
                                            const Codegen::WriteReport &report)
{
    GenerateOutcome outcome;
    outcome.succeeded = true;
    const QDir dir(folder);
    // Warnings first: they are what the user should look at.
    for (const QString &warning : report.warnings)
        outcome.diagnostics.append(Profile::Diagnostic::warning(folder, 0, 0, warning));
    addFiles(&outcome.diagnostics, dir, report.created, Text::tr("created"));
    addFiles(&outcome.diagnostics, dir, report.merged,
             Text::tr("merged (generated regions refreshed, your code kept)"));
    addFiles(&outcome.diagnostics, dir, report.overwritten, Text::tr("overwritten"));
    addFiles(&outcome.diagnostics, dir, report.kept, Text::tr("kept as it was (not regenerated)"));
    addFiles(&outcome.diagnostics, dir, report.backups, Text::tr("backup of the previous file"));
    const int written
        = int(report.created.size() + report.merged.size() + report.overwritten.size());
    outcome.summary = Text::tr("Generated into %1: %2 written, %3 kept, %4 unchanged.")
                          .arg(QDir::toNativeSeparators(folder))
                          .arg(written)
                          .arg(report.kept.size())
                          .arg(report.unchanged.size());
    return outcome;
}

GenerateOutcome GenerateOutcome::refused(const Profile::Diagnostics &problems)
{
    GenerateOutcome outcome;
    outcome.diagnostics = problems;
    outcome.summary = Text::tr("Generate refused: %n problem(s) to fix first.", nullptr, int(problems.size()));
    return outcome;
}

GenerateOutcome GenerateOutcome::failed(const Profile::Diagnostics &problems)
{
    GenerateOutcome outcome;
    outcome.diagnostics = problems;
    outcome.summary = Text::tr("Code generation failed with %n problem(s).", nullptr, int(problems.size()));
    return outcome;
}

bool GenerateOutcome::needsAttention() const
{
    for (const Profile::Diagnostic &d : diagnostics) {
        if (d.severity != Profile::Diagnostic::Severity::Info)
            return true;
    }
    return false;
}

} // namespace Builder
