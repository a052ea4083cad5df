// SPDX-License-Identifier: MIT
// The Builder's Basic page and the System Editor's system info form: edits become undo commands,
// the views follow the document (also on undo), problems are marked inline.
#include "basicpage.h"
#include "fieldrules.h"
#include "rtcdocument.h"
#include "systeminfoform.h"

#include <QComboBox>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTest>
#include <QUndoStack>

using namespace Studio;
using Builder::BasicPage;
using Field = Builder::BasicField;
using SystemField = RtsDocument::SystemField;

namespace {

QLineEdit *lineEdit(const BasicPage &page, Field field)
{
    return qobject_cast<QLineEdit *>(page.editor(field));
}

/// Types text like keyClicks(), also characters outside ASCII (which keyClicks() cannot send).
void typeText(QWidget *widget, const QString &text)
{
    for (QChar c : text) {
        if (c.unicode() < 0x80)
            QTest::keyClick(widget, c.toLatin1());
        else
            QTest::sendKeyEvent(QTest::Click, widget, Qt::Key_unknown, QString(c), Qt::NoModifier);
    }
}

QComboBox *comboBox(const BasicPage &page, Field field)
{
    return qobject_cast<QComboBox *>(page.editor(field));
}

} // namespace

class TestAppViews : public QObject
{
    Q_OBJECT

private slots:
    void basicPageShowsDocument();
    void typingIntoNameIsOneUndoStep();
    void nameCharsetIsMarkedInline_data();
    void nameCharsetIsMarkedInline();
    void numbersAreCheckedInline();
    void choosingAComboEntryPushesCommand();
    void typingIntoEditableComboKeepsTyping();
    void unknownEnumValueIsShownNotReplaced();
    void clearingOptionalFieldRemovesIt();
    void systemInfoEditsTheId();
    void systemInfoRefusesColonAndMarksEmpty();
    void systemInfoAbstractIsUndoable();
    void fieldRules_data();
    void fieldRules();
};

void TestAppViews::basicPageShowsDocument()
{
    RtcDocument document(Profile::RtcProfile::createDefault());
    BasicPage page(document.model(), document.undoStack());
    QCOMPARE(lineEdit(page, Field::Name)->text(), QStringLiteral("ModuleName"));
    QCOMPARE(lineEdit(page, Field::Description)->text(), QStringLiteral("ModuleDescription"));
    QCOMPARE(lineEdit(page, Field::Version)->text(), QStringLiteral("1.0.0"));
    QCOMPARE(lineEdit(page, Field::Vendor)->text(), QStringLiteral("VenderName"));
    QCOMPARE(comboBox(page, Field::Category)->currentText(), QStringLiteral("Category"));
    QCOMPARE(comboBox(page, Field::ComponentType)->currentText(), QStringLiteral("STATIC"));
    QCOMPARE(comboBox(page, Field::ActivityType)->currentText(), QStringLiteral("PERIODIC"));
    QCOMPARE(lineEdit(page, Field::MaxInstances)->text(), QStringLiteral("1"));
    QCOMPARE(comboBox(page, Field::ExecutionType)->currentText(),
             QStringLiteral("PeriodicExecutionContext"));
    QCOMPARE(lineEdit(page, Field::ExecutionRate)->text().toDouble(), 1000.0);
    QVERIFY(comboBox(page, Field::Category)->findText(QStringLiteral("Sensor")) >= 0);
    QCOMPARE(BasicPage::categoryPresets().size(), 32);
    QCOMPARE(document.undoStack()->count(), 0); // showing pushes nothing
    QCOMPARE(page.problem(Field::Name), QString());
}

