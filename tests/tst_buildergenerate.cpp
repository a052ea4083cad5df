// SPDX-License-Identifier: MIT
// RTC Builder's Generate, regeneration choices, Code restore and Clear backups, driven through
// GenerateController with scripted answers instead of dialogs: files written into a temporary
// project folder, merge keeping the user's lines, keep, overwrite with backups, backup rotation,
// restoring a backup set and clearing backups.
#include "backups.h"
#include "basicpage.h"
#include "codegenerator.h"
#include "componenteditor.h"
#include "componentmodel.h"
#include "generatecontroller.h"
#include "generateoptionsdialog.h"
#include "idltypelibrary.h"
#include "regionmerge.h"
#include "rtcxml.h"
#include "typecatalog.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace Builder;
using Codegen::FileDecision;
using Codegen::TargetLanguage;

Q_DECLARE_METATYPE(Codegen::TargetLanguage)

namespace {

Profile::RtcProfile fixture()
{
    QFile file(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/buildergenerate/Counter.xml"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("missing fixture Counter.xml");
    Profile::Diagnostics diagnostics;
    return *Profile::readRtcXml(file.readAll(), file.fileName(), &diagnostics);
}

/// The fixture with one more output port, so that regenerating changes the marked regions.
Profile::RtcProfile fixtureWithExtraPort()
{
    Profile::RtcProfile profile = fixture();
    Profile::RtcDataPort port = profile.dataPorts.constLast();
    port.name = QStringLiteral("total");
    port.variableName = QStringLiteral("total");
    profile.dataPorts << port;
    return profile;
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

void writeAll(const QString &path, const QByteArray &data)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(file.write(data), data.size());
}

/// Answers every question from fields the test sets, and records what was asked.
struct ScriptedPrompts : GeneratePrompts
{
    std::optional<GenerateOptions> options;
    std::function<FileChoice(const QString &)> decide
        = [](const QString &) { return FileChoice {}; };
    QString restoreAnswer;
    bool clearAnswer = true;

    int optionsAsked = 0;
    GenerateOptions offeredOptions;
    QStringList askedFiles;
    QHash<QString, QPair<QByteArray, QByteArray>> shownContents;
    QStringList offeredStamps;
    int clearCount = -1;
    QString summaryTitle;
    QString summaryText;
    Profile::Diagnostics summaryProblems;

    std::optional<GenerateOptions> askGenerateOptions(const GenerateOptions &current) override
    {
        ++optionsAsked;
        offeredOptions = current;
        return options;
    }
    FileChoice askFileDecision(const QString &relativePath, const QByteArray &existing,
                               const QByteArray &fresh) override
    {
        askedFiles << relativePath;
        shownContents.insert(relativePath, {existing, fresh});
        return decide(relativePath);
    }
    QString askRestoreStamp(const QString &, const QStringList &stamps) override
    {
        offeredStamps = stamps;
        return restoreAnswer;
    }
    bool confirmClearBackups(const QString &, int count) override
    {
        clearCount = count;
        return clearAnswer;
    }
    void showSummary(const QString &title, const QString &text,
                     const Profile::Diagnostics &problems) override
    {
        summaryTitle = title;
        summaryText = text;
        summaryProblems = problems;
    }
};

/// A controller over its own model, writing into a fresh temporary folder, with a clock that
/// moves one minute per call so that every Generate has its own backup stamp.
struct Setup
{
    QTemporaryDir dir;
    ComponentModel model {fixture()};
    ScriptedPrompts prompts;
    GenerateController controller {&model, nullptr, &prompts};
    QDateTime now {QDate(2024, 5, 6), QTime(7, 8, 0)};

    Setup()
    {
        prompts.options = GenerateOptions {dir.path(), 3};
        controller.setClock([this] {
            now = now.addSecs(60);
            return now;
        });
    }
    QString path(const QString &relative) const { return QDir(dir.path()).filePath(relative); }
    /// What the generator makes of `profile` (the expected file contents).
    static QList<Codegen::GeneratedFile> expected(const Profile::RtcProfile &profile)
    {
        const Codegen::IdlTypeLibrary library({RTSTUDIO_IDL_DIR});
        Profile::Diagnostics problems;
        return *Codegen::CodeGenerator(profile, library.model())
                    .generate({TargetLanguage::Python}, &problems);
    }
};

const QByteArray UserLine = "# counted by hand, kept across generations\n";

} // namespace

class TestBuilderGenerate : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void languagesComeFromTheProfile_data();
    void languagesComeFromTheProfile();
    void generateWritesTheProject();
    void generateRemembersTheFolderPerComponent();
    void cancelledOptionsWriteNothing();
    void unknownLanguageIsRefused();
    void mergeKeepsTheUsersLinesAndBacksUp();
    void mergeSkipsMarkersMentionedInText();
    void keepLeavesTheFile();
    void overwriteReplacesAndBacksUp();
    void applyToAllAsksOnce();
    void backupsAreRotated();
    void codeRestoreBringsTheOldSetBack();
    void codeRestoreCancelledChangesNothing();
    void clearBackupsAsksThenRemoves();
    void editorButtonsReachTheController();
    void testComponentBoxWritesTheTestProject();

private:
    QTemporaryDir m_settingsDir;
};

