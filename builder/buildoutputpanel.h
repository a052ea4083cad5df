// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QToolButton;

namespace Builder {

/**
 * The Builder's build output: what cmake, the build tool and the compilers print, as it comes,
 * with a progress bar (a busy bar while the count is unknown), a status line and Cancel.
 * It only shows; BuildController fills it.
 */
class BuildOutputPanel : public QWidget
{
    Q_OBJECT

public:
    explicit BuildOutputPanel(QWidget *parent = nullptr);

    /// Clears the output and shows the panel busy (`running`) or idle.
    void startBuild(const QString &status);
    void appendLine(const QString &line);
    /// `total` 0: busy without a count.
    void setProgress(int done, int total);
    /// Leaves the running state with `status` as the last word.
    void finishBuild(bool ok, const QString &status);

    QString text() const;
    QString status() const;
    bool isRunning() const { return m_running; }
    QPlainTextEdit *outputView() const { return m_output; }
    QProgressBar *progressBar() const { return m_progress; }
    QToolButton *cancelButton() const { return m_cancel; }

signals:
    void cancelRequested();

private:
    QPlainTextEdit *m_output;
    QProgressBar *m_progress;
    QLabel *m_status;
    QToolButton *m_cancel;
    bool m_running = false;
};

} // namespace Builder
