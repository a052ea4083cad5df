// SPDX-License-Identifier: MIT
#include "rtctlrunner.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

// Runs the real rtctl binary, as a user or a script would.
class TestRtctl : public QObject
{
    Q_OBJECT

private slots:
    void helpAndVersion();
    void usageErrors_data();
    void usageErrors();
    void checkAcceptsValidFiles_data();
    void checkAcceptsValidFiles();
    void checkReportsProblemsWithPositions_data();
    void checkReportsProblemsWithPositions();
    void convertRoundTrips_data();
    void convertRoundTrips();
    void convertFailureLeavesTargetUntouched();

private:
    using Result = RtctlResult;
    Result rtctl(const QStringList &arguments);
};

static QString example(const QString &relative)
{
    return (RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/")) + relative;
}

static QString data(const QString &relative)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/")) + relative;
}

TestRtctl::Result TestRtctl::rtctl(const QStringList &arguments)
{
    return runRtctl(arguments);
}

void TestRtctl::helpAndVersion()
{
    const Result help = rtctl({QStringLiteral("--help")});
    QCOMPARE(help.code, 0);
    QVERIFY(help.out.contains(QStringLiteral("profile")));
    const Result version = rtctl({QStringLiteral("--version")});
    QCOMPARE(version.code, 0);
    QVERIFY(version.out.startsWith(QStringLiteral("rtctl ")));
    const Result profileHelp = rtctl({QStringLiteral("profile"), QStringLiteral("--help")});
    QCOMPARE(profileHelp.code, 0);
    QVERIFY(profileHelp.out.contains(QStringLiteral("convert")));
}

void TestRtctl::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("nothing") << QStringList();
    QTest::newRow("unknown command") << QStringList{QStringLiteral("frobnicate")};
    QTest::newRow("profile alone") << QStringList{QStringLiteral("profile")};
    QTest::newRow("check without files") << QStringList{QStringLiteral("profile"), QStringLiteral("check")};
    QTest::newRow("convert one file")
        << QStringList{QStringLiteral("profile"), QStringLiteral("convert"), QStringLiteral("a.xml")};
    QTest::newRow("unknown sub-command")
        << QStringList{QStringLiteral("profile"), QStringLiteral("lint"), QStringLiteral("a.xml")};
}

void TestRtctl::usageErrors()
{
    QFETCH(QStringList, arguments);
    const Result result = rtctl(arguments);
    QCOMPARE(result.code, 2);
    QVERIFY(result.err.contains(QStringLiteral("Usage")));
}

void TestRtctl::checkAcceptsValidFiles_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("system") << example(QStringLiteral("ConsoleInOut/ConsoleInOut.xml"));
    QTest::newRow("component") << example(QStringLiteral("ConsoleInOut/RTCs/ConsoleIn0.xml"));
    QTest::newRow("seq system") << example(QStringLiteral("SeqIO/SeqIO.xml"));
    QTest::newRow("seq component") << example(QStringLiteral("SeqIO/RTCs/SeqOut0.xml"));
}

void TestRtctl::checkAcceptsValidFiles()
{
    QFETCH(QString, file);
    const Result result = rtctl({QStringLiteral("profile"), QStringLiteral("check"), file});
    QVERIFY2(result.code == 0, qPrintable(result.err));
    QVERIFY(result.out.contains(QStringLiteral(": ok")));
}

void TestRtctl::checkReportsProblemsWithPositions_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("expected"); // start of the first finding
    QTest::newRow("missing file") << data(QStringLiteral("cli/does-not-exist.xml"))
                                  << data(QStringLiteral("cli/does-not-exist.xml: error: no such file"));
    QTest::newRow("truncated") << data(QStringLiteral("cli/truncated.xml"))
                               << data(QStringLiteral("cli/truncated.xml:5:1: error:"));
    QTest::newRow("duplicate instance") << data(QStringLiteral("cli/duplicate-instance.xml"))
                                        << data(QStringLiteral("cli/duplicate-instance.xml:6:"));
    QTest::newRow("not a profile") << data(QStringLiteral("cli/not-a-profile.xml"))
                                   << data(QStringLiteral("cli/not-a-profile.xml:2:1: error: the root element <project>"));
}

void TestRtctl::checkReportsProblemsWithPositions()
{
    QFETCH(QString, file);
    QFETCH(QString, expected);
    const Result result = rtctl({QStringLiteral("profile"), QStringLiteral("check"), file});
    QCOMPARE(result.code, 1);
    QVERIFY2(result.err.startsWith(expected), qPrintable(result.err));
}

void TestRtctl::convertRoundTrips_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("system") << example(QStringLiteral("SeqIO/SeqIO.xml"));
    QTest::newRow("component") << example(QStringLiteral("SeqIO/RTCs/SeqOut0.xml"));
}

void TestRtctl::convertRoundTrips()
{
    QFETCH(QString, file);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString yaml = dir.filePath(QStringLiteral("out.yaml"));
    const QString xml = dir.filePath(QStringLiteral("out.xml"));
    const QString again = dir.filePath(QStringLiteral("again.xml"));
    QCOMPARE(rtctl({QStringLiteral("profile"), QStringLiteral("convert"), file, yaml}).code, 0);
    QCOMPARE(rtctl({QStringLiteral("profile"), QStringLiteral("convert"), yaml, xml}).code, 0);
    QCOMPARE(rtctl({QStringLiteral("profile"), QStringLiteral("convert"), xml, again}).code, 0);
    QFile a(xml), b(again);
    QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
    const QByteArray first = a.readAll();
    QVERIFY(first.size() > 200);
    // Normalised XML is a fixed point: converting it again changes nothing.
    QCOMPARE(b.readAll(), first);
    QCOMPARE(rtctl({QStringLiteral("profile"), QStringLiteral("check"), yaml}).code, 0);
}

void TestRtctl::convertFailureLeavesTargetUntouched()
{
    QTemporaryDir dir;
    const QString target = dir.filePath(QStringLiteral("keep.xml"));
    QFile file(target);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("precious");
    file.close();
    const Result result = rtctl({QStringLiteral("profile"), QStringLiteral("convert"),
                                 data(QStringLiteral("cli/truncated.xml")), target});
    QCOMPARE(result.code, 1);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("precious"));
}

QTEST_GUILESS_MAIN(TestRtctl)
#include "tst_rtctl.moc"
