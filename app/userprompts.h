// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "profileio.h"
#include "systemprofileinfo.h"

#include <QString>
#include <QStringList>

namespace Studio {

/**
 * Every question the application asks the user, and every modal message it shows.
 *
 * The main window asks through this interface instead of calling QMessageBox or QFileDialog
 * itself, so that tests can answer the questions without modal dialogs (see DialogPrompts for the
 * real implementation).
 */
class UserPrompts
{
public:
    /// The answer to "this document has unsaved changes".
    enum class SaveChoice { Save, Discard, Cancel };

    virtual ~UserPrompts() = default;

    /// Asks whether to save `documentName` before it is closed.
    virtual SaveChoice askSaveChanges(const QString &documentName) = 0;
    /// Asks for profile files to open; an empty list means cancelled.
    virtual QStringList askOpenFileNames(const QString &directory) = 0;
    /// Asks where to save a profile of `kind`; an empty string means cancelled.
    virtual QString askSaveFileName(Profile::ProfileKind kind, const QString &suggestedPath) = 0;
    /// Tells the user that something failed; `diagnostics` carry the details.
    virtual void showProblems(const QString &title, const QString &text,
                              const Profile::Diagnostics &diagnostics)
        = 0;
    /// Shows the About box.
    virtual void showAbout() = 0;
    /**
     * Asks a system's profile information before it is saved: vendor, name, version, abstract
     * and which of `components` are required. Nothing means cancelled (nothing is saved). Without
     * anyone to ask, the current information is kept.
     */
    virtual std::optional<SystemEditor::SystemProfileInfo>
    askSystemProfileInfo(const SystemEditor::SystemProfileInfo &current,
                         const QStringList &components)
    {
        Q_UNUSED(components)
        return current;
    }
    /// Asks where to export a diagram (.png or .svg); an empty string means cancelled. Without
    /// anyone to ask, nothing is exported.
    virtual QString askExportFileName(const QString &suggestedPath)
    {
        Q_UNUSED(suggestedPath)
        return {};
    }
};

} // namespace Studio
