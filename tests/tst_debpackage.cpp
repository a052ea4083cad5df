// SPDX-License-Identifier: MIT
// The Debian package: `cpack -G DEB` in the build folder, unpacked with dpkg -x into a temporary
// root, and each program run from there: --version and one real action (a profile check, a
// manager listing its components to rtctl, a diagram exported without a window).
#include "livesystem.h"

#include <QDir>
#include <QDirIterator>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

class TestDebPackage : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void containsWhatIsInstalled_data();
    void containsWhatIsInstalled();
    void dependsOnDebianPackages();
    void programsRunFromTheUnpackedTree();
    void completesRtctlCommands();

private:
    /// Runs `program` with `arguments`; its exit code, or -1 when it did not end within 120 s.
    static int run(const QString &program, const QStringList &arguments, QString *output,
                   const QString &directory = {});
    QString bin(const QString &program) const { return m_root.filePath("usr/bin/" + program); }

    QTemporaryDir m_work;
    QTemporaryDir m_unpacked;
    QDir m_root;
    QString m_package;
};

int TestDebPackage::run(const QString &program, const QStringList &arguments, QString *output,
                        const QString &directory)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    if (!directory.isEmpty())
        process.setWorkingDirectory(directory);
    process.start(program, arguments);
    // cpack runs dpkg-shlibdeps on every program and library: minutes for the sanitizer build on
    // a busy machine.
    if (!process.waitForFinished(400000)) {
        process.kill();
        process.waitForFinished();
        *output = QString::fromLocal8Bit(process.readAll());
        return -1;
    }
    *output = QString::fromLocal8Bit(process.readAll());
    return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
}

void TestDebPackage::initTestCase()
{
    if (QStandardPaths::findExecutable("dpkg-deb").isEmpty())
        QSKIP("skipped: dpkg-deb is not installed (Debian's dpkg)");
    QVERIFY(m_work.isValid() && m_unpacked.isValid());
    QString output;
    const int code = run(QStringLiteral(CPACK_COMMAND),
                         {"-G", "DEB", "--config", RTSTUDIO_BUILD_DIR + QStringLiteral("/CPackConfig.cmake"), "-B", m_work.path()},
                         &output, RTSTUDIO_BUILD_DIR);
    QVERIFY2(code == 0, qPrintable(output));
    const QStringList debs = QDir(m_work.path()).entryList({"rtstudio_*_amd64.deb"});
    QCOMPARE(debs.size(), 1);
    QCOMPARE(debs.first(), QStringLiteral("rtstudio_" RTSTUDIO_VERSION "_amd64.deb"));
    m_package = QDir(m_work.path()).filePath(debs.first());
    QVERIFY2(run("dpkg-deb", {"-x", m_package, m_unpacked.path()}, &output) == 0, qPrintable(output));
    m_root = QDir(m_unpacked.path());
}

void TestDebPackage::containsWhatIsInstalled_data()
{
    QTest::addColumn<QString>("path");
    for (const char *path : {"usr/bin/rtstudio", "usr/bin/rtctl", "usr/bin/rtmanager", "usr/bin/rtm2-config",
                             "usr/bin/rtm2-skelwrapper", "usr/lib/librtstudio_rtm.so",
                             "usr/lib/cmake/openrtm-2.1/OpenRTMConfig.cmake", "usr/lib/pkgconfig/openrtm2.pc",
                             "usr/include/openrtm-2.1/rtm/Manager.h", "usr/share/rtstudio/idl/RTC.idl",
                             "usr/share/rtstudio/examples/ConsoleInOut/ConsoleInOut.xml",
                             "usr/share/applications/rtstudio.desktop",
                             "usr/share/icons/hicolor/scalable/apps/rtstudio.svg",
                             "usr/share/mime/packages/rtstudio.xml", "usr/share/man/man1/rtstudio.1",
                             "usr/share/man/man1/rtctl.1", "usr/share/man/man1/rtmanager.1",
                             "usr/share/bash-completion/completions/rtctl"})
        QTest::newRow(path) << QString::fromLatin1(path);
}