void TestAppViews::typingIntoNameIsOneUndoStep()
{
    RtcDocument document(Profile::RtcProfile::createDefault());
    BasicPage page(document.model(), document.undoStack());
    QLineEdit *name = lineEdit(page, Field::Name);
    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("Scanner"));
    QCOMPARE(document.model()->basicField(Field::Name), QStringLiteral("Scanner"));
    QCOMPARE(document.model()->componentId(), QStringLiteral("RTC:VenderName:Category:Scanner:1.0.0"));
    QCOMPARE(document.undoStack()->count(), 1);

    document.undoStack()->undo();
    QCOMPARE(name->text(), QStringLiteral("ModuleName"));
    QCOMPARE(document.model()->basicField(Field::Name), QStringLiteral("ModuleName"));
    document.undoStack()->redo();
    QCOMPARE(name->text(), QStringLiteral("Scanner"));
}

void TestAppViews::nameCharsetIsMarkedInline_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("valid");
    QTest::newRow("letters digits _ - :") << QStringLiteral("Comp_1-a:b") << true;
    QTest::newRow("space") << QStringLiteral("My Comp") << false;
    QTest::newRow("dot") << QStringLiteral("comp.v2") << false;
    QTest::newRow("non-ascii") << QStringLiteral("Komponente\u00e4") << false;
}

void TestAppViews::nameCharsetIsMarkedInline()
{
    QFETCH(QString, name);
    QFETCH(bool, valid);
    RtcDocument document(Profile::RtcProfile::createDefault());
    BasicPage page(document.model(), document.undoStack());
    QLineEdit *edit = lineEdit(page, Field::Name);
    edit->clear();
    typeText(edit, name);
    QCOMPARE(document.model()->basicField(Field::Name), name); // the value is kept either way
    QCOMPARE(page.problem(Field::Name).isEmpty(), valid);
    QCOMPARE(edit->toolTip(), page.problem(Field::Name));
}

void TestAppViews::numbersAreCheckedInline()
{
    RtcDocument document(Profile::RtcProfile::createDefault());
    BasicPage page(document.model(), document.undoStack());
    QLineEdit *instances = lineEdit(page, Field::MaxInstances);
    instances->selectAll();
    QTest::keyClicks(instances, QStringLiteral("-1"));
    QVERIFY(!page.problem(Field::MaxInstances).isEmpty());
    QTest::keyClick(instances, Qt::Key_Backspace);
    QTest::keyClick(instances, Qt::Key_Backspace);
    QTest::keyClicks(instances, QStringLiteral("0"));
    QCOMPARE(page.problem(Field::MaxInstances), QString());

    QLineEdit *rate = lineEdit(page, Field::ExecutionRate);
    rate->selectAll();
    QTest::keyClicks(rate, QStringLiteral("fast"));
    QVERIFY(!page.problem(Field::ExecutionRate).isEmpty());
    document.undoStack()->undo();
    QCOMPARE(page.problem(Field::ExecutionRate), QString());
}

void TestAppViews::choosingAComboEntryPushesCommand()
{
    RtcDocument document(Profile::RtcProfile::createDefault());
    BasicPage page(document.model(), document.undoStack());
    QComboBox *activity = comboBox(page, Field::ActivityType);
    activity->setCurrentIndex(activity->findText(QStringLiteral("SPORADIC")));
    QCOMPARE(document.model()->basicField(Field::ActivityType), QStringLiteral("SPORADIC"));
    QCOMPARE(document.undoStack()->count(), 1);

    QComboBox *category = comboBox(page, Field::Category);
    category->setCurrentIndex(category->findText(QStringLiteral("Vehicle")));
    QCOMPARE(document.model()->basicField(Field::Category), QStringLiteral("Vehicle"));
    QCOMPARE(document.model()->componentId(), QStringLiteral("RTC:VenderName:Vehicle:ModuleName:1.0.0"));

    document.undoStack()->undo();
    document.undoStack()->undo();
    QCOMPARE(activity->currentText(), QStringLiteral("PERIODIC"));
    QCOMPARE(category->currentText(), QStringLiteral("Category"));
}

