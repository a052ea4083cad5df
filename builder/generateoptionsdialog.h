// SPDX-License-Identifier: MIT
#pragma once

#include "generateprompts.h"

#include <QDialog>

class QCheckBox;
class QLineEdit;
class QSpinBox;

namespace Builder {

/**
 * Asked on Generate: the folder the component's project is written to (with Browse…), how
 * many backups of each generated file are kept, and whether the C++ test component is written
 * under `test/` too.
 */
class GenerateOptionsDialog : public QDialog
{
    Q_OBJECT

public:
    explicit GenerateOptionsDialog(const GenerateOptions &current, QWidget *parent = nullptr);

    GenerateOptions options() const;
    QLineEdit *folderEdit() const { return m_folder; }
    QSpinBox *backupsBox() const { return m_backups; }
    QCheckBox *testComponentBox() const { return m_testComponent; }

private:
    void browse();

    QLineEdit *m_folder;
    QSpinBox *m_backups;
    QCheckBox *m_testComponent;
};

} // namespace Builder