void TestBuilderGenerate::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_buildergenerate"));
}

void TestBuilderGenerate::init()
{
    QSettings().clear();
}

void TestBuilderGenerate::languagesComeFromTheProfile_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<bool>("hasLanguage");
    QTest::addColumn<QList<TargetLanguage>>("languages");
    QTest::addColumn<QStringList>("unknown");
    QTest::newRow("C++") << "C++" << true << QList {TargetLanguage::Cpp} << QStringList();
    QTest::newRow("Python") << "Python" << true << QList {TargetLanguage::Python} << QStringList();
    QTest::newRow("Java") << "Java" << true << QList {TargetLanguage::Java} << QStringList();
    QTest::newRow("several") << "Python, C++;Java" << true
                             << QList {TargetLanguage::Python, TargetLanguage::Cpp,
                                       TargetLanguage::Java}
                             << QStringList();
    QTest::newRow("repeated") << "C++,cpp" << true << QList {TargetLanguage::Cpp} << QStringList();
    QTest::newRow("empty kind") << "" << true << QList {TargetLanguage::Cpp} << QStringList();
    QTest::newRow("no language") << "" << false << QList {TargetLanguage::Cpp} << QStringList();
    QTest::newRow("unknown") << "Ruby" << true << QList<TargetLanguage>() << QStringList {"Ruby"};
    QTest::newRow("unknown beside known")
        << "C++,Ruby" << true << QList {TargetLanguage::Cpp} << QStringList {"Ruby"};
}

void TestBuilderGenerate::languagesComeFromTheProfile()
{
    QFETCH(QString, kind);
    QFETCH(bool, hasLanguage);
    QFETCH(QList<TargetLanguage>, languages);
    QFETCH(QStringList, unknown);
    Profile::RtcProfile profile = fixture();
    if (hasLanguage)
        profile.language->kind = kind;
    else
        profile.language.reset();
    QStringList found;
    QCOMPARE(GenerateController::languagesOf(profile, &found), languages);
    QCOMPARE(found, unknown);
}

void TestBuilderGenerate::generateWritesTheProject()
{
    Setup s;
    QSignalSpy generated(&s.controller, &GenerateController::generated);
    QVERIFY(s.controller.generate());
    QCOMPARE(generated.count(), 1);
    const QList<Codegen::GeneratedFile> expected = Setup::expected(fixture());
    QVERIFY(expected.size() > 3);
    QStringList paths;
    for (const Codegen::GeneratedFile &file : expected) {
        paths << file.path;
        QCOMPARE(readAll(s.path(file.path)), file.content);
    }
    QVERIFY(paths.contains("Counter.py"));
    QVERIFY(paths.contains("RTC.xml"));
    const auto report = generated.at(0).at(0).value<Codegen::WriteReport>();
    QCOMPARE(report.created.size(), expected.size());
    QVERIFY(s.prompts.askedFiles.isEmpty()); // nothing existed, so nothing to decide
    QCOMPARE(s.prompts.summaryTitle, QStringLiteral("Generate"));
    QVERIFY(s.prompts.summaryText.contains("Counter.py"));
    QVERIFY(s.prompts.summaryProblems.isEmpty());
    // The staging folder is gone again.
    QCOMPARE(QDir(s.dir.path()).entryList({".rtstudio-gen-*"}, QDir::AllEntries | QDir::Hidden),
             QStringList());
}

void TestBuilderGenerate::generateRemembersTheFolderPerComponent()
{
    Setup s;
    QCOMPARE(s.controller.outputFolder(), QString());
    s.prompts.options = GenerateOptions {s.dir.path(), 5};
    QVERIFY(s.controller.generate());
    QCOMPARE(s.controller.outputFolder(), s.dir.path());
    QCOMPARE(GenerateController::backupsKept(), 5);
    // The next Generate offers what was chosen.
    QVERIFY(s.controller.generate());
    QCOMPARE(s.prompts.offeredOptions, (GenerateOptions {s.dir.path(), 5}));
    // Another component has its own folder.
    Profile::RtcProfile other = fixture();
    other.id = QStringLiteral("RTC:Example:Test:Other:1.0.0");
    other.basicInfo.name = QStringLiteral("Other");
    ComponentModel otherModel(other);
    GenerateController otherController(&otherModel, nullptr, &s.prompts);
    QCOMPARE(otherController.outputFolder(), QString());
}

