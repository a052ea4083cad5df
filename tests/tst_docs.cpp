// SPDX-License-Identifier: MIT
// The documentation stays true: every relative link and image of README.md and docs/ names a file
// that exists, every `rtctl COMMAND --option` the pages show is a command and an option that
// `rtctl COMMAND --help` describes, and the other way round docs/rtctl.md shows every command of
// `rtctl --help` and names every long option of its `--help`.
#include "rtctlrunner.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QSet>
#include <QTest>

#include <algorithm>

namespace {

const QString sourceDir = RTSTUDIO_SOURCE_DIR;

/// README.md and every Markdown page below docs/, relative to the source folder.
QStringList markdownFiles()
{
    QStringList files{QStringLiteral("README.md")};
    QDirIterator it(sourceDir + QStringLiteral("/docs"), {QStringLiteral("*.md")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        files << QDir(sourceDir).relativeFilePath(it.next());
    files.sort();
    return files;
}

QString readText(const QString &relativePath)
{
    QFile file(QDir(sourceDir).filePath(relativePath));
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

/// The text of inline code spans and fenced code blocks: where commands are shown.
QStringList codeTexts(const QString &markdown)
{
    QStringList texts;
    static const QRegularExpression fence(QStringLiteral("```[^\\n]*\\n(.*?)```"),
                                          QRegularExpression::DotMatchesEverythingOption);
    QString rest = markdown;
    for (auto it = fence.globalMatch(markdown); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        texts << m.captured(1).split(QLatin1Char('\n'));
        rest.replace(m.captured(0), QString());
    }
    static const QRegularExpression span(QStringLiteral("`([^`\\n]+)`"));
    for (auto it = span.globalMatch(rest); it.hasNext();)
        texts << it.next().captured(1);
    return texts;
}

/// The long options a command's --help offers: those of its usage lines (`rtctl …`) and of its
/// option table (lines starting with an option), not ones of other programs its prose mentions.
QStringList longOptions(const QString &help)
{
    static const QRegularExpression option(QStringLiteral("(?:^|[\\s\\[(|,])(--[a-z][a-z0-9-]*)"));
    static const QRegularExpression optionLine(QStringLiteral("^\\s*[-\\[]"));
    QStringList options;
    for (const QString &line : help.split(QLatin1Char('\n'))) {
        if (!line.contains(QLatin1String("rtctl ")) && !optionLine.match(line).hasMatch())
            continue;
        for (auto it = option.globalMatch(line); it.hasNext();)
            options << it.next().captured(1);
    }
    options.removeAll(QStringLiteral("--help"));
    options.removeDuplicates();
    return options;
}

} // namespace

class TestDocs : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void linksExist_data();
    void linksExist();
    void rtctlCommandsExist_data();
    void rtctlCommandsExist();
    void rtctlReferenceIsComplete();
    void setUpCommandsAgree();

private:
    QString help(const QString &command);

    QSet<QString> m_commands;
    QHash<QString, QString> m_help;
};

void TestDocs::initTestCase()
{
    const RtctlResult result = runRtctl({QStringLiteral("--help")});
    QCOMPARE(result.code, 0);
    static const QRegularExpression line(QStringLiteral("^  ([a-z]+)  "), QRegularExpression::MultilineOption);
    for (auto it = line.globalMatch(result.out); it.hasNext();)
        m_commands.insert(it.next().captured(1));
    QVERIFY2(m_commands.contains(QStringLiteral("gen")), qPrintable(result.out));
    QVERIFY(markdownFiles().size() > 2);
}

QString TestDocs::help(const QString &command)
{
    if (!m_help.contains(command))
        m_help.insert(command, runRtctl({command, QStringLiteral("--help")}).out);
    return m_help.value(command);
}

void TestDocs::linksExist_data()
{
    QTest::addColumn<QString>("file");
    for (const QString &file : markdownFiles())
        QTest::newRow(qPrintable(file)) << file;
}

void TestDocs::linksExist()
{
    QFETCH(QString, file);
    const QString text = readText(file);
    QVERIFY(!text.isEmpty());
    const QDir base = QFileInfo(QDir(sourceDir).filePath(file)).absoluteDir();
    static const QRegularExpression link(QStringLiteral("\\]\\(([^)\\s]+)(?:\\s+\"[^\"]*\")?\\)"));
    QStringList missing;
    for (auto it = link.globalMatch(text); it.hasNext();) {
        QString target = it.next().captured(1);
        if (target.contains(QLatin1String("://")) || target.startsWith(QLatin1String("mailto:"))
            || target.startsWith(QLatin1Char('#')))
            continue;
        target = target.section(QLatin1Char('#'), 0, 0);
        if (!QFileInfo::exists(base.filePath(target)))
            missing << target;
    }
    QVERIFY2(missing.isEmpty(), qPrintable(file + QStringLiteral(" links to missing files: ") + missing.join(", ")));
}

void TestDocs::rtctlCommandsExist_data()
{
    linksExist_data();
}

void TestDocs::rtctlCommandsExist()
{
    QFETCH(QString, file);
    static const QRegularExpression invocation(QStringLiteral("(?:^|[\\s/(])rtctl\\s+([a-z]+)((?:\\s+[^|;&]*)?)"));
    static const QRegularExpression option(QStringLiteral("(?:^|\\s)(--[a-z][a-z0-9-]*)"));
    QStringList problems;
    for (const QString &code : codeTexts(readText(file))) {
        for (auto it = invocation.globalMatch(code); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            const QString command = m.captured(1);
            if (!m_commands.contains(command)) {
                problems << QStringLiteral("no command 'rtctl %1' (in \"%2\")").arg(command, code.trimmed());
                continue;
            }
            for (auto o = option.globalMatch(m.captured(2)); o.hasNext();) {
                const QString name = o.next().captured(1);
                if (name != QLatin1String("--help") && !help(command).contains(name))
                    problems << QStringLiteral("'rtctl %1 --help' has no %2 (in \"%3\")").arg(command, name, code.trimmed());
            }
        }
    }
    QVERIFY2(problems.isEmpty(), qPrintable(file + QStringLiteral(":\n") + problems.join('\n')));
}

void TestDocs::rtctlReferenceIsComplete()
{
    const QString reference = readText(QStringLiteral("docs/rtctl.md"));
    const QString code = codeTexts(reference).join(QLatin1Char('\n'));
    QStringList missing;
    for (const QString &command : std::as_const(m_commands)) {
        // `rtctl act|deact|reset` shows three.
        const QRegularExpression shown(QStringLiteral("rtctl\\s+(?:[a-z]+\\|)*%1(?![a-z])").arg(command));
        if (!shown.match(code).hasMatch())
            missing << QStringLiteral("rtctl ") + command;
        for (const QString &name : longOptions(help(command))) {
            const QRegularExpression named(QStringLiteral("%1(?![a-z0-9-])").arg(name));
            if (!named.match(reference).hasMatch())
                missing << QStringLiteral("rtctl %1 %2").arg(command, name);
        }
    }
    missing.removeDuplicates();
    QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("docs/rtctl.md does not show: ") + missing.join(", ")));
}

