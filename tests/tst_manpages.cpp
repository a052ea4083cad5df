// SPDX-License-Identifier: MIT
// The man pages say what the programs say: rtctl(1) is what `rtctl --man` writes from the command
// table (every command with its usage), rtstudio(1) and rtmanager(1) name every option their
// --help names, and groff formats each page without a warning.
#include "rtctlrunner.h"

#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTest>

namespace {

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

/// The options a help text names (`-f`, `--export-diagram`), as roff writes them (`\-f`).
QSet<QString> optionsInRoff(const QString &help)
{
    static const QRegularExpression option(
        QStringLiteral("(?:^|[\\s\\[(|,])(--?[a-zA-Z][a-zA-Z0-9-]*)"));
    QSet<QString> options;
    for (auto it = option.globalMatch(help); it.hasNext();)
        options.insert(it.next().captured(1).replace(QLatin1Char('-'), QStringLiteral("\\-")));
    return options;
}

/// True when @p roff names @p option as a word: `\-h` is not in `\-\-help`.
bool names(const QString &roff, const QString &option)
{
    const QRegularExpression word(QStringLiteral("(?<![A-Za-z0-9-])%1(?![A-Za-z0-9\\\\])")
                                      .arg(QRegularExpression::escape(option)));
    return word.match(roff).hasMatch();
}

const QString rtctl = RTCTL_PATH;

} // namespace

class TestManPages : public QObject
{
    Q_OBJECT

private slots:
    void rtctlPageIsWhatRtctlWrites();
    void rtctlPageHasEveryCommandAndOption();
    void pagesNameEveryOptionOfHelp_data();
    void pagesNameEveryOptionOfHelp();
    void groffFormatsWithoutWarnings_data();
    void groffFormatsWithoutWarnings();
};

// The installed page is the one the build wrote from this rtctl, not an older one.
void TestManPages::rtctlPageIsWhatRtctlWrites()
{
    const RtctlResult man = runProgram(rtctl, {QStringLiteral("--man")});
    QCOMPARE(man.code, 0);
    QVERIFY(man.out.startsWith(QStringLiteral(".\\\" SPDX-License-Identifier: MIT\n.TH RTCTL 1")));
    QCOMPARE(readText(RTCTL_MAN_PAGE), man.out);
    QVERIFY2(!man.out.contains(QStringLiteral("@")), "a placeholder of rtctl.1.in was left");
    // Hidden: --help lists commands and options for users, not the build's.
    QVERIFY(!runProgram(rtctl, {QStringLiteral("--help")}).out.contains(QStringLiteral("--man")));
}

void TestManPages::rtctlPageHasEveryCommandAndOption()
{
    const QString page = readText(RTCTL_MAN_PAGE);
    const RtctlResult help = runProgram(rtctl, {QStringLiteral("--help")});
    static const QRegularExpression line(QStringLiteral("^  ([a-z]+)  "),
                                         QRegularExpression::MultilineOption);
    QStringList commands;
    for (auto it = line.globalMatch(help.out); it.hasNext();)
        commands << it.next().captured(1);
    QVERIFY2(commands.size() > 20, qPrintable(help.out));
    QStringList missing;
    for (const QString &command : std::as_const(commands)) {
        const qsizetype at = page.indexOf(QStringLiteral(".SS \"rtctl %1\"\n").arg(command));
        if (at < 0) {
            missing << command;
            continue;
        }
        const QString section = page.mid(at, page.indexOf(QStringLiteral(".SS "), at + 1) - at);
        for (const QString &option :
             optionsInRoff(runProgram(rtctl, {command, QStringLiteral("--help")}).out)) {
            if (!names(section, option))
                missing << command + QLatin1Char(' ') + option;
        }
    }
    QVERIFY2(missing.isEmpty(),
             qPrintable(QStringLiteral("not in rtctl(1): ") + missing.join(", ")));
}

void TestManPages::pagesNameEveryOptionOfHelp_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("page");
    QTest::newRow("rtstudio") << RTSTUDIO_PATH
                              << MAN_PAGE_DIR + QStringLiteral("/rtstudio.1");
    QTest::newRow("rtmanager") << RTMANAGER_PATH
                               << MAN_PAGE_DIR + QStringLiteral("/rtmanager.1");
}

void TestManPages::pagesNameEveryOptionOfHelp()
{
    QFETCH(QString, program);
    QFETCH(QString, page);
    const RtctlResult help = runProgram(program, {QStringLiteral("--help")});
    QCOMPARE(help.code, 0);
    const QSet<QString> options = optionsInRoff(help.out);
    QVERIFY2(options.size() >= 4, qPrintable(help.out));
    const QString text = readText(page);
    QStringList missing;
    for (const QString &option : options) {
        if (!names(text, option))
            missing << option;
    }
    QVERIFY2(missing.isEmpty(), qPrintable(page + QStringLiteral(" lacks ") + missing.join(", ")));
}

void TestManPages::groffFormatsWithoutWarnings_data()
{
    QTest::addColumn<QString>("page");
    QTest::newRow("rtctl") << RTCTL_MAN_PAGE;
    QTest::newRow("rtstudio") << MAN_PAGE_DIR + QStringLiteral("/rtstudio.1");
    QTest::newRow("rtmanager") << MAN_PAGE_DIR + QStringLiteral("/rtmanager.1");
}

// What `man -l PAGE` formats, with every groff warning on.
void TestManPages::groffFormatsWithoutWarnings()
{
    QFETCH(QString, page);
    const QString groff = QStandardPaths::findExecutable(QStringLiteral("groff"));
    if (groff.isEmpty())
        QSKIP("groff is not installed (Debian's groff-base, which man-db brings)");
    QVERIFY(QFile::exists(page));
    const RtctlResult formatted
        = runProgram(groff, {QStringLiteral("-man"), QStringLiteral("-ww"), QStringLiteral("-z"), page});
    QCOMPARE(formatted.code, 0);
    QVERIFY2(formatted.err.isEmpty(), qPrintable(formatted.err));
}

QTEST_GUILESS_MAIN(TestManPages)
#include "tst_manpages.moc"