void TestBuilderGenerate::cancelledOptionsWriteNothing()
{
    Setup s;
    s.prompts.options.reset();
    QSignalSpy generated(&s.controller, &GenerateController::generated);
    QVERIFY(!s.controller.generate());
    QCOMPARE(s.prompts.optionsAsked, 1);
    QCOMPARE(generated.count(), 0);
    QCOMPARE(QDir(s.dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot), QStringList());
}

void TestBuilderGenerate::unknownLanguageIsRefused()
{
    Setup s;
    Profile::RtcProfile profile = fixture();
    profile.language->kind = QStringLiteral("Ruby");
    s.model.setProfile(profile);
    QSignalSpy problems(&s.controller, &GenerateController::problemsFound);
    QVERIFY(!s.controller.generate());
    QCOMPARE(problems.count(), 1);
    QCOMPARE(s.prompts.optionsAsked, 0);
    QCOMPARE(s.prompts.summaryProblems.size(), 1);
    QVERIFY(s.prompts.summaryProblems.at(0).message.contains("Ruby"));
    QCOMPARE(QDir(s.dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot), QStringList());
}

void TestBuilderGenerate::mergeKeepsTheUsersLinesAndBacksUp()
{
    Setup s;
    QVERIFY(s.controller.generate());
    const QString script = s.path("Counter.py");
    const QByteArray edited = readAll(script) + UserLine;
    writeAll(script, edited);
    s.model.setProfile(fixtureWithExtraPort());
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Merge, false}; };
    QVERIFY2(s.controller.generate(), qPrintable(s.prompts.summaryProblems.value(0).toString()));

    QVERIFY(s.prompts.askedFiles.contains("Counter.py"));
    QCOMPARE(s.prompts.shownContents.value("Counter.py").first, edited);
    const QByteArray merged = readAll(script);
    QVERIFY(merged.contains(UserLine)); // the user's line outside the markers stays
    QVERIFY(merged.contains("total")); // the marked regions know the new port
    QVERIFY(!edited.contains("total"));
    const QStringList backups = Codegen::Backups::backupsOf(script);
    QCOMPARE(backups.size(), 1);
    QCOMPARE(readAll(backups.at(0)), edited);
    QVERIFY(s.prompts.summaryText.contains("Merged"));
}

void TestBuilderGenerate::mergeSkipsMarkersMentionedInText()
{
    // The generated README explains the markers in prose; only marker lines open blocks.
    const QString existing = QStringLiteral(
        "Code between `<rtc-template block=\"…\">` markers belongs to the generator.\n"
        "<!-- <rtc-template block=\"list\"> -->\nold\n<!-- </rtc-template> -->\nmine\n");
    const QString fresh = QStringLiteral(
        "Code between `<rtc-template block=\"…\">` markers belongs to the generator.\n"
        "<!-- <rtc-template block=\"list\"> -->\nnew\n<!-- </rtc-template> -->\n");
    const Codegen::RegionMergeResult merged = Codegen::mergeTemplateRegions(existing, fresh);
    QVERIFY2(merged.text, qPrintable(merged.error));
    QCOMPARE(*merged.text, QString(existing).replace("old", "new"));
    QCOMPARE(Codegen::templateRegionNames(existing), QStringList {"list"});
}

void TestBuilderGenerate::keepLeavesTheFile()
{
    Setup s;
    QVERIFY(s.controller.generate());
    const QString script = s.path("Counter.py");
    const QByteArray edited = readAll(script) + UserLine;
    writeAll(script, edited);
    s.model.setProfile(fixtureWithExtraPort());
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Keep, false}; };
    QSignalSpy generated(&s.controller, &GenerateController::generated);
    QVERIFY(s.controller.generate());
    QCOMPARE(readAll(script), edited);
    QVERIFY(Codegen::Backups::backupsOf(script).isEmpty());
    const auto report = generated.at(0).at(0).value<Codegen::WriteReport>();
    QVERIFY(report.kept.contains("Counter.py"));
    QVERIFY(report.backups.isEmpty());
}

