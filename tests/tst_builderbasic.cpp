// SPDX-License-Identifier: MIT
// The Basic page's newer fields driven like a user: abstract, RTC type, component kind check
// boxes, language check boxes kept in sync with the Language page, Import (one undo step, precise
// errors, nothing lost) and Export (XML or YAML by extension).
#include "basicpage.h"
#include "componenteditor.h"
#include "kindchoices.h"
#include "languagepage.h"
#include "modalguard.h"
#include "profileio.h"
#include "rtcxml.h"
#include "tst_buildersupport.h"
#include "typecatalog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace Builder;

namespace {

using BuilderTest::fixture;

/// An editor over the fixture, shown, with its own model, stack and IDL catalog.
struct Editor
{
    ComponentModel model {fixture()};
    QUndoStack stack;
    TypeCatalog types {RTSTUDIO_IDL_DIR};
    ComponentEditor editor {&model, &stack, &types};
    BasicPage *basic = editor.basicPage();

    Editor()
    {
        editor.resize(1200, 800);
        editor.show();
    }
};

/// Clicks a check box as a user does.
void click(QCheckBox *box)
{
    QTest::mouseClick(box, Qt::LeftButton, {}, QPoint(4, box->height() / 2));
}

} // namespace

class TestBuilderBasic : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void abstractIsTypedAndUndone();
    void rtcTypeIsOptional();
    void componentKindBoxes();
    void componentKindNeedsOne();
    void kindChoices();
    void languageBoxesFollowLanguagePage();
    void languageProblemsAreShown();
    void importIsOneUndoStep();
    void importFromTheDialog();
    void importOfBrokenFileNamesLineAndKeepsModel();
    void importOfSystemIsRefused();
    void exportWritesXmlOrYaml();
    void exportFailureLeavesOldFile();

private:
    QTemporaryDir m_settingsDir;
};

void TestBuilderBasic::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    BuilderTest::isolateSettings(m_settingsDir, QStringLiteral("tst_builderbasic"));
}

void TestBuilderBasic::abstractIsTypedAndUndone()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *abstract = qobject_cast<QPlainTextEdit *>(e.basic->editor(BasicField::Abstract));
    QVERIFY(abstract);
    QCOMPARE(abstract->toPlainText(), QString());
    QVERIFY(!e.model.profile().basicInfo.abstractText);
    abstract->setFocus();
    QTest::keyClicks(abstract, QStringLiteral("Two lines"));
    QTest::keyClick(abstract, Qt::Key_Return);
    QTest::keyClicks(abstract, QStringLiteral("of text"));
    QCOMPARE(e.model.profile().basicInfo.abstractText, QStringLiteral("Two lines\nof text"));
    QCOMPARE(e.stack.count(), 1); // typing is one step
    QCOMPARE(e.stack.undoText(), QStringLiteral("Change abstract"));
    QVERIFY(
        Profile::writeRtcXml(e.model.profile()).contains("rtc:abstract=\"Two lines&#10;of text\""));
    e.stack.undo();
    QVERIFY(!e.model.profile().basicInfo.abstractText);
    QCOMPARE(abstract->toPlainText(), QString());
    QVERIFY(e.model.profile() == fixture());
    e.stack.redo();
    QCOMPARE(abstract->toPlainText(), QStringLiteral("Two lines\nof text"));
}

void TestBuilderBasic::rtcTypeIsOptional()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *rtcType = qobject_cast<QLineEdit *>(e.basic->editor(BasicField::RtcType));
    QVERIFY(rtcType);
    QTest::keyClicks(rtcType, QStringLiteral("Normal"));
    QCOMPARE(e.model.profile().basicInfo.rtcType, QStringLiteral("Normal"));
    QVERIFY(Profile::writeRtcXml(e.model.profile()).contains("rtc:rtcType=\"Normal\""));
    // Deleting it again leaves no attribute, as before.
    rtcType->selectAll();
    QTest::keyClick(rtcType, Qt::Key_Delete);
    QVERIFY(!e.model.profile().basicInfo.rtcType);
    QCOMPARE(e.basic->problem(BasicField::RtcType), QString());
    QCOMPARE(e.stack.count(), 0); // the merged step ended where it started
}

void TestBuilderBasic::componentKindBoxes()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    QCheckBox *dataFlow = e.basic->componentKindBox(QStringLiteral("DataFlow"));
    QCheckBox *fsm = e.basic->componentKindBox(QStringLiteral("FiniteStateMachine"));
    QCheckBox *multiMode = e.basic->componentKindBox(QStringLiteral("MultiMode"));
    QVERIFY(dataFlow && fsm && multiMode);
    QVERIFY(dataFlow->isChecked());
    QVERIFY(!fsm->isChecked());
    QCOMPARE(fsm->text(), QStringLiteral("FSM"));
    click(fsm);
    QCOMPARE(e.model.profile().basicInfo.componentKind,
             QStringLiteral("DataFlowFiniteStateMachineComponent"));
    click(multiMode);
    QCOMPARE(e.model.profile().basicInfo.componentKind,
             QStringLiteral("DataFlowFiniteStateMachineMultiModeComponent"));
    QCOMPARE(e.stack.count(), 2); // every click is a step
    QCOMPARE(e.stack.undoText(), QStringLiteral("Change component kind"));
    e.stack.undo();
    QVERIFY(!multiMode->isChecked());
    e.stack.undo();
    QVERIFY(!fsm->isChecked());
    QCOMPARE(e.model.profile().basicInfo.componentKind, QStringLiteral("DataFlowComponent"));
    e.stack.redo();
    QVERIFY(fsm->isChecked());
}