void TestAppViews::typingIntoEditableComboKeepsTyping()
{
    RtcDocument document(Profile::RtcProfile::createDefault());
    BasicPage page(document.model(), document.undoStack());
    page.show();
    QVERIFY(QTest::qWaitForWindowActive(&page));
    QComboBox *category = comboBox(page, Field::Category);
    QLineEdit *edit = category->lineEdit();
    QVERIFY(edit);
    edit->setFocus();
    QTRY_VERIFY(edit->hasFocus()); // the completer works on the focused field only
    edit->selectAll();
    // "M" and "My" are prefixes the preset list may complete inline; typing goes on regardless.
    QTest::keyClicks(edit, QStringLiteral("MyCat"));
    QCOMPARE(edit->text(), QStringLiteral("MyCat"));
    QCOMPARE(document.model()->basicField(Field::Category), QStringLiteral("MyCat"));
    QCOMPARE(document.undoStack()->count(), 1);

    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("Vehicle"));
    QCOMPARE(document.model()->basicField(Field::Category), QStringLiteral("Vehicle"));
    QCOMPARE(category->currentText(), QStringLiteral("Vehicle"));
    QCOMPARE(document.undoStack()->count(), 1); // both typings edit the same field: one step
}

void TestAppViews::unknownEnumValueIsShownNotReplaced()
{
    Profile::RtcProfile profile = Profile::RtcProfile::createDefault();
    profile.basicInfo.componentType = QStringLiteral("static");
    RtcDocument document(profile);
    BasicPage page(document.model(), document.undoStack());
    QCOMPARE(comboBox(page, Field::ComponentType)->currentText(), QStringLiteral("static"));
    QVERIFY(page.problem(Field::ComponentType).contains(QStringLiteral("STATIC")));
    QCOMPARE(document.undoStack()->count(), 0);
    QCOMPARE(document.model()->basicField(Field::ComponentType), QStringLiteral("static"));
}

void TestAppViews::clearingOptionalFieldRemovesIt()
{
    Profile::RtcProfile profile = Profile::RtcProfile::createDefault();
    profile.basicInfo.executionRate.reset();
    RtcDocument document(profile);
    BasicPage page(document.model(), document.undoStack());
    QLineEdit *rate = lineEdit(page, Field::ExecutionRate);
    QCOMPARE(rate->text(), QString());
    QTest::keyClicks(rate, QStringLiteral("5"));
    QCOMPARE(document.model()->basicField(Field::ExecutionRate), QStringLiteral("5"));
    QTest::keyClick(rate, Qt::Key_Backspace);
    QCOMPARE(document.model()->basicField(Field::ExecutionRate), std::nullopt);
    QCOMPARE(document.undoStack()->count(), 0);
}

void TestAppViews::systemInfoEditsTheId()
{
    RtsDocument document(Profile::RtsProfile::createNew(
        QStringLiteral("Vendor"), QStringLiteral("Demo"), QStringLiteral("1.0")));
    SystemInfoForm form(&document);
    auto *vendor = qobject_cast<QLineEdit *>(form.editor(SystemField::Vendor));
    auto *name = qobject_cast<QLineEdit *>(form.editor(SystemField::Name));
    QVERIFY(vendor && name);
    QCOMPARE(vendor->text(), QStringLiteral("Vendor"));
    QCOMPARE(name->text(), QStringLiteral("Demo"));

    vendor->selectAll();
    QTest::keyClicks(vendor, QStringLiteral("AIST"));
    QCOMPARE(document.systemId(), QStringLiteral("RTSystem:AIST:Demo:1.0"));
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QCOMPARE(vendor->text(), QStringLiteral("Vendor"));
    QCOMPARE(document.systemId(), QStringLiteral("RTSystem:Vendor:Demo:1.0"));
}

