// SPDX-License-Identifier: MIT
#include "rtctlrunner.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

// `rtctl gen` as a user or a build script runs it.
class TestRtctlGen : public QObject
{
    Q_OBJECT

private slots:
    void usageErrors_data();
    void usageErrors();
    void generatesProject();
    void testComponentWritesTestTree();
    void testComponentInPythonOrCpp();
    void keepMergeOverwrite();
    void refusesBadNameWritingNothing();
    void missingInterfaceTypeIsAProblem();

private:
    using Result = RtctlResult;
    Result rtctl(const QStringList &arguments);
};

static QString fixture()
{
    return RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/SampleComp.xml");
}

static QString idlDir()
{
    return RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/idl");
}

static QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

static bool writeAll(const QString &path, const QByteArray &data)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(data) == data.size();
}

TestRtctlGen::Result TestRtctlGen::rtctl(const QStringList &arguments)
{
    return runRtctl(arguments);
}

void TestRtctlGen::usageErrors_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("nothing") << QStringList{"gen"};
    QTest::newRow("no language") << QStringList{"gen", fixture(), "-o", "x"};
    QTest::newRow("no output") << QStringList{"gen", fixture(), "--lang", "cpp"};
    QTest::newRow("bad language") << QStringList{"gen", fixture(), "--lang", "cobol", "-o", "x"};
    QTest::newRow("unknown option") << QStringList{"gen", fixture(), "--lang", "cpp", "-o", "x", "--frob"};
    QTest::newRow("two profiles") << QStringList{"gen", fixture(), fixture(), "--lang", "cpp", "-o", "x"};
    QTest::newRow("bad backups") << QStringList{"gen", fixture(), "--lang", "cpp", "-o", "x", "--backups", "-1"};
}

void TestRtctlGen::usageErrors()
{
    QFETCH(QStringList, arguments);
    const Result result = rtctl(arguments);
    QCOMPARE(result.code, 2);
    QVERIFY(result.err.contains(QStringLiteral("Usage:")));
}

void TestRtctlGen::generatesProject()
{
    QTemporaryDir dir;
    const Result result = rtctl({"gen", fixture(), "--lang", "cpp", "--lang", "python", "-o",
                                 dir.path(), "--idl-dir", idlDir()});
    QVERIFY2(result.code == 0, qPrintable(result.err));
    for (const char *path : {"CMakeLists.txt", "src/SampleComp.cpp", "include/SampleComp/SampleComp.h",
                             "src/SampleServiceSVC_impl.cpp", "SampleComp.py", "idlcompile.sh",
                             "RTC.xml", "README.md", "rtc.conf", "SampleComp.conf",
                             "idl/SampleService.idl"})
        QVERIFY2(QFile::exists(QDir(dir.path()).filePath(path)), path);
    QVERIFY(!QFile::exists(QDir(dir.path()).filePath("src/SampleComp.java")));
    QVERIFY(!QFile::exists(QDir(dir.path()).filePath("test"))); // only on request
    QVERIFY(result.out.contains(QStringLiteral("created src/SampleComp.cpp")));
    QVERIFY(QFileInfo(QDir(dir.path()).filePath("idlcompile.sh")).isExecutable());
    // The RTC.xml written with the project reads back.
    const Result check = rtctl({"profile", "check", QDir(dir.path()).filePath("RTC.xml")});
    QCOMPARE(check.code, 0);
}

