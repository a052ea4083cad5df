// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QLabel;
class QPushButton;
class QTimer;

namespace Studio {

class DocumentController;

/**
 * The status bar's part while a file is being read: what is opened, a busy bar and Cancel. The
 * window stays painted meanwhile but takes no other input (a second open, a close, an edit could
 * not wait for the first); Cancel stays clickable. Shown only when reading takes a moment.
 */
class OpeningProgress : public QWidget
{
    Q_OBJECT

public:
    OpeningProgress(DocumentController *controller, QWidget *parent = nullptr);
    ~OpeningProgress() override;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void started(const QString &filePath);
    void finished();

    QLabel *m_label;
    QPushButton *m_cancel;
    QTimer *m_delay;
    bool m_blocking = false;
};

} // namespace Studio