void TestAppViews::systemInfoRefusesColonAndMarksEmpty()
{
    RtsDocument document(Profile::RtsProfile::createNew(
        QStringLiteral("Vendor"), QStringLiteral("Demo"), QStringLiteral("1.0")));
    SystemInfoForm form(&document);
    auto *version = qobject_cast<QLineEdit *>(form.editor(SystemField::Version));
    QCOMPARE(form.problem(SystemField::Version), QString());
    version->clear();
    QTest::keyClicks(version, QStringLiteral("1:2")); // ':' would split the id: refused
    QCOMPARE(document.systemField(SystemField::Version), QStringLiteral("12"));
    QCOMPARE(document.systemId(), QStringLiteral("RTSystem:Vendor:Demo:12"));
    QCOMPARE(form.problem(SystemField::Version), QString());
    version->selectAll();
    QTest::keyClick(version, Qt::Key_Delete);
    QCOMPARE(document.systemField(SystemField::Version), QString());
    QVERIFY(!form.problem(SystemField::Version).isEmpty());
    // The other parts survive an empty one.
    QCOMPARE(document.systemField(SystemField::Name), QStringLiteral("Demo"));
    QTest::keyClicks(version, QStringLiteral("3"));
    QCOMPARE(form.problem(SystemField::Version), QString());
}

void TestAppViews::systemInfoAbstractIsUndoable()
{
    RtsDocument document(Profile::RtsProfile::createNew(
        QStringLiteral("Vendor"), QStringLiteral("Demo"), QStringLiteral("1.0")));
    SystemInfoForm form(&document);
    auto *abstract = qobject_cast<QPlainTextEdit *>(form.editor(SystemField::Abstract));
    QVERIFY(abstract);
    QVERIFY(!document.abstract());
    QTest::keyClicks(abstract, QStringLiteral("Two robots"));
    QCOMPARE(document.abstract(), QStringLiteral("Two robots"));
    QCOMPARE(document.undoStack()->count(), 1);
    document.undoStack()->undo();
    QVERIFY(!document.abstract());
    QCOMPARE(abstract->toPlainText(), QString());
}

void TestAppViews::fieldRules_data()
{
    QTest::addColumn<QString>("rule");
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("ok");
    QTest::newRow("name ok") << "name"
                             << "Abc_09-:" << true;
    QTest::newRow("name empty") << "name"
                                << "" << false;
    QTest::newRow("name slash") << "name"
                                << "a/b" << false;
    QTest::newRow("integer absent") << "integer"
                                    << "" << true;
    QTest::newRow("integer zero") << "integer"
                                  << "0" << true;
    QTest::newRow("integer negative") << "integer"
                                      << "-3" << false;
    QTest::newRow("integer fraction") << "integer"
                                      << "1.5" << false;
    QTest::newRow("number ok") << "number"
                               << "1000.0" << true;
    QTest::newRow("number negative") << "number"
                                     << "-0.1" << false;
    QTest::newRow("number nan") << "number"
                                << "nan" << false;
    QTest::newRow("required blank") << "required"
                                    << "  " << false;
    QTest::newRow("id part ok") << "idpart"
                                << "jp.go.aist" << true;
    QTest::newRow("id part colon") << "idpart"
                                   << "a:b" << false;
}

void TestAppViews::fieldRules()
{
    QFETCH(QString, rule);
    QFETCH(QString, text);
    QFETCH(bool, ok);
    QString problem;
    if (rule == QLatin1String("name"))
        problem = FieldRules::componentNameProblem(text);
    else if (rule == QLatin1String("integer"))
        problem = FieldRules::nonNegativeIntegerProblem(text);
    else if (rule == QLatin1String("number"))
        problem = FieldRules::nonNegativeNumberProblem(text);
    else if (rule == QLatin1String("required"))
        problem = FieldRules::requiredProblem(text);
    else
        problem = FieldRules::systemIdPartProblem(text);
    QCOMPARE(problem.isEmpty(), ok);
}

QTEST_MAIN(TestAppViews)
#include "tst_appviews.moc"
