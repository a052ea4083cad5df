// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QListWidget;
class QPlainTextEdit;

namespace Builder {

/**
 * "Code restore": lists the backup sets of a project folder (one per Generate, newest first,
 * by time stamp) with the files of the selected set, and returns the chosen stamp.
 */
class CodeRestoreDialog : public QDialog
{
    Q_OBJECT

public:
    CodeRestoreDialog(const QString &projectDir, const QStringList &stamps,
                      QWidget *parent = nullptr);

    /// The stamp (`YYYYMMDDHHMMSS`) of the selected set; empty when none is selected.
    QString selectedStamp() const;
    QListWidget *setList() const { return m_sets; }
    /// The files (relative paths) of the selected set, as listed.
    QStringList listedFiles() const;

private:
    void showFiles();

    QString m_projectDir;
    QListWidget *m_sets;
    QListWidget *m_files;
};

} // namespace Builder
