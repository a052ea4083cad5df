// SPDX-License-Identifier: MIT
#pragma once

#include "systemprofileinfo.h"

#include <QDialog>

class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;
class QUndoCommand;

namespace SystemEditor {

class SystemModel;

/**
 * The reference's "profile information" dialog asked when a system is saved: vendor, system name
 * and version (the id `RTSystem:<vendor>:<name>:<version>`), the abstract, and which components
 * are required. OK is enabled only while the info is acceptable (SystemProfileInfo::problems()).
 * Widgets have object names (`vendorEdit`, `systemNameEdit`, `versionEdit`, `abstractEdit`,
 * `requiredList`) by which tests find them.
 */
class SaveProfileDialog : public QDialog
{
    Q_OBJECT

public:
    /// Pre-filled with `info`; `components` are the instance names listed with a check box.
    SaveProfileDialog(const SystemProfileInfo &info, const QStringList &components,
                      QWidget *parent = nullptr);

    /// The info as edited (the dates are kept as given).
    SystemProfileInfo info() const;

    /// Sets whether `instanceName` is ticked as required; false when it is not listed.
    bool setRequired(const QString &instanceName, bool required);

    /**
     * The one undoable step that gives `model` the edited `info` (id, abstract and required
     * flags), or null when it changes nothing.
     */
    static QUndoCommand *applyCommand(SystemModel *model, const SystemProfileInfo &info);

private:
    QLineEdit *addLine(const QString &objectName, const QString &text);
    void updateProblems();

    SystemProfileInfo m_original;
    QLineEdit *m_vendor;
    QLineEdit *m_name;
    QLineEdit *m_version;
    QPlainTextEdit *m_abstract;
    QListWidget *m_required;
    QLabel *m_problems;
    QDialogButtonBox *m_buttons;
};

} // namespace SystemEditor
