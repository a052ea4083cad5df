// SPDX-License-Identifier: MIT
#pragma once

#include "userprompts.h"

class QWidget;

namespace Studio {

/// UserPrompts answered by the user through QMessageBox and QFileDialog.
class DialogPrompts : public UserPrompts
{
public:
    /// Dialogs are shown over `parent`, which must outlive this object.
    explicit DialogPrompts(QWidget *parent);

    SaveChoice askSaveChanges(const QString &documentName) override;
    QStringList askOpenFileNames(const QString &directory) override;
    QString askSaveFileName(Profile::ProfileKind kind, const QString &suggestedPath) override;
    void showProblems(const QString &title, const QString &text,
                      const Profile::Diagnostics &diagnostics) override;
    void showAbout() override;
    std::optional<SystemEditor::SystemProfileInfo>
    askSystemProfileInfo(const SystemEditor::SystemProfileInfo &current,
                         const QStringList &components) override;
    QString askExportFileName(const QString &suggestedPath) override;

private:
    QWidget *m_parent;
};

} // namespace Studio
