// SPDX-License-Identifier: MIT
#include "projectwriter.h"

#include "backups.h"
#include "regionmerge.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

using namespace Profile;

namespace Codegen {

namespace {

Diagnostic writeError(const QString &file, const QString &message)
{
    return Diagnostic::error(file, 0, 0, message);
}

bool writeBytes(const QString &path, const QByteArray &data)
{
    if (!QDir().mkpath(QFileInfo(path).absolutePath()))
        return false;
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(data) != data.size()
        || !file.flush())
        return false;
    // Generated scripts (idlcompile.sh, <N>.sh) are meant to be run as they are.
    if (path.endsWith(QLatin1String(".sh")))
        file.setPermissions(file.permissions() | QFileDevice::ExeOwner | QFileDevice::ExeGroup
                            | QFileDevice::ExeOther);
    return true;
}

} // namespace

ProjectWriter::ProjectWriter(const QString &projectDir)
    : m_projectDir(QDir(projectDir).absolutePath())
    , m_decide([](const QString &) { return FileDecision::Keep; })
    , m_clock([] { return QDateTime::currentDateTime(); })
{
}

std::optional<QList<ProjectWriter::Plan>> ProjectWriter::plan(const QList<GeneratedFile> &files,
                                                              WriteReport *report,
                                                              Diagnostics *diagnostics) const
{
    QList<Plan> plans;
    const QDir dir(m_projectDir);
    for (const GeneratedFile &file : files) {
        if (!CodeGenerator::isSafeRelativePath(file.path)) {
            diagnostics->append(writeError(file.path, QStringLiteral("refusing to write outside "
                                                                     "the project folder")));
            return std::nullopt;
        }
        Plan p{file, FileDecision::Overwrite, false};
        QFile existing(dir.filePath(file.path));
        if (existing.exists()) {
            if (!existing.open(QIODevice::ReadOnly)) {
                diagnostics->append(writeError(existing.fileName(), existing.errorString()));
                return std::nullopt;
            }
            const QByteArray old = existing.readAll();
            if (old == file.content) {
                report->unchanged << file.path;
                continue;
            }
            p.exists = true;
            p.decision = m_decide(file.path);
            if (p.decision == FileDecision::Keep) {
                report->kept << file.path;
                continue;
            }
            if (p.decision == FileDecision::Merge) {
                const RegionMergeResult merged = mergeTemplateRegions(
                    QString::fromUtf8(old), QString::fromUtf8(file.content));
                if (!merged.text) {
                    diagnostics->append(writeError(existing.fileName(), merged.error));
                    return std::nullopt;
                }
                for (const QString &block : merged.notInExisting)
                    report->warnings << QStringLiteral("%1: block \"%2\" is no longer in the file; "
                                                       "it was not merged")
                                            .arg(file.path, block);
                p.file.content = merged.text->toUtf8();
            }
        }
        plans << p;
    }
    return plans;
}

QString ProjectWriter::freeStamp(const QList<Plan> &plans) const
{
    // Two runs within one second would share a stamp; move on until no backup name is taken,
    // so that an earlier backup is never overwritten.
    QDateTime when = m_clock();
    for (;;) {
        const QString stamp = Backups::stamp(when);
        const bool taken = std::any_of(plans.cbegin(), plans.cend(), [&](const Plan &p) {
            return p.exists
                && QFileInfo::exists(Backups::backupPath(QDir(m_projectDir).filePath(p.file.path),
                                                         stamp));
        });
        if (!taken)
            return stamp;
        when = when.addSecs(1);
    }
}

std::optional<WriteReport> ProjectWriter::write(const QList<GeneratedFile> &files,
                                                Diagnostics *diagnostics) const
{
    WriteReport report;
    if (!QDir().mkpath(m_projectDir)) {
        diagnostics->append(writeError(m_projectDir, QStringLiteral("cannot create the folder")));
        return std::nullopt;
    }
    const std::optional<QList<Plan>> plans = plan(files, &report, diagnostics);
    if (!plans)
        return std::nullopt;
    // Stage inside the project folder: the final renames then stay on one file system.
    QTemporaryDir staging(QDir(m_projectDir).filePath(QStringLiteral(".rtstudio-gen-XXXXXX")));
    if (!staging.isValid()) {
        diagnostics->append(writeError(m_projectDir, staging.errorString()));
        return std::nullopt;
    }
    for (const Plan &p : *plans) {
        if (!writeBytes(staging.filePath(p.file.path), p.file.content)) {
            diagnostics->append(writeError(QDir(m_projectDir).filePath(p.file.path),
                                           QStringLiteral("cannot write the file")));
            return std::nullopt;
        }
    }
    const QString stamp = freeStamp(*plans);
    const QDir dir(m_projectDir);
    for (const Plan &p : *plans) {
        const QString target = dir.filePath(p.file.path);
        if (p.exists) {
            const QString backup = Backups::backupPath(target, stamp);
            if (!QFile::rename(target, backup)) {
                diagnostics->append(writeError(target, QStringLiteral("cannot make a backup")));
                return std::nullopt;
            }
            report.backups << dir.relativeFilePath(backup);
        }
        QDir().mkpath(QFileInfo(target).absolutePath());
        if (!QFile::rename(staging.filePath(p.file.path), target)) {
            diagnostics->append(writeError(target, QStringLiteral("cannot move the new file "
                                                                  "into place")));
            return std::nullopt;
        }
        if (!p.exists)
            report.created << p.file.path;
        else if (p.decision == FileDecision::Merge)
            report.merged << p.file.path;
        else
            report.overwritten << p.file.path;
        if (p.exists) {
            for (const QString &removed : Backups::prune(target, m_backupsKept))
                report.pruned << dir.relativeFilePath(removed);
        }
    }
    return report;
}

} // namespace Codegen
