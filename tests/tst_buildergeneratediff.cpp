// SPDX-License-Identifier: MIT
// The line diff behind the regeneration dialog (LCS line diff and unified hunks), and the
// dialogs of Generate: the regeneration choice shows the changed lines and returns the button
// pressed, Code restore lists backup sets with their files, the options dialog round-trips.
#include "backups.h"
#include "coderestoredialog.h"
#include "generatediff.h"
#include "generateoptionsdialog.h"
#include "regenerationdialog.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBlock>
#include <QTextDocument>

using namespace Builder;
using Codegen::FileDecision;

Q_DECLARE_METATYPE(Codegen::FileDecision)

namespace {

/// A diff written compactly: one entry per line, ' ', '-' or '+' followed by the text.
QStringList compact(const QList<DiffLine> &lines)
{
    QStringList out;
    for (const DiffLine &line : lines) {
        const QChar sign = line.kind == DiffLine::Kind::Same ? QLatin1Char(' ')
            : line.kind == DiffLine::Kind::Removed           ? QLatin1Char('-')
                                                             : QLatin1Char('+');
        out << sign + line.text;
    }
    return out;
}

QStringList chars(const QString &text)
{
    QStringList out;
    for (QChar c : text)
        out << QString(c);
    return out;
}

void touch(const QString &path, const QByteArray &data)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(data);
}

} // namespace

class TestBuilderGenerateDiff : public QObject
{
    Q_OBJECT

private slots:
    void splitsLines_data();
    void splitsLines();
    void lineDiff_data();
    void lineDiff();
    void lineDiffNumbersLines();
    void unifiedDiff_data();
    void unifiedDiff();
    void regenerationDialogShowsTheChangedLines();
    void regenerationDialogReturnsTheButtonPressed_data();
    void regenerationDialogReturnsTheButtonPressed();
    void codeRestoreDialogListsSetsAndFiles();
    void optionsDialogRoundTrips();
};

void TestBuilderGenerateDiff::splitsLines_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QStringList>("lines");
    QTest::newRow("empty") << "" << QStringList();
    QTest::newRow("one without break") << "a" << QStringList {"a"};
    QTest::newRow("final break adds nothing") << "a\nb\n" << QStringList {"a", "b"};
    QTest::newRow("crlf and cr") << "a\r\nb\rc" << QStringList {"a", "b", "c"};
    QTest::newRow("empty lines kept") << "a\n\nb\n\n" << QStringList {"a", "", "b", ""};
}

void TestBuilderGenerateDiff::splitsLines()
{
    QFETCH(QString, text);
    QFETCH(QStringList, lines);
    QCOMPARE(diffLines(text), lines);
}

void TestBuilderGenerateDiff::lineDiff_data()
{
    // Old and new texts are written one character per line.
    QTest::addColumn<QString>("oldText");
    QTest::addColumn<QString>("newText");
    QTest::addColumn<QStringList>("diff");
    QTest::newRow("same") << "abc"
                          << "abc" << QStringList {" a", " b", " c"};
    QTest::newRow("both empty") << ""
                                << "" << QStringList();
    QTest::newRow("all added") << ""
                               << "ab" << QStringList {"+a", "+b"};
    QTest::newRow("all removed") << "ab"
                                 << "" << QStringList {"-a", "-b"};
    QTest::newRow("changed middle") << "abc"
                                    << "axc" << QStringList {" a", "-b", "+x", " c"};
    QTest::newRow("inserted") << "ac"
                              << "abc" << QStringList {" a", "+b", " c"};
    QTest::newRow("deleted at end") << "abc"
                                    << "ab" << QStringList {" a", " b", "-c"};
    QTest::newRow("inserted at start") << "bc"
                                       << "abc" << QStringList {"+a", " b", " c"};
    QTest::newRow("lcs not greedy")
        << "abcabba"
        << "cbabac" << QStringList {"-a", "+c", " b", "-c", " a", " b", "-b", " a", "+c"};
    QTest::newRow("replaced block") << "axyb"
                                    << "apqb" << QStringList {" a", "-x", "-y", "+p", "+q", " b"};
}

