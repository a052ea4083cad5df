// SPDX-License-Identifier: MIT
// Every shell block of the documentation is run by a test. The tours (between <!-- tour --> and
// <!-- /tour -->) are tst_readmetour's; a block marked <!-- run: NAME --> on the line before its
// fence is run here, as written, by the recipe of that name (what the reader has in the folder
// beforehand, and what the block must have done); a block marked <!-- tested by tst_NAME -->
// is run in that form by that test; <!-- not run: REASON --> says why no test can. An unmarked
// block fails the test: a command a reader copies must be one that runs.
#include "pythonenvironment.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <csignal>
#include <iterator>

namespace {

/// A fenced shell block of a page and the marker on the line before it (empty when none).
struct ShellBlock
{
    QString page;
    int line = 0;
    QString marker;
    QString text;
    bool inTour = false;
};

QList<ShellBlock> shellBlocks(const QString &page)
{
    QFile file((RTSTUDIO_SOURCE_DIR + QStringLiteral("/")) + page);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'));
    static const QRegularExpression fence(QStringLiteral("^( *)```(\\w*)\\s*$"));
    static const QRegularExpression marker(
        QStringLiteral("^\\s*<!-- (run: [\\w-]+|tested by tst_\\w+|not run: [^>]*\\w[^>]*) -->\\s*$"));
    QList<ShellBlock> blocks;
    bool inTour = false;
    for (int i = 0; i < lines.size(); ++i) {
        if (lines.at(i).contains(QLatin1String("<!-- tour -->")))
            inTour = true;
        else if (lines.at(i).contains(QLatin1String("<!-- /tour -->")))
            inTour = false;
        const QRegularExpressionMatch open = fence.match(lines.at(i));
        if (!open.hasMatch() || open.captured(2).isEmpty())
            continue;
        const qsizetype indent = open.captured(1).size();
        QStringList body;
        int end = i + 1;
        for (; end < lines.size() && !lines.at(end).trimmed().startsWith(QLatin1String("```")); ++end)
            body << lines.at(end).mid(qMin(indent, lines.at(end).size() - lines.at(end).trimmed().size()));
        if (open.captured(2) == QLatin1String("sh")) {
            ShellBlock block{page, i + 1, {}, body.join(QLatin1Char('\n')), inTour};
            if (i > 0)
                block.marker = marker.match(lines.at(i - 1)).captured(1);
            blocks << block;
        }
        i = end;
    }
    return blocks;
}

/// The pages of the documentation: README.md and docs/ with its translations.
QStringList pages()
{
    QStringList names{QStringLiteral("README.md")};
    for (const QString &folder : {QStringLiteral("docs"), QStringLiteral("docs/ja")}) {
        const QDir dir((RTSTUDIO_SOURCE_DIR + QStringLiteral("/")) + folder);
        for (const QString &name : dir.entryList({QStringLiteral("*.md")}, QDir::Files, QDir::Name))
            names << folder + QLatin1Char('/') + name;
    }
    return names;
}

/// What a recipe needs of OpenRTM-aist-Python's examples, copied into its folder (none: empty).
struct Recipe
{
    const char *name;
    /// The example folder of the corpus whose files the reader has (empty: none).
    const char *corpusFolder;
    /// Files of tests/data the reader has in the folder.
    QStringList dataFiles;
    /// True when the block's last command runs until stopped (a component program).
    bool runsOn;
};

const Recipe recipes[] = {
    {"python-in-rtmanager", "", {QStringLiteral("python/PyScaler.py")}, false},
    {"python-idl", "SimpleService", {}, true},
};

QString corpusDir()
{
    return RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-python-examples");
}

} // namespace

class TestDocCommands : public QObject
{
    Q_OBJECT

private slots:
    void everyShellBlockIsRun();
    void blockRuns_data();
    void blockRuns();
    void cleanup();

private:
    QProcessEnvironment environment(const QString &folder) const;
    /// rtctl @p arguments in the recipe's folder: its standard output, or a null string when it failed.
    QString rtctl(const QString &folder, const QStringList &arguments, QString *error = nullptr) const;
    /// The block of @p page marked `run: @p name`.
    static ShellBlock markedBlock(const QString &name);

    QTemporaryDir m_home;
};

