// SPDX-License-Identifier: MIT
#pragma once

#include "generateprompts.h"

#include <QDialog>

class QLineEdit;
class QSpinBox;

namespace Builder {

/**
 * Asked on Generate: the folder the component's project is written to (with Browse…) and how
 * many backups of each generated file are kept.
 */
class GenerateOptionsDialog : public QDialog
{
    Q_OBJECT

public:
    explicit GenerateOptionsDialog(const GenerateOptions &current, QWidget *parent = nullptr);

    GenerateOptions options() const;
    QLineEdit *folderEdit() const { return m_folder; }
    QSpinBox *backupsBox() const { return m_backups; }

private:
    void browse();

    QLineEdit *m_folder;
    QSpinBox *m_backups;
};

} // namespace Builder