void TestBuilderGenerateDiff::lineDiff()
{
    QFETCH(QString, oldText);
    QFETCH(QString, newText);
    QFETCH(QStringList, diff);
    const QList<DiffLine> lines = Builder::lineDiff(chars(oldText), chars(newText));
    QCOMPARE(compact(lines), diff);
    // Every old and every new line appears once, in order.
    QStringList olds, news;
    for (const DiffLine &line : lines) {
        if (line.kind != DiffLine::Kind::Added)
            olds << line.text;
        if (line.kind != DiffLine::Kind::Removed)
            news << line.text;
    }
    QCOMPARE(olds, chars(oldText));
    QCOMPARE(news, chars(newText));
}

void TestBuilderGenerateDiff::lineDiffNumbersLines()
{
    const QList<DiffLine> lines = Builder::lineDiff({"a", "b", "c"}, {"a", "x", "c", "d"});
    const QList<DiffLine> expected {{DiffLine::Kind::Same, "a", 1, 1},
                                    {DiffLine::Kind::Removed, "b", 2, 0},
                                    {DiffLine::Kind::Added, "x", 0, 2},
                                    {DiffLine::Kind::Same, "c", 3, 3},
                                    {DiffLine::Kind::Added, "d", 0, 4}};
    QCOMPARE(lines, expected);
}

void TestBuilderGenerateDiff::unifiedDiff_data()
{
    QTest::addColumn<QString>("oldText");
    QTest::addColumn<QString>("newText");
    QTest::addColumn<int>("context");
    QTest::addColumn<QString>("diff");
    const QString head = QStringLiteral("--- old\n+++ new\n");
    QTest::newRow("identical") << "a\nb\n"
                               << "a\nb\n"
                               << 3 << QString();
    QTest::newRow("only the last line break differs") << "a\nb"
                                                      << "a\nb\n"
                                                      << 3 << QString();
    QTest::newRow("one change, context 1") << "1\n2\n3\n4\n5\n"
                                           << "1\n2\nX\n4\n5\n"
                                           << 1 << head + "@@ -2,3 +2,3 @@\n 2\n-3\n+X\n 4\n";
    QTest::newRow("into an empty file") << ""
                                        << "a\nb\n"
                                        << 3 << head + "@@ -0,0 +1,2 @@\n+a\n+b\n";
    QTest::newRow("everything removed") << "a\n"
                                        << "" << 3 << head + "@@ -1 +0,0 @@\n-a\n";
    QTest::newRow("insertion without context") << "a\nb\n"
                                               << "a\nX\nb\n"
                                               << 0 << head + "@@ -1,0 +2 @@\n+X\n";
    QTest::newRow("distant changes, two hunks")
        << "1\n2\n3\n4\n5\n6\n7\n8\n"
        << "X\n2\n3\n4\n5\n6\n7\nY\n"
        << 1 << head + "@@ -1,2 +1,2 @@\n-1\n+X\n 2\n@@ -7,2 +7,2 @@\n 7\n-8\n+Y\n";
    QTest::newRow("close changes, one hunk")
        << "1\n2\n3\n4\n5\n"
        << "X\n2\n3\nY\n5\n"
        << 1 << head + "@@ -1,5 +1,5 @@\n-1\n+X\n 2\n 3\n-4\n+Y\n 5\n";
}

void TestBuilderGenerateDiff::unifiedDiff()
{
    QFETCH(QString, oldText);
    QFETCH(QString, newText);
    QFETCH(int, context);
    QFETCH(QString, diff);
    QCOMPARE(Builder::unifiedDiff(oldText, newText, "old", "new", context), diff);
}

void TestBuilderGenerateDiff::regenerationDialogShowsTheChangedLines()
{
    const QByteArray existing = "keep\n# my own line\nsame\n";
    const QByteArray fresh = "keep\nsame\n# generated line\n";
    RegenerationDialog dialog("src/Counter.py", existing, fresh);
    const QString text = dialog.diffView()->toPlainText();
    QVERIFY(text.contains("--- src/Counter.py (existing)"));
    QVERIFY(text.contains("-# my own line"));
    QVERIFY(text.contains("+# generated line"));
    QVERIFY(text.contains(" same"));
    QVERIFY(dialog.diffView()->isReadOnly());
    // Changed lines are coloured; context lines are not.
    const QTextDocument *document = dialog.diffView()->document();
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        const bool changed = block.blockNumber() >= 2
            && (block.text().startsWith('-') || block.text().startsWith('+'));
        QCOMPARE(block.blockFormat().hasProperty(QTextFormat::BackgroundBrush)
                     && !block.text().startsWith("@@"),
                 changed);
    }
}

