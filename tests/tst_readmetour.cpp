// SPDX-License-Identifier: MIT
// README.md's five-minute tour, run as written (and the other documents that tell it, the same): its shell blocks in order in one shell, from a
// folder laid out like the checkout after the first set-up command (build/cli and resources/),
// with its C++ block put into the generated onExecute where step 2 says. The component is built,
// runs in the local runtime, the saved system starts and the Doubler sends even numbers. The
// local runtime is stopped at the end whatever happened.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace {

struct Block
{
    QString language;
    QString text;
};

/// The fenced blocks between `<!-- tour -->` and `<!-- /tour -->`, indentation removed.
QList<Block> tourBlocks(const QString &readme)
{
    const qsizetype begin = readme.indexOf(QLatin1String("<!-- tour -->"));
    const qsizetype end = readme.indexOf(QLatin1String("<!-- /tour -->"));
    QList<Block> blocks;
    if (begin < 0 || end < begin)
        return blocks;
    static const QRegularExpression fence(QStringLiteral("^( *)```(\\w+)\\n(.*?)^ *```$"),
                                          QRegularExpression::MultilineOption
                                              | QRegularExpression::DotMatchesEverythingOption);
    for (auto it = fence.globalMatch(readme.mid(begin, end - begin)); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        QStringList lines = m.captured(3).split(QLatin1Char('\n'));
        for (QString &line : lines)
            line.remove(0, qMin(m.captured(1).size(), line.size() - line.trimmed().size()));
        blocks << Block{m.captured(2), lines.join(QLatin1Char('\n'))};
    }
    return blocks;
}

// Replaces the body of the generated onExecute of the file given first by the file given second.
const char editScript[] = R"(python3 - "$1" "$2" <<'EDIT'
import re, sys
source = open(sys.argv[1]).read()
body = open(sys.argv[2]).read()
edited, count = re.subn(r'(::onExecute\([^)]*\)\n\{\n)  return RTC::RTC_OK;\n\}',
                        lambda m: m.group(1) + ''.join('  ' + l + '\n' for l in body.splitlines()) + '}',
                        source)
if count != 1:
    sys.exit('no generated onExecute in ' + sys.argv[1])
open(sys.argv[1], 'w').write(edited)
EDIT
)";

} // namespace

class TestReadmeTour : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void tourRuns();
    void otherToursAreTheSame_data();
    void otherToursAreTheSame();
    void cleanupTestCase();

private:
    QProcessEnvironment environment() const;

    QTemporaryDir m_checkout;
    QList<Block> m_blocks;
};

QProcessEnvironment TestReadmeTour::environment() const
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("XDG_RUNTIME_DIR"), m_checkout.filePath(QStringLiteral("run")));
    env.remove(QStringLiteral("RTCTREE_NAMESERVERS"));
    return env;
}