void TestRtctlGen::testComponentWritesTestTree()
{
    QTemporaryDir dir;
    const Result result = rtctl({"gen", fixture(), "--lang", "cpp", "-o", dir.path(), "--idl-dir",
                                 idlDir(), "--test-component"});
    QVERIFY2(result.code == 0, qPrintable(result.err));
    QVERIFY(result.out.contains(QStringLiteral("created test/src/SampleCompTest.cpp")));
    // The test tree is the one the golden files hold, file for file.
    const QDir golden(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/golden/SampleComp/test"));
    QDirIterator it(golden.path(), QDir::Files, QDirIterator::Subdirectories);
    int compared = 0;
    while (it.hasNext()) {
        const QString relative = golden.relativeFilePath(it.next());
        QCOMPARE(readAll(QDir(dir.path()).filePath("test/" + relative)), readAll(it.filePath()));
        ++compared;
    }
    QCOMPARE(compared, 9);
    QVERIFY(QFile::exists(QDir(dir.path()).filePath("src/SampleComp.cpp")));
}

void TestRtctlGen::testComponentInPythonOrCpp()
{
    // A Python-only project gets its test component in Python: the module with the ports turned round.
    QTemporaryDir python;
    Result result = rtctl({"gen", fixture(), "--lang", "python", "-o", python.path(), "--idl-dir", idlDir(),
                           "--test-component"});
    QVERIFY2(result.code == 0, qPrintable(result.err));
    QVERIFY(QFile::exists(QDir(python.path()).filePath("SampleComp.py")));
    const QByteArray test = readAll(QDir(python.path()).filePath("test/SampleCompTest.py"));
    QVERIFY2(test.contains("def SampleCompTestInit(manager):"), test.constData());
    QVERIFY(QFileInfo(QDir(python.path()).filePath("test/idlcompile.sh")).isExecutable());
    const QByteArray component = readAll(QDir(python.path()).filePath("SampleComp.py"));
    for (const QRegularExpressionMatch &port :
         QRegularExpression(QStringLiteral("OpenRTM_aist\\.(In|Out)Port\\(\"(\\w+)\"")).globalMatch(QString::fromUtf8(component))) {
        const QString mirrored = QStringLiteral("OpenRTM_aist.%1Port(\"%2\"")
                                     .arg(port.captured(1) == QLatin1String("In") ? QStringLiteral("Out") : QStringLiteral("In"),
                                          port.captured(2));
        QVERIFY2(test.contains(mirrored.toUtf8()), qPrintable(mirrored));
    }
    // Java alone gets none, and says why.
    QTemporaryDir java;
    result = rtctl({"gen", fixture(), "--lang", "java", "-o", java.path(), "--idl-dir", idlDir(), "--test-component"});
    QCOMPARE(result.code, 0);
    QVERIFY2(result.err.contains(QStringLiteral("C++ or Python only")), qPrintable(result.err));
    QVERIFY(!QFile::exists(QDir(java.path()).filePath("test")));
}

void TestRtctlGen::keepMergeOverwrite()
{
    QTemporaryDir dir;
    const QStringList base{"gen", fixture(), "--lang", "cpp", "-o", dir.path(), "--idl-dir", idlDir()};
    QCOMPARE(rtctl(base).code, 0);
    const QString source = QDir(dir.path()).filePath("src/SampleComp.cpp");
    const QByteArray generated = readAll(source);
    QByteArray edited = generated;
    edited.replace("  return RTC::RTC_OK;\n}\n\n// RTC::ReturnCode_t SampleComp::onFinalize()",
                   "  return RTC::RTC_OK; // user code\n}\n\n// RTC::ReturnCode_t SampleComp::onFinalize()");
    edited.replace("bindParameter(\"rate\", m_rate, \"0.5\");", "bindParameter(\"rate\", m_rate, \"9\");");
    QVERIFY(edited.contains("// user code"));
    QVERIFY(writeAll(source, edited));

    const Result kept = rtctl(base + QStringList{"--keep"});
    QCOMPARE(kept.code, 0);
    QVERIFY(kept.out.contains(QStringLiteral("kept src/SampleComp.cpp")));
    QCOMPARE(readAll(source), edited);

    const Result merged = rtctl(base + QStringList{"--merge"});
    QCOMPARE(merged.code, 0);
    QVERIFY(merged.out.contains(QStringLiteral("merged src/SampleComp.cpp")));
    const QByteArray afterMerge = readAll(source);
    QVERIFY(afterMerge.contains("// user code")); // outside the marked regions
    QVERIFY(afterMerge.contains("bindParameter(\"rate\", m_rate, \"0.5\");")); // region refreshed
    QStringList backups = QDir(dir.path() + "/src").entryList({"SampleComp.cpp2*"});
    QCOMPARE(backups.size(), 1);
    QCOMPARE(readAll(dir.path() + "/src/" + backups.first()), edited);

    QVERIFY(writeAll(source, edited));
    const Result overwritten = rtctl(base + QStringList{"--overwrite"});
    QCOMPARE(overwritten.code, 0);
    QCOMPARE(readAll(source), generated);
    backups = QDir(dir.path() + "/src").entryList({"SampleComp.cpp2*"});
    QCOMPARE(backups.size(), 2);
}

void TestRtctlGen::refusesBadNameWritingNothing()
{
    QTemporaryDir dir;
    QByteArray xml = readAll(fixture());
    xml.replace("rtc:name=\"SampleComp\"", "rtc:name=\"Sample-Comp\"");
    const QString profile = QDir(dir.path()).filePath("RTC.xml");
    QVERIFY(writeAll(profile, xml));
    const QString out = QDir(dir.path()).filePath("out");
    const Result result = rtctl({"gen", profile, "--lang", "java", "-o", out, "--idl-dir", idlDir()});
    QCOMPARE(result.code, 1);
    QVERIFY2(result.err.contains(QStringLiteral("Sample-Comp")), qPrintable(result.err));
    QVERIFY(!QFile::exists(out));
}

void TestRtctlGen::missingInterfaceTypeIsAProblem()
{
    QTemporaryDir dir;
    // A copy of the profile away from its idl/ folder: the service interface types are nowhere.
    const QString profile = QDir(dir.path()).filePath("RTC.xml");
    QVERIFY(QFile::copy(fixture(), profile));
    const QString out = QDir(dir.path()).filePath("out");
    const Result result = rtctl({"gen", profile, "--lang", "cpp", "-o", out});
    QCOMPARE(result.code, 1);
    QVERIFY2(result.err.contains(QStringLiteral("Sample::Echo")), qPrintable(result.err));
    QVERIFY(!QFile::exists(out));
}

QTEST_GUILESS_MAIN(TestRtctlGen)
#include "tst_rtctlgen.moc"