void TestBuilderGenerateDiff::regenerationDialogReturnsTheButtonPressed_data()
{
    QTest::addColumn<FileDecision>("decision");
    QTest::addColumn<bool>("applyToAll");
    QTest::addColumn<int>("result");
    QTest::newRow("keep") << FileDecision::Keep << false << int(QDialog::Rejected);
    QTest::newRow("merge") << FileDecision::Merge << false << int(QDialog::Accepted);
    QTest::newRow("overwrite for all") << FileDecision::Overwrite << true << int(QDialog::Accepted);
}

void TestBuilderGenerateDiff::regenerationDialogReturnsTheButtonPressed()
{
    QFETCH(FileDecision, decision);
    QFETCH(bool, applyToAll);
    QFETCH(int, result);
    RegenerationDialog dialog("a.txt", "old\n", "new\n");
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    if (applyToAll)
        QTest::mouseClick(dialog.applyToAllBox(), Qt::LeftButton, {},
                          QPoint(4, dialog.applyToAllBox()->height() / 2));
    QTest::mouseClick(dialog.button(decision), Qt::LeftButton);
    QTRY_VERIFY(!dialog.isVisible());
    QCOMPARE(dialog.result(), result);
    QCOMPARE(dialog.choice().decision, decision);
    QCOMPARE(dialog.choice().applyToAll, applyToAll);
}

void TestBuilderGenerateDiff::codeRestoreDialogListsSetsAndFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkpath("src"));
    const QString a = dir.filePath("a.py");
    const QString b = dir.filePath("src/b.cpp");
    touch(a, "a");
    touch(b, "b");
    touch(Codegen::Backups::backupPath(a, "20240101100000"), "old a");
    touch(Codegen::Backups::backupPath(a, "20240102100000"), "newer a");
    touch(Codegen::Backups::backupPath(b, "20240102100000"), "newer b");
    const QStringList stamps = Codegen::Backups::stamps(dir.path());
    QCOMPARE(stamps, (QStringList {"20240102100000", "20240101100000"}));

    CodeRestoreDialog dialog(dir.path(), stamps);
    QCOMPARE(dialog.setList()->count(), 2);
    QCOMPARE(dialog.setList()->item(0)->text(), QStringLiteral("2024-01-02 10:00:00"));
    QCOMPARE(dialog.selectedStamp(), QStringLiteral("20240102100000")); // newest preselected
    QCOMPARE(dialog.listedFiles(), (QStringList {"a.py", "src/b.cpp"}));
    dialog.setList()->setCurrentRow(1);
    QCOMPARE(dialog.selectedStamp(), QStringLiteral("20240101100000"));
    QCOMPARE(dialog.listedFiles(), QStringList {"a.py"});
}

void TestBuilderGenerateDiff::optionsDialogRoundTrips()
{
    GenerateOptionsDialog dialog({QStringLiteral("/tmp/out"), 4});
    QCOMPARE(dialog.options(), (GenerateOptions {QStringLiteral("/tmp/out"), 4}));
    dialog.backupsBox()->setValue(7);
    dialog.folderEdit()->setText(QStringLiteral("  /tmp/other  "));
    QCOMPARE(dialog.options(), (GenerateOptions {QStringLiteral("/tmp/other"), 7}));
    QVERIFY(!dialog.testComponentBox()->isChecked());
    dialog.testComponentBox()->setChecked(true);
    QCOMPARE(dialog.options(), (GenerateOptions {QStringLiteral("/tmp/other"), 7, true}));
    GenerateOptionsDialog again({QStringLiteral("/tmp/out"), 4, true});
    QVERIFY(again.testComponentBox()->isChecked());
    QPushButton *generate = nullptr;
    for (QPushButton *button : dialog.findChildren<QPushButton *>()) {
        if (button->text() == QLatin1String("&Generate"))
            generate = button;
    }
    QVERIFY(generate);
    QVERIFY(generate->isEnabled());
    dialog.folderEdit()->clear();
    QVERIFY(!generate->isEnabled());
}

QTEST_MAIN(TestBuilderGenerateDiff)
#include "tst_buildergeneratediff.moc"
