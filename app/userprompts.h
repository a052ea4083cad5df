// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "profileio.h"

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
};

} // namespace Studio