void TestBuilderBasic::componentKindNeedsOne()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    click(e.basic->componentKindBox(QStringLiteral("DataFlow")));
    QCOMPARE(e.model.profile().basicInfo.componentKind, QString());
    QCOMPARE(e.basic->problem(BasicField::ComponentKind),
             QStringLiteral("Choose at least one component kind (DataFlow, FSM or MultiMode)."));
    click(e.basic->componentKindBox(QStringLiteral("MultiMode")));
    QCOMPARE(e.model.profile().basicInfo.componentKind, QStringLiteral("MultiModeComponent"));
    QCOMPARE(e.basic->problem(BasicField::ComponentKind), QString());
}

void TestBuilderBasic::kindChoices()
{
    using namespace KindChoices;
    QCOMPARE(
        withComponentKind(QStringLiteral("MultiModeComponent"), QStringLiteral("DataFlow"), true),
        QStringLiteral("DataFlowMultiModeComponent"));
    QCOMPARE(
        withComponentKind(QStringLiteral("DataFlowComponent"), QStringLiteral("DataFlow"), false),
        QString());
    QVERIFY(componentKindProblem(QStringLiteral("Strange")).contains(QStringLiteral("Strange")));
    QCOMPARE(withLanguage(QStringLiteral("C++"), QStringLiteral("Java"), true),
             QStringLiteral("C++, Java"));
    QCOMPARE(withLanguage(QStringLiteral("c++;Java"), QStringLiteral("C++"), false),
             QStringLiteral("Java"));
    QVERIFY(hasLanguage(QStringLiteral("python"), QStringLiteral("Python")));
    QCOMPARE(languageProblem(QStringLiteral("C++, Ruby")),
             QStringLiteral("No code can be generated for Ruby (C++, Python or Java)."));
    QCOMPARE(languageProblem(QString()), QStringLiteral("Choose at least one language."));
}

void TestBuilderBasic::languageBoxesFollowLanguagePage()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    QCheckBox *cpp = e.basic->languageBox(QStringLiteral("C++"));
    QCheckBox *python = e.basic->languageBox(QStringLiteral("Python"));
    QVERIFY(cpp && python);
    QVERIFY(cpp->isChecked());
    QVERIFY(!python->isChecked());
    click(python);
    QCOMPARE(e.model.profile().language->kind, QStringLiteral("C++, Python"));
    // The Language page shows the same field.
    auto *language
        = qobject_cast<LanguagePage *>(e.editor.page(QStringLiteral("Language/Environment")));
    auto *kind = qobject_cast<QComboBox *>(language->editor(LanguagePage::Field::Kind));
    QCOMPARE(kind->currentText(), QStringLiteral("C++, Python"));
    click(cpp);
    QCOMPARE(e.model.profile().language->kind, QStringLiteral("Python"));
    // Choosing on the Language page updates the boxes.
    kind->setCurrentIndex(kind->findText(QStringLiteral("Java")));
    QCOMPARE(e.model.profile().language->kind, QStringLiteral("Java"));
    QVERIFY(!python->isChecked());
    QVERIFY(e.basic->languageBox(QStringLiteral("Java"))->isChecked());
    QCOMPARE(e.stack.count(), 3);
    e.stack.undo();
    QVERIFY(python->isChecked());
    e.stack.undo();
    e.stack.undo();
    QVERIFY(cpp->isChecked());
    QVERIFY(!python->isChecked());
    QVERIFY(e.model.profile() == fixture()); // targets and libraries untouched
}

void TestBuilderBasic::languageProblemsAreShown()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    QCOMPARE(e.basic->languageProblem(), QString());
    click(e.basic->languageBox(QStringLiteral("C++")));
    QCOMPARE(e.basic->languageProblem(), QStringLiteral("Choose at least one language."));
    Profile::RtcLanguage language = *e.model.profile().language;
    language.kind = QStringLiteral("Ruby");
    e.model.setLanguage(language);
    QVERIFY(e.basic->languageProblem().contains(QStringLiteral("Ruby")));
}

