// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QComboBox;
class QPushButton;

namespace Builder {

/**
 * Run in Manager's chooser: which manager (`host:port`, typed or one used before) should load
 * `modulePath` and create the component. It is not modal: Run emits runRequested() and closes.
 */
class RunManagerDialog : public QDialog
{
    Q_OBJECT

public:
    RunManagerDialog(const QStringList &addresses, const QString &modulePath,
                     QWidget *parent = nullptr);

    QString address() const;
    void setAddress(const QString &address);
    QComboBox *addressBox() const { return m_address; }
    QPushButton *runButton() const { return m_runButton; }

signals:
    void runRequested(const QString &address);

private:
    void run();

    QComboBox *m_address;
    QPushButton *m_runButton;
};

} // namespace Builder
