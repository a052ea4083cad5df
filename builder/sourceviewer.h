// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QLabel;
class QPlainTextEdit;
class QToolButton;

namespace Builder {

/**
 * A read-only view of one text file (a generated source, a file a build complained about) with
 * the cursor on a given line and that line highlighted, so that a problem can be read where it
 * is. "Open Externally" hands the file to the desktop's editor; "Close" hides the viewer.
 */
class SourceViewer : public QWidget
{
    Q_OBJECT

public:
    explicit SourceViewer(QWidget *parent = nullptr);

    /// Shows `path` with the cursor at `line` (1-based; 0: the top) and `column`; false when the
    /// file cannot be read or is not text (then the viewer is left as it was).
    bool openFile(const QString &path, int line = 0, int column = 0);

    QString filePath() const { return m_path; }
    /// The 1-based line the cursor is on.
    int currentLine() const;
    QPlainTextEdit *editor() const { return m_editor; }

    /// True when `path` looks like text (no NUL byte near its start); binaries are not shown.
    static bool isTextFile(const QString &path);

signals:
    void closed();

private:
    void openExternally();

    QLabel *m_title;
    QPlainTextEdit *m_editor;
    QString m_path;
};

} // namespace Builder
