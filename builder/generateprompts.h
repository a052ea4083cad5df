// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "projectwriter.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <optional>

namespace Builder {

/// Where and how Generate writes: asked for on every Generate, remembered in between.
struct GenerateOptions
{
    QString outputFolder; ///< the component's project folder
    int backupsKept = 3; ///< backups kept per generated file
    bool testComponent = false; ///< also write the C++ test component under `test/`

    bool operator==(const GenerateOptions &other) const
    {
        return outputFolder == other.outputFolder && backupsKept == other.backupsKept
            && testComponent == other.testComponent;
    }
    bool operator!=(const GenerateOptions &other) const { return !(*this == other); }
};

/// The user's answer for one existing file that differs from the fresh one.
struct FileChoice
{
    Codegen::FileDecision decision = Codegen::FileDecision::Keep;
    bool applyToAll = false; ///< use the same decision for the remaining files of this run
};

/**
 * Every question Generate, Code restore and Clear backups ask, and the summary they show.
 * GenerateController asks through this interface so that tests answer without modal dialogs;
 * GenerateDialogPrompts is the real implementation.
 */
class GeneratePrompts
{
public:
    virtual ~GeneratePrompts() = default;

    /// Asks for the output folder, the backups kept and the test component; nothing: cancelled.
    virtual std::optional<GenerateOptions> askGenerateOptions(const GenerateOptions &current) = 0;
    /// Asks what to do with `relativePath`, whose `existing` content differs from `fresh`.
    virtual FileChoice askFileDecision(const QString &relativePath, const QByteArray &existing,
                                       const QByteArray &fresh)
        = 0;
    /// Asks which backup set (stamps newest first) to restore; empty means cancelled.
    virtual QString askRestoreStamp(const QString &projectDir, const QStringList &stamps) = 0;
    /// Asks whether to delete the `count` backup files below `projectDir`.
    virtual bool confirmClearBackups(const QString &projectDir, int count) = 0;
    /// Shows what an action did (`text`) and the problems it met.
    virtual void showSummary(const QString &title, const QString &text,
                             const Profile::Diagnostics &problems)
        = 0;
};

} // namespace Builder
