// SPDX-License-Identifier: MIT
// Debian's rules for package names and versions, the order of versions (checked against dpkg
// --compare-versions itself), and control paragraphs read and written again.
#include <debcontrol.h>
#include <debnames.h>

#include <QProcess>
#include <QtTest>

using namespace Packages;

class TestDebNames : public QObject
{
    Q_OBJECT

private slots:
    void packageNames_data();
    void packageNames();
    void versions_data();
    void versions();
    void versionOrder_data();
    void versionOrder();
    void controlParagraphs();
    void malformedControl();
};

void TestDebNames::packageNames_data()
{
    QTest::addColumn<QString>("vendor");
    QTest::addColumn<QString>("category");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("expected"); // empty: refused

    QTest::newRow("OpenRTM example") << "AIST"
                                     << "example"
                                     << "ConsoleIn"
                                     << "rtc-aist-example-consolein";
    QTest::newRow("spaces and underscores") << "My Lab"
                                            << "Motor_Control"
                                            << "Wheel Driver"
                                            << "rtc-my-lab-motor-control-wheel-driver";
    QTest::newRow("no category") << "AIST"
                                 << ""
                                 << "Sensor"
                                 << "rtc-aist-sensor";
    QTest::newRow("plus and dot kept") << "a.b"
                                       << "c++"
                                       << "X1"
                                       << "rtc-a.b-c++-x1";
    QTest::newRow("runs of others are one dash") << "R&D//Lab"
                                                 << "?"
                                                 << "Arm"
                                                 << "rtc-r-d-lab-arm";
    QTest::newRow("non-ASCII dropped") << "Ünï"
                                       << "カテゴリ"
                                       << "Nav"
                                       << "rtc-n-nav";
    QTest::newRow("name without letters") << "AIST"
                                          << "x"
                                          << "__"
                                          << "";
    QTest::newRow("empty name") << "AIST"
                                << "x"
                                << ""
                                << "";
}

void TestDebNames::packageNames()
{
    QFETCH(QString, vendor);
    QFETCH(QString, category);
    QFETCH(QString, name);
    QFETCH(QString, expected);
    QString error;
    const std::optional<QString> result = componentPackageName(vendor, category, name, &error);
    if (expected.isEmpty()) {
        QVERIFY(!result);
        QVERIFY(error.contains(QStringLiteral("'%1'").arg(name)));
        return;
    }
    QVERIFY2(result, qPrintable(error));
    QCOMPARE(*result, expected);
    QVERIFY(isValidPackageName(*result));
}

void TestDebNames::versions_data()
{
    QTest::addColumn<QString>("profile");
    QTest::addColumn<QString>("expected"); // empty: refused

    QTest::newRow("plain") << "1.0.0"
                           << "1.0.0";
    QTest::newRow("leading v") << "v2.1"
                               << "2.1";
    QTest::newRow("underscores and spaces") << " 1_2 3 "
                                            << "1.2.3";
    QTest::newRow("revision") << "1.0-2"
                              << "1.0-2";
    QTest::newRow("epoch") << "1:2.0"
                           << "1:2.0";
    QTest::newRow("tilde") << "2.0~rc1"
                           << "2.0~rc1";
    QTest::newRow("word") << "beta"
                          << "";
    QTest::newRow("empty") << ""
                           << "";
    QTest::newRow("colon without epoch") << "1.0:2"
                                         << "";
    QTest::newRow("slash") << "1.0/2"
                           << "";
    QTest::newRow("empty revision") << "1.0-"
                                    << "";
}

void TestDebNames::versions()
{
    QFETCH(QString, profile);
    QFETCH(QString, expected);
    QString error;
    const std::optional<QString> result = debianVersion(profile, &error);
    if (expected.isEmpty()) {
        QVERIFY(!result);
        QVERIFY(!error.isEmpty());
        return;
    }
    QVERIFY2(result, qPrintable(error));
    QCOMPARE(*result, expected);
}

void TestDebNames::versionOrder_data()
{
    QTest::addColumn<QString>("a");
    QTest::addColumn<QString>("b");
    const char *pairs[][2]
        = {{"1.0", "1.0"},      {"1.0", "1.1"},    {"1.10", "1.9"},  {"1.0~rc1", "1.0"},
           {"1.0", "1.0-1"},    {"1:0.1", "9.9"},  {"1.0a", "1.0+"}, {"1.0.0", "1.0"},
           {"2.0-1", "2.0-10"}, {"1.0~~", "1.0~"}, {"001", "1"},     {"1.a", "1.B"}};
    for (const auto &pair : pairs)
        QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(pair[0], pair[1])))
            << pair[0] << pair[1];
}

void TestDebNames::versionOrder()
{
    QFETCH(QString, a);
    QFETCH(QString, b);
    auto dpkgSays = [](const QString &x, const char *op, const QString &y) {
        return QProcess::execute("dpkg", {"--compare-versions", x, op, y}) == 0;
    };
    const int ours = compareVersions(a, b);
    QCOMPARE(ours < 0, dpkgSays(a, "lt", b));
    QCOMPARE(ours == 0, dpkgSays(a, "eq", b));
    QCOMPARE(ours > 0, dpkgSays(a, "gt", b));
}

void TestDebNames::controlParagraphs()
{
    const QByteArray text
        = "Package: rtc-a-b-c\nversion: 1.0\nDescription: short\n line two\n .\n line four\n\n"
          "Package: second\nVersion: 2\n";
    QString error;
    const std::optional<QList<DebControl>> all = DebControl::parseAll(text, &error);
    QVERIFY2(all, qPrintable(error));
    QCOMPARE(all->size(), 2);
    const DebControl &first = all->first();
    QCOMPARE(first.value("Version"), QStringLiteral("1.0")); // names without regard to case
    QCOMPARE(first.value("description"), QStringLiteral("short\n line two\n .\n line four"));
    QCOMPARE(first.names(), (QStringList {"Package", "version", "Description"}));
    QCOMPARE(all->at(1).value("Package"), QStringLiteral("second"));
    QCOMPARE(first.toText(), text.left(text.indexOf("\n\n") + 1));
    DebControl edited = first;
    edited.set("VERSION", "2.0");
    edited.set("X-RTC-Types", "A");
    edited.remove("Description");
    QCOMPARE(edited.toText(), QByteArray("Package: rtc-a-b-c\nversion: 2.0\nX-RTC-Types: A\n"));
}

void TestDebNames::malformedControl()
{
    QString error;
    QVERIFY(!DebControl::parse(" continuation first\nPackage: x\n", &error));
    QVERIFY(error.contains("line 1"));
    QVERIFY(!DebControl::parseAll("Package: x\n\nno colon here\n", &error));
    QVERIFY(error.contains("not a 'Name: value' field"));
}

QTEST_GUILESS_MAIN(TestDebNames)
#include "tst_debnames.moc"