void TestDebPackage::containsWhatIsInstalled()
{
    QFETCH(QString, path);
    QVERIFY2(QFileInfo::exists(m_root.filePath(path)), qPrintable(path));
}

void TestDebPackage::dependsOnDebianPackages()
{
    QString fields;
    QVERIFY2(run("dpkg-deb", {"-f", m_package, "Package", "Version", "Architecture", "Depends"}, &fields) == 0,
             qPrintable(fields));
    QVERIFY2(fields.contains("Package: rtstudio"), qPrintable(fields));
    QVERIFY2(fields.contains("Architecture: amd64"), qPrintable(fields));
    // Found by dpkg-shlibdeps from the programs' libraries, and what components are built with.
    for (const char *package : {"libqt6widgets6", "libomniorb4-2", "libyaml-cpp0.7", "omniorb-nameserver", "cmake"})
        QVERIFY2(fields.contains(QLatin1String(package)), qPrintable(fields));
}

void TestDebPackage::programsRunFromTheUnpackedTree()
{
    QString output;
    for (const char *program : {"rtstudio", "rtctl", "rtmanager"}) {
        QCOMPARE(run(bin(program), {"--version"}, &output), 0);
        QVERIFY2(output.contains(QStringLiteral("%1 " RTSTUDIO_VERSION).arg(program)), qPrintable(output));
    }
    const QString example = m_root.filePath("usr/share/rtstudio/examples/ConsoleInOut/ConsoleInOut.xml");
    QVERIFY2(run(bin("rtctl"), {"profile", "check", example}, &output) == 0, qPrintable(output));

    QTemporaryDir out;
    const QString svg = out.filePath("system.svg");
    QVERIFY2(run(bin("rtstudio"), {"--export-diagram", example, "--output", svg}, &output) == 0, qPrintable(output));
    QVERIFY(QFileInfo(svg).size() > 0);

    // The installed manager with its built-in components, asked by the installed rtctl.
    LiveTest::LiveSystem live;
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(live.startProcess(bin("rtmanager"),
                               {"-d", "-o", "naming.enable:NO", "-o",
                                QStringLiteral("corba.endpoints:127.0.0.1:%1").arg(port), "-o",
                                "manager.components.precreate:ConsoleIn"},
                               "rtmanager ready", &error),
             qPrintable(error));
    QVERIFY2(run(bin("rtctl"), {"mgr", QStringLiteral("corbaloc::127.0.0.1:%1").arg(port), "list"}, &output) == 0,
             qPrintable(output));
    QVERIFY2(output.contains("ConsoleIn0"), qPrintable(output));
}

void TestDebPackage::completesRtctlCommands()
{
    // The completion function as bash calls it: the words so far and the index of the current one.
    const QString script = m_root.filePath("usr/share/bash-completion/completions/rtctl");
    const auto complete = [&](const QString &words, int current) {
        QString output;
        const QString line = QStringLiteral("source '%1'; COMP_WORDS=(%2); COMP_CWORD=%3; _rtctl; "
                                            "printf '%s\\n' \"${COMPREPLY[@]}\"")
                                 .arg(script, words)
                                 .arg(current);
        run("bash", {"-c", line}, &output);
        return output.split('\n', Qt::SkipEmptyParts);
    };
    QCOMPARE(complete("rtctl pro", 1), QStringList {"profile"});
    QCOMPARE(complete("rtctl profile c", 2), (QStringList {"check", "convert"}));
    QVERIFY(complete("rtctl ", 1).contains("resurrect"));
    QVERIFY(complete("rtctl conf --", 2).contains("--json"));
}

QTEST_GUILESS_MAIN(TestDebPackage)
#include "tst_debpackage.moc"
