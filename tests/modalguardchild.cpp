// SPDX-License-Identifier: MIT
// Dialogs opened under the shared modal-dialog guard (common/modalguard.h), expected and not.
// Run by tst_modalguard as a child process, one function set at a time: some functions fail on
// purpose, so this executable is not a CTest test of its own.
#include "modalguard.h"

#include <QDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTest>

using GuiTest::ModalGuard;

class ModalGuardChild : public QObject
{
    Q_OBJECT

private slots:
    void unexpectedMessageBox();
    void unexpectedWindowModalDialog();
    void expectedMessageBoxIsAnswered();
    void expectedDialogAnsweredByTheTest();
    void oneExpectationCoversOneDialog();
};

void ModalGuardChild::unexpectedMessageBox()
{
    QMessageBox::warning(nullptr, QStringLiteral("Disk Full"),
                         QStringLiteral("Could not write report.txt"));
    qInfo("message box closed");
}

void ModalGuardChild::unexpectedWindowModalDialog()
{
    QWidget window;
    window.show();
    QDialog dialog(&window);
    dialog.setWindowTitle(QStringLiteral("Connect"));
    new QLabel(QStringLiteral("Choose the ports"), &dialog);
    dialog.open();
    QTRY_VERIFY(!dialog.isVisible());
    QCOMPARE(dialog.result(), int(QDialog::Rejected));
}

void ModalGuardChild::expectedMessageBoxIsAnswered()
{
    QString shown;
    const ModalGuard::Expected expected([&shown](QWidget *dialog) {
        auto *box = qobject_cast<QMessageBox *>(dialog);
        QVERIFY(box);
        shown = box->text();
        box->button(QMessageBox::No)->click();
    });
    QCOMPARE(QMessageBox::question(nullptr, QStringLiteral("Overwrite"),
                                   QStringLiteral("Overwrite RTC.xml?")),
             QMessageBox::No);
    QVERIFY(expected.seen());
    QCOMPARE(shown, QStringLiteral("Overwrite RTC.xml?"));
}

void ModalGuardChild::expectedDialogAnsweredByTheTest()
{
    const ModalGuard::Expected expected;
    QDialog dialog;
    dialog.open();
    QVERIFY(expected.seen());
    dialog.accept();
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
}

void ModalGuardChild::oneExpectationCoversOneDialog()
{
    const ModalGuard::Expected expected(
        [](QWidget *dialog) { static_cast<QDialog *>(dialog)->accept(); });
    QMessageBox::information(nullptr, QStringLiteral("First"), QStringLiteral("expected"));
    QMessageBox::information(nullptr, QStringLiteral("Second"), QStringLiteral("not expected"));
}

QTEST_MAIN(ModalGuardChild)
#include "modalguardchild.moc"