void TestBuilderBasic::importIsOneUndoStep()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    QVERIFY(e.basic->importProfile(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/rtc/full.xml")));
    QCOMPARE(e.stack.count(), 1);
    QCOMPARE(e.stack.undoText(), QStringLiteral("Import full.xml"));
    QCOMPARE(e.model.profile().basicInfo.name, QStringLiteral("Full"));
    auto *abstract = qobject_cast<QPlainTextEdit *>(e.basic->editor(BasicField::Abstract));
    QCOMPARE(abstract->toPlainText(), QStringLiteral("An abstract"));
    QCOMPARE(qobject_cast<QLineEdit *>(e.basic->editor(BasicField::RtcType))->text(),
             QStringLiteral("Normal"));
    QVERIFY(e.basic->transferMessage().startsWith(QStringLiteral("Imported full.xml")));
    e.stack.undo();
    QVERIFY(e.model.profile() == fixture());
    QCOMPARE(abstract->toPlainText(), QString());
    e.stack.redo();
    QCOMPARE(e.model.profile().basicInfo.name, QStringLiteral("Full"));
    // YAML works the same way, told apart by content.
    QVERIFY(e.basic->importProfile(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/rtc/full.yaml")));
    QCOMPARE(e.stack.count(), 2);
    QCOMPARE(e.model.profile().basicInfo.name, QStringLiteral("Yaml"));
}

void TestBuilderBasic::importFromTheDialog()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    const GuiTest::ModalGuard::Expected expected; // window-modal, answered below
    QTest::mouseClick(e.basic->findChild<QPushButton *>(QStringLiteral("importButton")),
                      Qt::LeftButton);
    QFileDialog *dialog = nullptr;
    QTRY_VERIFY((dialog = e.basic->findChild<QFileDialog *>(QStringLiteral("transferDialog"))));
    QCOMPARE(dialog->acceptMode(), QFileDialog::AcceptOpen);
    dialog->selectFile(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/rtc/full.xml"));
    static_cast<QDialog *>(dialog)->accept(); // what the Open button does
    QCOMPARE(e.model.profile().basicInfo.name, QStringLiteral("Full"));
    QCOMPARE(e.stack.count(), 1);
}

void TestBuilderBasic::importOfBrokenFileNamesLineAndKeepsModel()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    QSignalSpy failed(e.basic, &BasicPage::transferFailed);
    const QString broken = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builder/broken.xml");
    QVERIFY(!e.basic->importProfile(broken));
    QCOMPARE(failed.count(), 1);
    const auto problems = failed.at(0).at(0).value<Profile::Diagnostics>();
    QVERIFY(!problems.isEmpty());
    QCOMPARE(problems.first().file, broken);
    QVERIFY(problems.first().line > 0);
    QVERIFY2(e.basic->transferMessage().contains(QStringLiteral("broken.xml:")),
             qPrintable(e.basic->transferMessage()));
    QCOMPARE(e.stack.count(), 0);
    QVERIFY(e.model.profile() == fixture());
}

void TestBuilderBasic::importOfSystemIsRefused()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    QVERIFY(!e.basic->importProfile(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/rts/full.xml")));
    QVERIFY(e.basic->transferMessage().contains(QStringLiteral("System Editor")));
    QCOMPARE(e.stack.count(), 0);
    QVERIFY(e.model.profile() == fixture());
}

void TestBuilderBasic::exportWritesXmlOrYaml()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    auto *rtcType = qobject_cast<QLineEdit *>(e.basic->editor(BasicField::RtcType));
    QTest::keyClicks(rtcType, QStringLiteral("Normal"));
    for (const QString &name : {QStringLiteral("RTC.xml"), QStringLiteral("RTC.yaml")}) {
        const QString path = dir.filePath(name);
        QVERIFY(e.basic->exportProfile(path));
        Profile::Diagnostics diagnostics;
        const auto loaded = Profile::loadProfileFile(path, &diagnostics);
        QVERIFY(loaded && loaded->rtc);
        QCOMPARE(loaded->format, Profile::formatForFileName(path));
        QCOMPARE(loaded->rtc->basicInfo.rtcType, QStringLiteral("Normal"));
        QCOMPARE(loaded->rtc->basicInfo.name, QStringLiteral("Scanner"));
    }
    QVERIFY(e.basic->transferMessage().startsWith(QStringLiteral("Exported to")));
    QCOMPARE(e.stack.count(), 1); // exporting changes nothing
}

void TestBuilderBasic::exportFailureLeavesOldFile()
{
    Editor e;
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QSignalSpy failed(e.basic, &BasicPage::transferFailed);
    // A path below a plain file cannot be written.
    const QString blocker = dir.filePath(QStringLiteral("file"));
    QFile file(blocker);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("keep");
    file.close();
    QVERIFY(!e.basic->exportProfile(blocker + QStringLiteral("/RTC.xml")));
    QCOMPARE(failed.count(), 1);
    QVERIFY(e.basic->transferMessage().startsWith(QStringLiteral("Nothing was exported")));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), QByteArray("keep"));
}

QTEST_MAIN(TestBuilderBasic)
#include "tst_builderbasic.moc"
