// SPDX-License-Identifier: MIT
#pragma once

#include "generateprompts.h"

#include <QPointer>
#include <QWidget>

#include <functional>

namespace Builder {

class ComponentEditor;
class GenerateController;

/// GeneratePrompts answered by the user through modal dialogs over `parent`.
class GenerateDialogPrompts : public GeneratePrompts
{
public:
    explicit GenerateDialogPrompts(QWidget *parent);

    std::optional<GenerateOptions> askGenerateOptions(const GenerateOptions &current) override;
    FileChoice askFileDecision(const QString &relativePath, const QByteArray &existing,
                               const QByteArray &fresh) override;
    QString askRestoreStamp(const QString &projectDir, const QStringList &stamps) override;
    bool confirmClearBackups(const QString &projectDir, int count) override;
    void showSummary(const QString &title, const QString &text,
                     const Profile::Diagnostics &problems) override;
    /// Generate's summary is shown elsewhere while `quiet` says so (no modal box then).
    void setGenerateSummaryQuiet(std::function<bool()> quiet) { m_quiet = std::move(quiet); }

private:
    QPointer<QWidget> m_parent;
    std::function<bool()> m_quiet;
};

/**
 * Gives `editor` its Generate, Code restore and Clear backups: a GenerateController (a child of
 * the editor) asking through dialogs over it. `profilePath` tells where the profile is saved
 * (for IDL next to it); it may be empty. Outcomes go to ComponentEditor::reportGeneration();
 * while something listens there, Generate shows no summary box. The editor gets its Build over
 * the same output folder too (installBuildController()).
 */
GenerateController *installGenerateController(ComponentEditor *editor,
                                              std::function<QString()> profilePath);

} // namespace Builder