void TestDocCommands::everyShellBlockIsRun()
{
    QStringList unmarked;
    QStringList unknown;
    int counted = 0;
    for (const QString &page : pages()) {
        for (const ShellBlock &block : shellBlocks(page)) {
            ++counted;
            const QString where = QStringLiteral("%1:%2").arg(block.page).arg(block.line);
            if (block.inTour)
                continue;
            if (block.marker.isEmpty()) {
                unmarked << where;
            } else if (block.marker.startsWith(QLatin1String("run: "))) {
                const QString name = block.marker.mid(5);
                const bool known = std::any_of(std::begin(recipes), std::end(recipes),
                                               [&](const Recipe &r) { return name == QLatin1String(r.name); });
                if (!known)
                    unknown << where + QStringLiteral(" (no recipe %1)").arg(name);
            } else if (block.marker.startsWith(QLatin1String("not run: "))) {
                // What a test cannot do here (a peer built from another project's source), with the reason.
                continue;
            } else {
                const QString test = block.marker.mid(QStringLiteral("tested by ").size());
                if (!QFile::exists((RTSTUDIO_SOURCE_DIR + QStringLiteral("/tests/")) + test + QStringLiteral(".cpp")))
                    unknown << where + QStringLiteral(" (no test %1)").arg(test);
            }
        }
    }
    QVERIFY2(counted > 5, "the documentation's shell blocks were not found");
    QVERIFY2(unmarked.isEmpty(), qPrintable(QStringLiteral("shell blocks no test runs (mark them <!-- run: NAME --> "
                                                           "with a recipe here, <!-- tested by tst_NAME --> or "
                                                           "<!-- not run: REASON -->): ")
                                            + unmarked.join(QStringLiteral(", "))));
    QVERIFY2(unknown.isEmpty(), qPrintable(unknown.join(QStringLiteral(", "))));
}

ShellBlock TestDocCommands::markedBlock(const QString &name)
{
    for (const QString &page : pages())
        for (const ShellBlock &block : shellBlocks(page))
            if (block.marker == QStringLiteral("run: ") + name)
                return block;
    return {};
}

QProcessEnvironment TestDocCommands::environment(const QString &folder) const
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    // The reader's session: the local runtime's state in its runtime folder, rtctl and rtmanager
    // of this build first on PATH, then python3 (bin/, see blockRuns), the SDK's prefix (the build
    // folder) as PREFIX.
    env.insert(QStringLiteral("XDG_RUNTIME_DIR"), m_home.filePath(QStringLiteral("run")));
    env.insert(QStringLiteral("PATH"), (RTSTUDIO_BUILD_DIR + QStringLiteral("/cli:")) + m_home.filePath(QStringLiteral("bin"))
                                           + QLatin1Char(':') + env.value(QStringLiteral("PATH")));
    env.insert(QStringLiteral("PREFIX"), RTSTUDIO_BUILD_DIR);
    env.insert(QStringLiteral("PWD"), folder);
    env.remove(QStringLiteral("RTCTREE_NAMESERVERS"));
    env.remove(QStringLiteral("PYTHONPATH"));
    return env;
}

QString TestDocCommands::rtctl(const QString &folder, const QStringList &arguments, QString *error) const
{
    QProcess process;
    process.setProcessEnvironment(environment(folder));
    process.setWorkingDirectory(folder);
    process.start(RTSTUDIO_BUILD_DIR + QStringLiteral("/cli/rtctl"), arguments);
    const bool finished = process.waitForFinished(60000);
    if (!finished)
        process.kill();
    const QString out = QString::fromUtf8(process.readAllStandardOutput());
    if (!finished || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        if (error != nullptr)
            *error = QStringLiteral("rtctl %1: %2%3").arg(arguments.join(QLatin1Char(' ')), out,
                                                        QString::fromUtf8(process.readAllStandardError()));
        return {};
    }
    return out.isNull() ? QStringLiteral("") : out;
}

void TestDocCommands::blockRuns_data()
{
    QTest::addColumn<int>("recipe");
    for (int i = 0; i < int(std::size(recipes)); ++i)
        QTest::newRow(recipes[i].name) << i;
}