void TestBuilderGenerate::overwriteReplacesAndBacksUp()
{
    Setup s;
    QVERIFY(s.controller.generate());
    const QString script = s.path("Counter.py");
    const QByteArray edited = readAll(script) + UserLine;
    writeAll(script, edited);
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Overwrite, false}; };
    QVERIFY(s.controller.generate());
    // Only the edited file differed, so only it was asked about.
    QCOMPARE(s.prompts.askedFiles, QStringList {"Counter.py"});
    QByteArray fresh;
    for (const Codegen::GeneratedFile &file : Setup::expected(fixture())) {
        if (file.path == QLatin1String("Counter.py"))
            fresh = file.content;
    }
    QCOMPARE(readAll(script), fresh);
    const QStringList backups = Codegen::Backups::backupsOf(script);
    QCOMPARE(backups.size(), 1);
    QCOMPARE(readAll(backups.at(0)), edited);
    QVERIFY(backups.at(0).endsWith(Codegen::Backups::stamp(s.now)));
}

void TestBuilderGenerate::applyToAllAsksOnce()
{
    Setup s;
    QVERIFY(s.controller.generate());
    s.model.setProfile(fixtureWithExtraPort());
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Overwrite, true}; };
    QSignalSpy generated(&s.controller, &GenerateController::generated);
    QVERIFY(s.controller.generate());
    QCOMPARE(s.prompts.askedFiles.size(), 1);
    const auto report = generated.at(0).at(0).value<Codegen::WriteReport>();
    QVERIFY(report.overwritten.size() > 1); // the extra port changes more than one file
    for (const Codegen::GeneratedFile &file : Setup::expected(fixtureWithExtraPort()))
        QCOMPARE(readAll(s.path(file.path)), file.content);
}

void TestBuilderGenerate::backupsAreRotated()
{
    Setup s;
    s.prompts.options = GenerateOptions {s.dir.path(), 2};
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Overwrite, true}; };
    QVERIFY(s.controller.generate());
    const QString script = s.path("Counter.py");
    QStringList stamps;
    for (int round = 0; round < 4; ++round) {
        writeAll(script, readAll(script) + "# edit " + QByteArray::number(round) + '\n');
        QVERIFY(s.controller.generate());
        stamps.prepend(Codegen::Backups::stamp(s.now));
    }
    const QStringList backups = Codegen::Backups::backupsOf(script);
    QCOMPARE(backups.size(), 2);
    QVERIFY(backups.at(0).endsWith(stamps.at(0)));
    QVERIFY(backups.at(1).endsWith(stamps.at(1)));
    QVERIFY(readAll(backups.at(0)).endsWith("# edit 3\n"));
    QVERIFY(s.prompts.summaryText.contains("Old backups deleted"));
}

void TestBuilderGenerate::codeRestoreBringsTheOldSetBack()
{
    Setup s;
    QVERIFY(s.controller.generate());
    const QString script = s.path("Counter.py");
    const QByteArray edited = readAll(script) + UserLine;
    writeAll(script, edited);
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Overwrite, true}; };
    QVERIFY(s.controller.generate());
    const QByteArray regenerated = readAll(script);
    QVERIFY(regenerated != edited);

    const QStringList stamps = Codegen::Backups::stamps(s.dir.path());
    QCOMPARE(stamps.size(), 1);
    s.prompts.restoreAnswer = stamps.at(0);
    QVERIFY(s.controller.restoreCode());
    QCOMPARE(s.prompts.offeredStamps, stamps);
    QCOMPARE(readAll(script), edited);
    // The replaced file became the backup, so restoring again swaps back.
    QCOMPARE(readAll(Codegen::Backups::backupPath(script, stamps.at(0))), regenerated);
    QVERIFY(s.prompts.summaryText.contains("Counter.py"));
    QVERIFY(s.controller.restoreCode());
    QCOMPARE(readAll(script), regenerated);
}

void TestBuilderGenerate::codeRestoreCancelledChangesNothing()
{
    Setup s;
    QVERIFY(s.controller.restoreCode() == false); // nothing generated yet: no backups
    QVERIFY(s.prompts.summaryText.contains("no backups"));
    QVERIFY(s.controller.generate());
    const QString script = s.path("Counter.py");
    const QByteArray edited = readAll(script) + UserLine;
    writeAll(script, edited);
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Overwrite, true}; };
    QVERIFY(s.controller.generate());
    const QByteArray regenerated = readAll(script);
    s.prompts.restoreAnswer.clear();
    QVERIFY(!s.controller.restoreCode());
    QCOMPARE(s.prompts.offeredStamps.size(), 1);
    QCOMPARE(readAll(script), regenerated);
}

