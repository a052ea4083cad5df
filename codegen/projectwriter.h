// SPDX-License-Identifier: MIT
#pragma once

#include "codegenerator.h"

#include <QDateTime>

#include <functional>

namespace Codegen {

/// What to do with an existing file whose content differs from the fresh one.
enum class FileDecision {
    Keep, ///< leave the user's file as it is
    Merge, ///< keep the user's file, refresh only its `<rtc-template>` regions
    Overwrite ///< replace it with the fresh file
};

/// What a write did, by relative path.
struct WriteReport
{
    QStringList created;
    QStringList unchanged; ///< existing files that already had the fresh content
    QStringList kept;
    QStringList merged;
    QStringList overwritten;
    QStringList backups; ///< backup files made (relative paths)
    QStringList pruned; ///< old backups deleted (relative paths)
    QStringList warnings; ///< e.g. fresh blocks a merged file no longer has
};

/**
 * Writes a generated project over a folder that may already hold an earlier (edited) one.
 *
 * Files that do not exist are created; identical files are left alone; for each other file
 * `decide(relativePath)` chooses keep / merge / overwrite. All new contents (fresh or merged) are
 * first written into a temporary folder inside the project folder; only when every one was
 * written are they moved into place, each merged or overwritten file first renamed to
 * `<file>YYYYMMDDHHMMSS` (one stamp per run), and older backups beyond `backupsKept` deleted.
 * A failure before the moves leaves the project folder as it was.
 */
class ProjectWriter
{
public:
    using DecisionCallback = std::function<FileDecision(const QString &relativePath)>;

    explicit ProjectWriter(const QString &projectDir);

    void setDecisionCallback(DecisionCallback decide) { m_decide = std::move(decide); }
    void setBackupsKept(int count) { m_backupsKept = count; }
    /// The time stamped on backups (default: now when write() runs).
    void setClock(std::function<QDateTime()> clock) { m_clock = std::move(clock); }

    std::optional<WriteReport> write(const QList<GeneratedFile> &files,
                                     Profile::Diagnostics *diagnostics) const;

private:
    struct Plan
    {
        GeneratedFile file;
        FileDecision decision = FileDecision::Overwrite;
        bool exists = false;
    };
    std::optional<QList<Plan>> plan(const QList<GeneratedFile> &files, WriteReport *report,
                                    Profile::Diagnostics *diagnostics) const;
    QString freeStamp(const QList<Plan> &plans) const;

    QString m_projectDir;
    DecisionCallback m_decide;
    int m_backupsKept = 3;
    std::function<QDateTime()> m_clock;
};

} // namespace Codegen