void TestDocCommands::blockRuns()
{
    QFETCH(int, recipe);
    const Recipe &r = recipes[recipe];
    const ShellBlock block = markedBlock(QString::fromLatin1(r.name));
    QVERIFY2(!block.text.isEmpty(), qPrintable(QStringLiteral("no block is marked run: %1").arg(r.name)));
#ifndef RTSTUDIO_PYTHON_EXECUTABLE
    QSKIP("the Python runtime is not built (python3-dev and pybind11-dev are missing)");
#else
    const QString corpus = QString::fromLatin1(r.corpusFolder);
    if (!corpus.isEmpty() && !QDir(corpusDir() + QLatin1Char('/') + corpus).exists())
        QSKIP("the OpenRTM-aist-Python examples corpus (shared/conformance/openrtm-python-examples beside the "
              "project) is absent");

    QVERIFY(m_home.isValid());
    QVERIFY(QDir().mkpath(m_home.filePath(QStringLiteral("run"))));
    QFile::setPermissions(m_home.filePath(QStringLiteral("run")),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    // python3 is the interpreter the Python runtime was built for; in the sanitizer build it is
    // started with the sanitizers' runtimes, as the Python tests start it.
    QVERIFY(QDir().mkpath(m_home.filePath(QStringLiteral("bin"))));
    const QProcessEnvironment python = LiveTest::pythonEnvironment({}, QStringLiteral(RTSTUDIO_SANITIZER_PRELOAD));
    QFile wrapper(m_home.filePath(QStringLiteral("bin/python3")));
    QVERIFY(wrapper.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QString script = QStringLiteral("#!/bin/sh\n");
    if (python.contains(QStringLiteral("LD_PRELOAD")))
        script += QStringLiteral("export LD_PRELOAD='%1' ASAN_OPTIONS='%2'\n")
                      .arg(python.value(QStringLiteral("LD_PRELOAD")), python.value(QStringLiteral("ASAN_OPTIONS")));
    script += QStringLiteral("exec '%1' \"$@\"\n").arg(QStringLiteral(RTSTUDIO_PYTHON_EXECUTABLE));
    wrapper.write(script.toUtf8());
    wrapper.close();
    QVERIFY(wrapper.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner));
    const QString folder = m_home.filePath(QString::fromLatin1(r.name));
    QVERIFY(QDir().mkpath(folder));
    if (!corpus.isEmpty()) {
        const QDir from(corpusDir() + QLatin1Char('/') + corpus);
        for (const QString &name : from.entryList(QDir::Files))
            QVERIFY(QFile::copy(from.filePath(name), folder + QLatin1Char('/') + name));
    }
    for (const QString &file : r.dataFiles)
        QVERIFY(QFile::copy((RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/")) + file,
                            folder + QLatin1Char('/') + QFileInfo(file).fileName()));

    QString error;
    const QString host = QStringLiteral("/localhost/%1.host_cxt").arg(QSysInfo::machineHostName());
    if (r.runsOn) {
        // A component program runs until stopped: its name server first, then the block in a
        // session of its own, stopped (the program with it) once the component is seen.
        QVERIFY2(!rtctl(folder, {QStringLiteral("local"), QStringLiteral("start")}, &error).isNull(),
                 qPrintable(error));
    }
    QProcess shell;
    shell.setProcessEnvironment(environment(folder));
    shell.setWorkingDirectory(folder);
    shell.setProcessChannelMode(QProcess::MergedChannels);
    shell.start(QStringLiteral("setsid"), {QStringLiteral("sh"), QStringLiteral("-ec"), block.text});
    QVERIFY(shell.waitForStarted());
    const auto stopSession = qScopeGuard([&shell] {
        if (shell.state() != QProcess::NotRunning) {
            ::kill(-pid_t(shell.processId()), SIGTERM);
            if (!shell.waitForFinished(10000))
                ::kill(-pid_t(shell.processId()), SIGKILL);
            shell.waitForFinished();
        }
    });
    const QString where = QStringLiteral("%1:%2").arg(block.page).arg(block.line);
    if (!r.runsOn) {
        const bool finished = shell.waitForFinished(180000);
        QVERIFY2(finished && shell.exitStatus() == QProcess::NormalExit && shell.exitCode() == 0,
                 qPrintable(QStringLiteral("%1 failed:\n%2").arg(where, QString::fromUtf8(shell.readAll()))));
    }

    if (QLatin1String(r.name) == QLatin1String("python-in-rtmanager")) {
        // The Python component scales what the built-in counter sends by 1000 on its way to ConsoleOut.
        const QString printed = rtctl(folder, {QStringLiteral("print"), QStringLiteral("-n"), QStringLiteral("3"),
                                               host + QStringLiteral("/PyScaler0.rtc:out")},
                                      &error);
        QVERIFY2(!printed.isNull(), qPrintable(error));
        static const QRegularExpression sample(QStringLiteral("data=(\\d+)$"), QRegularExpression::MultilineOption);
        int samples = 0;
        for (auto it = sample.globalMatch(printed); it.hasNext();) {
            const qlonglong value = it.next().captured(1).toLongLong();
            QVERIFY2(value > 0 && value % 1000 == 0, qPrintable(printed));
            ++samples;
        }
        QVERIFY2(samples == 3, qPrintable(printed));
    } else if (QLatin1String(r.name) == QLatin1String("python-idl")) {
        // The stubs were written and the provider, started with them, registered its name (a
        // block that ended has failed: the provider runs until stopped).
        const auto listed = [&] {
            return rtctl(folder, {QStringLiteral("ls"), QStringLiteral("/localhost")})
                .contains(QLatin1String("MyServiceProvider0.rtc"));
        };
        QTRY_VERIFY_WITH_TIMEOUT(shell.state() == QProcess::NotRunning || listed(), 60000);
        QVERIFY2(shell.state() != QProcess::NotRunning && listed(),
                 qPrintable(QStringLiteral("%1: no MyServiceProvider0.rtc; the block said:\n%2")
                                .arg(where, QString::fromUtf8(shell.readAll()))));
        for (const char *written : {"MyService_idl.py", "SimpleService/__init__.py", "SimpleService__POA/__init__.py"})
            QVERIFY2(QFile::exists(folder + QLatin1Char('/') + QLatin1String(written)), written);
    }
#endif
}

void TestDocCommands::cleanup()
{
    // The blocks start a local runtime; whatever happened, it is stopped.
    if (QDir(m_home.filePath(QStringLiteral("run"))).exists())
        rtctl(m_home.path(), {QStringLiteral("local"), QStringLiteral("stop")});
}

QTEST_GUILESS_MAIN(TestDocCommands)
#include "tst_doccommands.moc"