void TestBuilderGenerate::clearBackupsAsksThenRemoves()
{
    Setup s;
    QVERIFY(s.controller.generate());
    s.prompts.decide = [](const QString &) { return FileChoice {FileDecision::Overwrite, true}; };
    s.model.setProfile(fixtureWithExtraPort());
    QVERIFY(s.controller.generate());
    const QString stamp = Codegen::Backups::stamps(s.dir.path()).value(0);
    const int count = int(Codegen::Backups::filesOfSet(s.dir.path(), stamp).size());
    QVERIFY(count > 1);

    s.prompts.clearAnswer = false;
    QVERIFY(!s.controller.clearBackups());
    QCOMPARE(s.prompts.clearCount, count);
    QCOMPARE(Codegen::Backups::filesOfSet(s.dir.path(), stamp).size(), count);

    s.prompts.clearAnswer = true;
    QVERIFY(s.controller.clearBackups());
    QCOMPARE(Codegen::Backups::stamps(s.dir.path()), QStringList());
    QVERIFY(QFile::exists(s.path("Counter.py"))); // the generated files themselves stay
    QVERIFY(s.prompts.summaryText.contains(QString::number(count)));
}

void TestBuilderGenerate::editorButtonsReachTheController()
{
    Setup s;
    QUndoStack stack;
    TypeCatalog types(RTSTUDIO_IDL_DIR);
    ComponentEditor editor(&s.model, &stack, &types);
    s.controller.connectEditor(&editor);
    QSignalSpy generated(&s.controller, &GenerateController::generated);
    QTest::mouseClick(editor.basicPage()->generateButton(), Qt::LeftButton);
    QCOMPARE(generated.count(), 1);
    QVERIFY(QFile::exists(s.path("Counter.py")));

    s.prompts.clearCount = -1;
    emit editor.clearBackupsRequested();
    QCOMPARE(s.prompts.summaryTitle, QStringLiteral("Clear Backups")); // nothing to clear yet
    s.prompts.summaryTitle.clear();
    emit editor.codeRestoreRequested();
    QCOMPARE(s.prompts.summaryTitle, QStringLiteral("Code Restore"));
}

/// Answers the options question with the real dialog: ticks the test component box, as the user
/// would, and presses Generate.
struct TickingPrompts : ScriptedPrompts
{
    bool tick = true;

    std::optional<GenerateOptions> askGenerateOptions(const GenerateOptions &current) override
    {
        ++optionsAsked;
        offeredOptions = current;
        GenerateOptionsDialog dialog(current);
        dialog.show();
        if (!QTest::qWaitForWindowExposed(&dialog))
            return std::nullopt;
        if (tick)
            QTest::mouseClick(dialog.testComponentBox(), Qt::LeftButton, {},
                              dialog.testComponentBox()->rect().center());
        dialog.folderEdit()->setText(options->outputFolder);
        for (QPushButton *button : dialog.findChildren<QPushButton *>()) {
            if (button->text() == QLatin1String("&Generate"))
                QTest::mouseClick(button, Qt::LeftButton);
        }
        if (dialog.result() != QDialog::Accepted)
            return std::nullopt;
        return dialog.options();
    }
};

void TestBuilderGenerate::testComponentBoxWritesTheTestProject()
{
    QTemporaryDir dir;
    Profile::RtcProfile profile = fixture();
    profile.language->kind = QStringLiteral("C++");
    ComponentModel model(profile);
    TickingPrompts prompts;
    prompts.options = GenerateOptions {dir.path(), 3};
    GenerateController controller(&model, nullptr, &prompts);
    QVERIFY(controller.generate());
    QVERIFY(!prompts.offeredOptions.testComponent); // off until asked for
    QVERIFY2(prompts.summaryProblems.isEmpty(),
             qPrintable(prompts.summaryProblems.value(0).toString()));
    const QDir out(dir.path());
    for (const char *path : {"src/Counter.cpp", "test/CMakeLists.txt", "test/src/CounterTest.cpp",
                             "test/include/CounterTest/CounterTest.h"})
        QVERIFY2(out.exists(path), path);
    QVERIFY(readAll(out.filePath("test/src/CounterTest.cpp")).contains("CounterTest::"));
    // The choice is remembered and offered, ticked, next time; unticking it is remembered too.
    QVERIFY(GenerateController::testComponent());
    QVERIFY(controller.generate());
    QVERIFY(prompts.offeredOptions.testComponent);
    QVERIFY(!GenerateController::testComponent());
    prompts.tick = false;
    QVERIFY(controller.generate());
    QVERIFY(!prompts.offeredOptions.testComponent);
}

QTEST_MAIN(TestBuilderGenerate)
#include "tst_buildergenerate.moc"
