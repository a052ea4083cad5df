// SPDX-License-Identifier: MIT
// The shared modal-dialog guard of the GUI tests (common/modalguard.h): a dialog a test does not
// expect fails that test at once with the dialog's text and is closed, so the run goes on; an
// expected dialog passes. Each case runs modalguardchild as a child process, since failing is
// the point.
#include <QProcess>
#include <QTest>

namespace {

struct ChildRun
{
    bool finished = false;
    int exitCode = -1;
    QString output;
};

ChildRun runChild(const QStringList &functions)
{
    QProcess child;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
    child.setProcessEnvironment(environment);
    child.setProcessChannelMode(QProcess::MergedChannels);
    child.start(MODALGUARD_CHILD_PATH, functions);
    ChildRun run;
    // Only a hang comes near this bound: without the guard the first dialog never closes.
    run.finished = child.waitForFinished(60000);
    if (!run.finished) {
        child.kill();
        child.waitForFinished();
    }
    run.exitCode = child.exitStatus() == QProcess::NormalExit ? child.exitCode() : -1;
    run.output = QString::fromLocal8Bit(child.readAll());
    return run;
}

const QString failPrefix = QStringLiteral("FAIL!  : ModalGuardChild::");
const QString passPrefix = QStringLiteral("PASS   : ModalGuardChild::");

} // namespace

class TestModalGuard : public QObject
{
    Q_OBJECT

private slots:
    void reportsDialogs_data();
    void reportsDialogs();
    void failsWhileTheDialogIsOpenAndGoesOn();
};

void TestModalGuard::reportsDialogs_data()
{
    QTest::addColumn<QStringList>("functions");
    QTest::addColumn<int>("failures");
    QTest::addColumn<QStringList>("lines");
    QTest::addColumn<QStringList>("absent");
    QTest::newRow("unexpected message box")
        << QStringList {"unexpectedMessageBox"} << 1
        << QStringList {failPrefix + "unexpectedMessageBox() Unexpected modal dialog",
                        "QMessageBox \"Disk Full\": Could not write report.txt"}
        << QStringList {};
    QTest::newRow("unexpected window-modal dialog")
        << QStringList {"unexpectedWindowModalDialog"} << 1
        << QStringList {failPrefix + "unexpectedWindowModalDialog() Unexpected modal dialog",
                        "QDialog \"Connect\": Choose the ports"}
        << QStringList {};
    QTest::newRow("expected dialogs")
        << QStringList {"expectedMessageBoxIsAnswered", "expectedDialogAnsweredByTheTest"} << 0
        << QStringList {passPrefix + "expectedMessageBoxIsAnswered()",
                        passPrefix + "expectedDialogAnsweredByTheTest()"}
        << QStringList {"Unexpected modal dialog"};
    QTest::newRow("one expectation, two dialogs")
        << QStringList {"oneExpectationCoversOneDialog"} << 1
        << QStringList {failPrefix + "oneExpectationCoversOneDialog() Unexpected modal dialog",
                        "QMessageBox \"Second\": not expected"}
        << QStringList {"\"First\""};
}

void TestModalGuard::reportsDialogs()
{
    QFETCH(QStringList, functions);
    QFETCH(int, failures);
    QFETCH(QStringList, lines);
    QFETCH(QStringList, absent);
    const ChildRun run = runChild(functions);
    QVERIFY2(run.finished, qPrintable(run.output));
    QVERIFY2(run.exitCode == failures, qPrintable(run.output));
    for (const QString &line : lines)
        QVERIFY2(run.output.contains(line), qPrintable(line + "\nnot in\n" + run.output));
    for (const QString &line : absent)
        QVERIFY2(!run.output.contains(line), qPrintable(line + "\nin\n" + run.output));
}

void TestModalGuard::failsWhileTheDialogIsOpenAndGoesOn()
{
    const ChildRun run = runChild({"unexpectedMessageBox", "expectedMessageBoxIsAnswered"});
    QVERIFY2(run.finished, qPrintable(run.output));
    QCOMPARE(run.exitCode, 1);
    // Reported when the box showed, before the code under test got its answer.
    const qsizetype failed = run.output.indexOf(failPrefix + "unexpectedMessageBox()");
    const qsizetype closed = run.output.indexOf(QStringLiteral("message box closed"));
    QVERIFY2(failed >= 0 && closed > failed, qPrintable(run.output));
    QVERIFY2(run.output.contains(passPrefix + "expectedMessageBoxIsAnswered()"),
             qPrintable(run.output));
}

QTEST_GUILESS_MAIN(TestModalGuard)
#include "tst_modalguard.moc"