// The README starts with the two set-up commands; CI runs the second one, the Japanese README
// shows both.
void TestDocs::setUpCommandsAgree()
{
    const QStringList readme = codeTexts(readText(QStringLiteral("README.md")));
    static const QRegularExpression setUp(QStringLiteral("^scripts/install-deps\\.sh && "));
    QStringList commands;
    for (const QString &code : readme) {
        if (setUp.match(code).hasMatch())
            commands << code.trimmed();
    }
    QVERIFY2(commands.size() >= 2, qPrintable(commands.join('\n')));
    const QString build = commands.at(0);
    const QString test = commands.at(1);
    QVERIFY2(build.contains(QStringLiteral("rtstudio")), qPrintable(build));
    QVERIFY2(test.contains(QStringLiteral("--workflow")), qPrintable(test));
    const QString ci = readText(QStringLiteral(".ci/run"));
    QVERIFY2(ci.split(QLatin1Char('\n')).contains(test), qPrintable(ci));
    const QString japanese = readText(QStringLiteral("docs/ja/README.md"));
    QVERIFY(japanese.contains(build));
    QVERIFY(japanese.contains(test));
    // Getting started builds as the first command does, without starting rtstudio.
    for (const QString &page : {QStringLiteral("docs/getting-started.md"), QStringLiteral("docs/ja/getting-started.md")}) {
        const QStringList codes = codeTexts(readText(page));
        const bool same = std::any_of(codes.cbegin(), codes.cend(), [&](const QString &code) {
            return setUp.match(code).hasMatch() && build.startsWith(code.trimmed() + QStringLiteral(" && "));
        });
        QVERIFY2(same, qPrintable(page));
    }
}

QTEST_GUILESS_MAIN(TestDocs)
#include "tst_docs.moc"