void TestReadmeTour::initTestCase()
{
    QFile readme(RTSTUDIO_SOURCE_DIR + QStringLiteral("/README.md"));
    QVERIFY(readme.open(QIODevice::ReadOnly));
    m_blocks = tourBlocks(QString::fromUtf8(readme.readAll()));
    QVERIFY2(m_blocks.size() >= 3, "README.md has no tour between <!-- tour --> and <!-- /tour -->");
    QVERIFY(m_checkout.isValid());
    QVERIFY(QDir().mkpath(m_checkout.filePath(QStringLiteral("build"))));
    QVERIFY(QFile::link(RTSTUDIO_BUILD_DIR + QStringLiteral("/cli"), m_checkout.filePath(QStringLiteral("build/cli"))));
    QVERIFY(QFile::link(RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources"), m_checkout.filePath(QStringLiteral("resources"))));
    QVERIFY(QDir().mkpath(m_checkout.filePath(QStringLiteral("run"))));
    QFile::setPermissions(m_checkout.filePath(QStringLiteral("run")),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
}

void TestReadmeTour::tourRuns()
{
    // One shell for all blocks, so that what a step exports or sets the next ones see.
    QString script = QStringLiteral("set -e\nedit_on_execute() {\n%1}\n").arg(QString::fromLatin1(editScript));
    int cppBlocks = 0;
    for (const Block &block : std::as_const(m_blocks)) {
        if (block.language == QLatin1String("sh")) {
            script += block.text + QLatin1Char('\n');
        } else if (block.language == QLatin1String("cpp")) {
            const QString body = m_checkout.filePath(QStringLiteral("body%1.cpp").arg(++cppBlocks));
            QFile file(body);
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(block.text.toUtf8());
            file.close();
            script += QStringLiteral("edit_on_execute tour/Doubler/src/Doubler.cpp '%1'\n").arg(body);
        }
    }
    QCOMPARE(cppBlocks, 1);
    QProcess shell;
    shell.setProcessEnvironment(environment());
    shell.setWorkingDirectory(m_checkout.path());
    shell.setProcessChannelMode(QProcess::MergedChannels);
    shell.start(QStringLiteral("sh"), {QStringLiteral("-c"), script});
    const bool finished = shell.waitForFinished(240000);
    if (!finished)
        shell.kill();
    const QString output = QString::fromUtf8(shell.readAll());
    // Qt Test shortens a message to about 1,000 characters: the end of the output says what failed.
    QVERIFY2(finished && shell.exitStatus() == QProcess::NormalExit && shell.exitCode() == 0,
             qPrintable(QStringLiteral("the tour failed, ending with:\n") + output.right(900)));
    QVERIFY2(output.contains(QStringLiteral("Built ")), qPrintable(output));
    QVERIFY2(output.contains(QStringLiteral("done activate Doubler0")), qPrintable(output));
    // What the Doubler sent: three samples, each twice a count, with a time stamp.
    static const QRegularExpression sample(QStringLiteral("^\\[(\\d+)\\.\\d+\\] data=(\\d+)$"),
                                           QRegularExpression::MultilineOption);
    int samples = 0;
    for (auto it = sample.globalMatch(output); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        QVERIFY2(m.captured(1).toLongLong() > 0, qPrintable(m.captured(0)));
        QVERIFY2(m.captured(2).toLongLong() > 0 && m.captured(2).toLongLong() % 2 == 0, qPrintable(m.captured(0)));
        ++samples;
    }
    QVERIFY2(samples == 3, qPrintable(output));
}

// The same tour told elsewhere (docs/ja/README.md, and Getting started, which explains each step):
// the same commands and code, in the same order, so that what the test above runs is what they say.
void TestReadmeTour::otherToursAreTheSame_data()
{
    QTest::addColumn<QString>("document");
    QTest::newRow("Japanese README") << QStringLiteral("docs/ja/README.md");
    QTest::newRow("Getting started") << QStringLiteral("docs/getting-started.md");
    QTest::newRow("Japanese Getting started") << QStringLiteral("docs/ja/getting-started.md");
}

void TestReadmeTour::otherToursAreTheSame()
{
    QFETCH(QString, document);
    QFile file((RTSTUDIO_SOURCE_DIR + QStringLiteral("/")) + document);
    QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.fileName()));
    const QList<Block> blocks = tourBlocks(QString::fromUtf8(file.readAll()));
    QCOMPARE(blocks.size(), m_blocks.size());
    for (qsizetype i = 0; i < blocks.size(); ++i) {
        QCOMPARE(blocks.at(i).language, m_blocks.at(i).language);
        QCOMPARE(blocks.at(i).text, m_blocks.at(i).text);
    }
}

void TestReadmeTour::cleanupTestCase()
{
    // The tour ends with `rtctl local stop`; after a failure half-way this stops what it started.
    QProcess stop;
    stop.setProcessEnvironment(environment());
    stop.start(RTSTUDIO_BUILD_DIR + QStringLiteral("/cli/rtctl"), {QStringLiteral("local"), QStringLiteral("stop")});
    if (!stop.waitForFinished(30000))
        stop.kill();
}

QTEST_GUILESS_MAIN(TestReadmeTour)
#include "tst_readmetour.moc"
