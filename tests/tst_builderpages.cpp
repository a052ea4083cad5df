// SPDX-License-Identifier: MIT
// The Builder's editor driven like a user: typing a port name updates the preview, problems are
// marked inline with their reason, undo reaches across pages, the RTC.xml page applies or refuses,
// Generate is refused while errors remain.
#include "activitypage.h"
#include "basicpage.h"
#include "componenteditor.h"
#include "componentpreview.h"
#include "configurationpage.h"
#include "dataportspage.h"
#include "documentationpage.h"
#include "idlsettingsdialog.h"
#include "itemform.h"
#include "itemtablemodel.h"
#include "languagepage.h"
#include "listeditor.h"
#include "rtcxml.h"
#include "rtcxmlpage.h"
#include "serviceportspage.h"
#include "serviceporttreemodel.h"
#include "tst_buildersupport.h"
#include "typecatalog.h"

#include <QComboBox>
#include <QLabel>
#include <QCompleter>
#include <QFile>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QToolTip>
#include <QTreeView>
#include <QUndoStack>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace Builder;

namespace {

using BuilderTest::fixture;

/// An editor over the fixture with its own model, stack and IDL catalog.
struct Editor
{
    ComponentModel model {fixture()};
    QUndoStack stack;
    TypeCatalog types {RTSTUDIO_IDL_DIR};
    ComponentEditor editor {&model, &stack, &types};

    template<typename Page> Page *page(const char *title)
    {
        auto *page = qobject_cast<Page *>(editor.page(QString::fromLatin1(title)));
        editor.pages()->setCurrentWidget(page);
        return page;
    }
};

QStringList previewNames(const ComponentPreview *preview)
{
    QStringList names;
    for (const ComponentPreview::Port &port : preview->ports())
        names << port.name;
    return names;
}

/// Clicks a row of a table view as a user does.
void clickRow(QTableView *view, int row)
{
    const QRect cell = view->visualRect(view->model()->index(row, 0));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, cell.center());
}

} // namespace

class TestBuilderPages : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void editorHasEveryPage();
    void typingAPortNameUpdatesThePreview();
    void duplicatePortNameIsMarkedWithReason();
    void previewPutsPortsOnTheirSides();
    void previewShortensLabelsThatDoNotFit();
    void addingAPortSelectsIt();
    void formKeepsItsPortWhenOthersComeAndGo();
    void undoReachesAcrossPages();
    void activityCheckAndDescription();
    void configurationConstraintErrorIsShownNotStored();
    void servicePortsAddInterfaceAndEditType();
    void documentationAndLanguageAreUndoable();
    void rtcXmlErrorShowsLineAndLeavesModel();
    void rtcXmlValidChangeIsOneUndoStep();
    void rtcXmlFollowsTheModelUntilEdited();
    void generateIsRefusedWhileErrorsRemain();
    void typeListsComeFromIdl();
    void idlSettingsStoreUserFolders();
    void idlScanShowsProgressAndCancels();

private:
    QTemporaryDir m_settingsDir;
};

void TestBuilderPages::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    BuilderTest::isolateSettings(m_settingsDir, QStringLiteral("tst_builderpages"));
}

void TestBuilderPages::editorHasEveryPage()
{
    Editor e;
    QStringList titles;
    for (int i = 0; i < e.editor.pages()->count(); ++i)
        titles << e.editor.pages()->tabText(i);
    QCOMPARE(titles,
             QStringList({"Basic", "Activity", "Data Ports", "Service Ports", "Configuration",
                          "Documentation", "Language/Environment", "RTC.xml"}));
    QCOMPARE(e.stack.count(), 0); // showing pushes nothing
    QVERIFY(e.model.profile() == fixture());
}

void TestBuilderPages::typingAPortNameUpdatesThePreview()
{
    Editor e;
    e.editor.resize(1200, 700);
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *page = e.page<DataPortsPage>("Data Ports");
    clickRow(page->inPorts()->view(), 1); // "speed"
    QCOMPARE(page->form()->currentIndex(), 2);
    auto *name = qobject_cast<QLineEdit *>(page->form()->editor(QStringLiteral("name")));
    QVERIFY(name && name->isEnabled());
    QCOMPARE(name->text(), QStringLiteral("speed"));
    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("vel"));
    QVERIFY(previewNames(e.editor.preview()).contains(QStringLiteral("vel")));
    QTest::keyClicks(name, QStringLiteral("ocity"));
    QVERIFY(previewNames(e.editor.preview()).contains(QStringLiteral("velocity")));
    QVERIFY(!previewNames(e.editor.preview()).contains(QStringLiteral("speed")));
    QCOMPARE(e.stack.count(), 1); // typing a name is one step
    QCOMPARE(page->inPorts()->table()->index(1, 0).data().toString(), QStringLiteral("velocity"));
    e.stack.undo();
    QCOMPARE(name->text(), QStringLiteral("speed"));
    QVERIFY(previewNames(e.editor.preview()).contains(QStringLiteral("speed")));
}

void TestBuilderPages::duplicatePortNameIsMarkedWithReason()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *page = e.page<DataPortsPage>("Data Ports");
    clickRow(page->outPorts()->view(), 0); // "ranges"
    auto *name = qobject_cast<QLineEdit *>(page->form()->editor(QStringLiteral("name")));
    QCOMPARE(page->form()->problem(QStringLiteral("name")), QString());
    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("trigger"));
    QCOMPARE(page->form()->problem(QStringLiteral("name")),
             QStringLiteral("The port name 'trigger' is already used by data port #1."));
    QCOMPARE(name->toolTip(), page->form()->problem(QStringLiteral("name")));
    QCOMPARE(e.model.profile().dataPorts.at(1).name, QStringLiteral("trigger")); // kept as typed
    // The table marks the other port too.
    QVERIFY(!page->inPorts()->table()->index(0, 0).data(ItemTableModel::ProblemRole).isNull());
    QTest::keyClick(name, Qt::Key_2);
    QCOMPARE(page->form()->problem(QStringLiteral("name")), QString());
    QVERIFY(page->inPorts()->table()->index(0, 0).data(ItemTableModel::ProblemRole).isNull());
}

void TestBuilderPages::previewPutsPortsOnTheirSides()
{
    Editor e;
    ComponentPreview *preview = e.editor.preview();
    preview->resize(400, 300);
    const QRectF box = preview->box();
    QCOMPARE(preview->title(), QStringLiteral("Scanner"));
    QHash<QString, ComponentPreview::Port> ports;
    for (const auto &port : preview->ports())
        ports.insert(port.name, port);
    QCOMPARE(ports.size(), 4);
    QVERIFY(ports.value(QStringLiteral("trigger")).marker.right() <= box.left() + 0.5);
    QVERIFY(ports.value(QStringLiteral("ranges")).marker.left() >= box.right() - 0.5);
    QVERIFY(ports.value(QStringLiteral("speed")).marker.bottom() <= box.top() + 0.5);
    QVERIFY(ports.value(QStringLiteral("control")).marker.top() >= box.bottom() - 0.5);
    QCOMPARE(ports.value(QStringLiteral("control")).kind, ComponentPreview::Port::Service);
    QCOMPARE(ports.value(QStringLiteral("ranges")).kind, ComponentPreview::Port::Out);
    // Changing the position moves the port at once.
    auto port = std::get<Profile::RtcDataPort>(e.model.item(Part::DataPort, 0));
    port.position = QStringLiteral("BOTTOM");
    e.model.setItem(Part::DataPort, 0, port);
    for (const auto &p : preview->ports()) {
        if (p.name == QLatin1String("trigger"))
            QVERIFY(p.marker.top() >= preview->box().bottom() - 0.5);
    }
    QImage image = preview->grab().toImage();
    QVERIFY(!image.isNull());
}

void TestBuilderPages::previewShortensLabelsThatDoNotFit()
{
    Editor e;
    const QString longName = QStringLiteral("rangesOfTheLaserScannerInMillimetres");
    auto port = std::get<Profile::RtcDataPort>(e.model.item(Part::DataPort, 1));
    QCOMPARE(port.name, QStringLiteral("ranges"));
    port.name = longName;
    e.model.setItem(Part::DataPort, 1, port);
    // A preview of its own, on the editor's model, as a window whose width the test sets.
    ComponentPreview own(&e.model);
    ComponentPreview *preview = &own;
    preview->show();
    QVERIFY(QTest::qWaitForWindowExposed(preview));
    const auto labelsInside = [preview] {
        for (const ComponentPreview::Port &p : preview->ports()) {
            const QRectF inside = preview->rect();
            if (inside.united(p.nameRect) != inside || inside.united(p.typeRect) != inside)
                return false;
        }
        return true;
    };
    const auto shown = [preview](const QString &name) {
        for (const ComponentPreview::Port &p : preview->ports()) {
            if (p.name == name)
                return p;
        }
        return ComponentPreview::Port();
    };

    // Wide enough: everything as it is.
    preview->resize(900, 300);
    QVERIFY(labelsInside());
    QCOMPARE(shown(longName).shownName, longName);
    QCOMPARE(shown(longName).shownType, shown(longName).type);

    // Too narrow: the long name and its type end in "…" at the widget's edge instead of beyond it.
    preview->resize(300, 300);
    QVERIFY(labelsInside());
    const ComponentPreview::Port cut = shown(longName);
    QVERIFY2(cut.shownName.endsWith(QChar(0x2026)) && cut.shownName.size() < longName.size(),
             qPrintable(cut.shownName));
    QVERIFY2(cut.shownType.endsWith(QChar(0x2026)), qPrintable(cut.shownType));
    QCOMPARE(shown(QStringLiteral("trigger")).shownName, QStringLiteral("trigger"));

    // Its tooltip gives both in full.
    QHelpEvent help(QEvent::ToolTip, cut.nameRect.center().toPoint(),
                    preview->mapToGlobal(cut.nameRect.center().toPoint()));
    QCoreApplication::sendEvent(preview, &help);
    QCOMPARE(QToolTip::text(), longName + QLatin1Char('\n') + cut.type);
}

void TestBuilderPages::addingAPortSelectsIt()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *page = e.page<DataPortsPage>("Data Ports");
    auto *add = page->outPorts()->findChild<QPushButton *>(QStringLiteral("add"));
    QTest::mouseClick(add, Qt::LeftButton);
    QCOMPARE(page->outPorts()->table()->rowCount(), 2);
    QCOMPARE(page->form()->currentIndex(), 2); // after "ranges", before "speed"
    QCOMPARE(e.model.itemName(Part::DataPort, 2), QStringLiteral("out"));
    QCOMPARE(std::get<Profile::RtcDataPort>(e.model.item(Part::DataPort, 2)).position,
             QStringLiteral("RIGHT"));
    QTest::mouseClick(add, Qt::LeftButton);
    QCOMPARE(e.model.itemName(Part::DataPort, 3), QStringLiteral("out1"));
    auto *remove = page->outPorts()->findChild<QPushButton *>(QStringLiteral("remove"));
    QTest::mouseClick(remove, Qt::LeftButton);
    QCOMPARE(page->outPorts()->table()->rowCount(), 2);
    QCOMPARE(e.stack.count(), 3);
    QCOMPARE(e.stack.undoText(), QStringLiteral("Remove data port out1"));
}

void TestBuilderPages::formKeepsItsPortWhenOthersComeAndGo()
{
    Editor e;
    auto *page = e.page<DataPortsPage>("Data Ports");
    page->inPorts()->selectItem(2); // "speed"
    QCOMPARE(page->form()->currentIndex(), 2);
    auto *name = qobject_cast<QLineEdit *>(page->form()->editor(QStringLiteral("name")));
    Profile::RtcDataPort out;
    out.name = QStringLiteral("first");
    out.portType = QStringLiteral("DataOutPort");
    e.model.insertItem(Part::DataPort, 0, out); // not in this table
    QCOMPARE(page->form()->currentIndex(), 3);
    QCOMPARE(name->text(), QStringLiteral("speed"));
    Profile::RtcDataPort in = out;
    in.name = QStringLiteral("early");
    in.portType = QStringLiteral("DataInPort");
    e.model.insertItem(Part::DataPort, 0, in); // a row of this table, in front
    QCOMPARE(page->form()->currentIndex(), 4);
    QCOMPARE(page->inPorts()->currentItem(), 4);
    QCOMPARE(name->text(), QStringLiteral("speed"));
    e.model.moveItem(Part::DataPort, 4, 0);
    QCOMPARE(page->form()->currentIndex(), 0);
    QCOMPARE(page->inPorts()->currentItem(), 0);
    QCOMPARE(name->text(), QStringLiteral("speed"));
    // Removing it makes the table's next row current, and the form shows that one.
    e.model.removeItem(Part::DataPort, 0);
    QCOMPARE(page->inPorts()->currentItem(), 0);
    QCOMPARE(page->form()->currentIndex(), 0);
    QCOMPARE(name->text(), QStringLiteral("early"));
}

void TestBuilderPages::undoReachesAcrossPages()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *basic = e.page<BasicPage>("Basic");
    auto *name = qobject_cast<QLineEdit *>(basic->editor(BasicField::Name));
    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("Lidar"));
    auto *ports = e.page<DataPortsPage>("Data Ports");
    QTest::mouseClick(ports->inPorts()->findChild<QPushButton *>(QStringLiteral("add")),
                      Qt::LeftButton);
    auto *configuration = e.page<ConfigurationPage>("Configuration");
    clickRow(configuration->list()->view(), 0);
    auto *value
        = qobject_cast<QLineEdit *>(configuration->form()->editor(QStringLiteral("defaultValue")));
    value->selectAll();
    QTest::keyClicks(value, QStringLiteral("2.5"));
    QCOMPARE(e.stack.count(), 3);
    QCOMPARE(e.editor.preview()->title(), QStringLiteral("Lidar"));

    e.stack.undo();
    QCOMPARE(value->text(), QStringLiteral("1.0"));
    e.stack.undo();
    QCOMPARE(ports->inPorts()->table()->rowCount(), 2);
    e.stack.undo();
    QCOMPARE(name->text(), QStringLiteral("Scanner"));
    QVERIFY(e.model.profile() == fixture());
    e.stack.redo();
    e.stack.redo();
    e.stack.redo();
    QCOMPARE(value->text(), QStringLiteral("2.5"));
    QCOMPARE(ports->inPorts()->table()->rowCount(), 3);
    QCOMPARE(e.editor.preview()->title(), QStringLiteral("Lidar"));
}

void TestBuilderPages::activityCheckAndDescription()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *page = e.page<ActivityPage>("Activity");
    QTableView *view = page->view();
    const int row = 9; // onExecute
    QCOMPARE(view->model()->index(row, 0).data().toString(), QStringLiteral("onExecute"));
    page->selectRow(row);
    QLineEdit *description = page->docEditor(ActivityPage::DocField::Description);
    QCOMPARE(description->text(), QStringLiteral("Reads one scan"));
    description->selectAll();
    QTest::keyClicks(description, QStringLiteral("Scans"));
    QCOMPARE(e.model.action(Profile::RtcAction::OnExecute)->doc->description,
             QStringLiteral("Scans"));
    QCOMPARE(view->model()->index(row, 1).data().toString(), QStringLiteral("Scans"));
    // The check box of onExecute switches it off.
    const QRect cell = view->visualRect(view->model()->index(row, 0));
    const QPoint checkBox(cell.left() + view->style()->pixelMetric(QStyle::PM_IndicatorWidth) / 2
                              + 4,
                          cell.center().y());
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, checkBox);
    QTRY_VERIFY(!e.model.profile().actions.isImplemented(Profile::RtcAction::OnExecute));
    QCOMPARE(e.stack.count(), 2);
    e.stack.undo();
    e.stack.undo();
    QCOMPARE(description->text(), QStringLiteral("Reads one scan"));
    QVERIFY(e.model.profile() == fixture());
}

void TestBuilderPages::configurationConstraintErrorIsShownNotStored()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *page = e.page<ConfigurationPage>("Configuration");
    clickRow(page->list()->view(), 1); // "mode", radio with (fast,slow)
    auto *constraint
        = qobject_cast<QLineEdit *>(page->form()->editor(QStringLiteral("constraint")));
    QCOMPARE(constraint->text(), QStringLiteral("(fast,slow)"));
    constraint->selectAll();
    QTest::keyClicks(constraint, QStringLiteral("(fast,"));
    QVERIFY(page->form()->problem(QStringLiteral("constraint")).contains(QStringLiteral("column")));
    QCOMPARE(e.stack.count(), 0);
    QTest::keyClicks(constraint, QStringLiteral("slow,off)"));
    QCOMPARE(page->form()->problem(QStringLiteral("constraint")), QString());
    QCOMPARE(constraint->text(), QStringLiteral("(fast,slow,off)"));
    QCOMPARE(e.stack.count(), 1);
    // A range is no enumeration: the radio widget is marked.
    constraint->selectAll();
    QTest::keyClicks(constraint, QStringLiteral("x>0"));
    QVERIFY(
        page->form()->problem(QStringLiteral("widget")).contains(QStringLiteral("enumeration")));
}

void TestBuilderPages::servicePortsAddInterfaceAndEditType()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    e.types.reload();
    auto *page = e.page<ServicePortsPage>("Service Ports");
    page->select(0);
    page->addInterface();
    QCOMPARE(e.model.profile().servicePorts.at(0).interfaces.size(), 3);
    QCOMPARE(page->tree()->rowCount(page->tree()->index(0, 0)), 3);
    auto *name = qobject_cast<QLineEdit *>(page->interfaceForm()->editor(QStringLiteral("name")));
    QCOMPARE(name->text(), QStringLiteral("interface"));
    name->selectAll();
    QTest::keyClicks(name, QStringLiteral("service0"));
    QVERIFY(page->interfaceForm()
                ->problem(QStringLiteral("name"))
                .contains(QStringLiteral("already used")));
    QTest::keyClick(name, Qt::Key_9);
    QCOMPARE(page->interfaceForm()->problem(QStringLiteral("name")), QString());
    auto *type = qobject_cast<QComboBox *>(page->interfaceForm()->editor(QStringLiteral("type")));
    QVERIFY(type->findText(QStringLiteral("SimpleService::MyService")) >= 0);
    type->setCurrentIndex(type->findText(QStringLiteral("SimpleService::MyService")));
    QCOMPARE(e.model.profile().servicePorts.at(0).interfaces.at(2).type,
             QStringLiteral("SimpleService::MyService"));
    while (e.stack.canUndo())
        e.stack.undo();
    QVERIFY(e.model.profile() == fixture());
}

void TestBuilderPages::documentationAndLanguageAreUndoable()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *doc = e.page<DocumentationPage>("Documentation");
    QPlainTextEdit *license = doc->editor(DocumentationPage::Field::License);
    QCOMPARE(license->toPlainText(), QStringLiteral("MIT"));
    license->setFocus();
    license->selectAll();
    QTest::keyClicks(license, QStringLiteral("BSD"));
    QCOMPARE(e.model.profile().basicInfo.doc->license, QStringLiteral("BSD"));
    QCOMPARE(e.stack.count(), 1);

    auto *language = e.page<LanguagePage>("Language/Environment");
    auto *kind = qobject_cast<QComboBox *>(language->editor(LanguagePage::Field::Kind));
    QCOMPARE(kind->currentText(), QStringLiteral("C++"));
    kind->setCurrentIndex(kind->findText(QStringLiteral("Python")));
    QCOMPARE(e.model.profile().language->kind, QStringLiteral("Python"));
    auto *os = qobject_cast<QLineEdit *>(language->editor(LanguagePage::Field::Os));
    QCOMPARE(os->text(), QStringLiteral("Linux"));
    os->selectAll();
    QTest::keyClicks(os, QStringLiteral("Windows"));
    QCOMPARE(e.model.profile().language->targets.first().os, QStringLiteral("Windows"));
    QCOMPARE(e.stack.count(), 3);
    e.stack.undo();
    e.stack.undo();
    e.stack.undo();
    QCOMPARE(license->toPlainText(), QStringLiteral("MIT"));
    QCOMPARE(kind->currentText(), QStringLiteral("C++"));
    QCOMPARE(os->text(), QStringLiteral("Linux"));
    QVERIFY(e.model.profile() == fixture());
}

void TestBuilderPages::rtcXmlErrorShowsLineAndLeavesModel()
{
    Editor e;
    auto *page = e.page<RtcXmlPage>("RTC.xml");
    QString text = page->editor()->toPlainText();
    QVERIFY(text.contains(QStringLiteral("rtc:name=\"Scanner\"")));
    // Break the third line: an unclosed attribute value.
    QStringList lines = text.split(QLatin1Char('\n'));
    lines[2].replace(QStringLiteral("rtc:name=\"Scanner\""), QStringLiteral("rtc:name=\"Scanner"));
    page->editor()->setPlainText(lines.join(QLatin1Char('\n')));
    QVERIFY(page->isEdited());
    QVERIFY(!page->apply());
    QVERIFY(!page->problems().isEmpty());
    QVERIFY2(page->problems().first().startsWith(QStringLiteral("RTC.xml:3:")),
             qPrintable(page->problems().first()));
    QCOMPARE(page->editor()->textCursor().blockNumber(), 2); // the cursor went there
    QVERIFY(page->pendingChanges().isEmpty());
    QCOMPARE(e.stack.count(), 0);
    QVERIFY(e.model.profile() == fixture());
}

void TestBuilderPages::rtcXmlValidChangeIsOneUndoStep()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *page = e.page<RtcXmlPage>("RTC.xml");
    QString text = page->editor()->toPlainText();
    text.replace(QStringLiteral("rtc:name=\"speed\""), QStringLiteral("rtc:name=\"velocity\""));
    text.replace(QStringLiteral("rtc:vendor=\"AIST\""), QStringLiteral("rtc:vendor=\"Lab\""));
    page->editor()->setPlainText(text);
    QVERIFY(page->apply());
    QCOMPARE(page->pendingChanges(),
             QStringList({QStringLiteral("Basic: vendor 'AIST' → 'Lab'"),
                          QStringLiteral("Data port 'speed' removed"),
                          QStringLiteral("Data port 'velocity' added")}));
    QVERIFY(e.model.profile() == fixture()); // nothing taken before Confirm
    page->confirm();
    QCOMPARE(e.stack.count(), 1);
    QCOMPARE(e.model.itemName(Part::DataPort, 2), QStringLiteral("velocity"));
    QCOMPARE(e.model.profile().basicInfo.vendor, QStringLiteral("Lab"));
    QVERIFY(!page->isEdited());
    e.stack.undo();
    QVERIFY(e.model.profile() == fixture());
    QVERIFY(page->editor()->toPlainText().contains(QStringLiteral("rtc:name=\"speed\"")));
    e.stack.redo();
    QCOMPARE(e.model.itemName(Part::DataPort, 2), QStringLiteral("velocity"));

    // Unchanged text applies as "no changes" and pushes nothing.
    page->revert();
    QVERIFY(page->apply());
    QVERIFY(page->pendingChanges().isEmpty());
    QCOMPARE(e.stack.count(), 1);
}

void TestBuilderPages::rtcXmlFollowsTheModelUntilEdited()
{
    Editor e;
    e.editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *page = e.page<RtcXmlPage>("RTC.xml");
    e.model.setBasicField(BasicField::Description, QStringLiteral("Changed elsewhere"));
    QVERIFY(page->editor()->toPlainText().contains(QStringLiteral("Changed elsewhere")));
    page->editor()->appendPlainText(QStringLiteral("<!-- mine -->"));
    e.model.setBasicField(BasicField::Description, QStringLiteral("Again"));
    QVERIFY(page->editor()->toPlainText().contains(QStringLiteral("<!-- mine -->")));
    page->revert();
    QVERIFY(page->editor()->toPlainText().contains(QStringLiteral("Again")));
}

void TestBuilderPages::generateIsRefusedWhileErrorsRemain()
{
    Editor e;
    QSignalSpy requested(&e.editor, &ComponentEditor::generateRequested);
    QSignalSpy refused(&e.editor, &ComponentEditor::generateRefused);
    QSignalSpy restore(&e.editor, &ComponentEditor::codeRestoreRequested);
    QTest::mouseClick(e.editor.basicPage()->generateButton(), Qt::LeftButton);
    QCOMPARE(requested.count(), 1);
    QCOMPARE(e.editor.basicPage()->generationProblems(), QString());

    auto port = std::get<Profile::RtcDataPort>(e.model.item(Part::DataPort, 0));
    port.name = QStringLiteral("my port");
    e.model.setItem(Part::DataPort, 0, port);
    QTest::mouseClick(e.editor.basicPage()->generateButton(), Qt::LeftButton);
    QCOMPARE(requested.count(), 1);
    QCOMPARE(refused.count(), 1);
    QVERIFY(e.editor.basicPage()->generationProblems().contains(QStringLiteral("my port")));
    QTest::mouseClick(
        e.editor.basicPage()->findChild<QPushButton *>(QStringLiteral("codeRestoreButton")),
        Qt::LeftButton);
    QCOMPARE(restore.count(), 1);

    // An interface type no parsed IDL declares refuses generation too.
    port.name = QStringLiteral("trigger");
    e.model.setItem(Part::DataPort, 0, port);
    e.types.reload();
    QTest::mouseClick(e.editor.basicPage()->generateButton(), Qt::LeftButton);
    QCOMPARE(requested.count(), 2);
    auto service = std::get<Profile::RtcServicePort>(e.model.item(Part::ServicePort, 0));
    service.interfaces[0].type = QStringLiteral("Missing::Service");
    e.model.setItem(Part::ServicePort, 0, service);
    QTest::mouseClick(e.editor.basicPage()->generateButton(), Qt::LeftButton);
    QCOMPARE(requested.count(), 2);
    QCOMPARE(refused.count(), 2);
    QVERIFY(
        e.editor.basicPage()->generationProblems().contains(QStringLiteral("Missing::Service")));
}

void TestBuilderPages::typeListsComeFromIdl()
{
    TypeCatalog catalog(RTSTUDIO_IDL_DIR);
    QCOMPARE(catalog.dataTypes(), TypeCatalog::builtInDataTypes()); // before loading
    QSignalSpy changed(&catalog, &TypeCatalog::typesChanged);
    catalog.reload();
    QCOMPARE(changed.count(), 1);
    QVERIFY(catalog.dataTypes().contains(QStringLiteral("RTC::TimedLong")));
    QVERIFY(catalog.dataTypes().contains(QStringLiteral("RTC::TimedPose2D")));
    QVERIFY(catalog.interfaceTypes().contains(QStringLiteral("SimpleService::MyService")));
    // OpenRTM-aist's extension IDL, as OpenRTP offers it.
    QVERIFY(catalog.dataTypes().contains(QStringLiteral("Img::TimedCameraImage")));
    QVERIFY(catalog.dataTypes().contains(QStringLiteral("JARA_ARM::TimedJointPos")));
    QVERIFY(catalog.interfaceTypes().contains(QStringLiteral("Img::CameraCaptureService")));
    QVERIFY(catalog.interfaceTypes().contains(QStringLiteral("JARA_ARM::ManipulatorCommonInterface_Middle")));
    QVERIFY(catalog.fileOf(QStringLiteral("RTC::TimedLong"))
                .endsWith(QStringLiteral("BasicDataType.idl")));

    Editor e;
    e.types.reload();
    auto *page = e.page<DataPortsPage>("Data Ports");
    page->inPorts()->selectItem(0);
    auto *type = qobject_cast<QComboBox *>(page->form()->editor(QStringLiteral("type")));
    QVERIFY(type->findText(QStringLiteral("RTC::TimedPose2D")) >= 0);
    QVERIFY(type->findText(QStringLiteral("Img::TimedCameraImage")) >= 0);
    QCOMPARE(type->currentText(), QStringLiteral("RTC::TimedLong"));
    QCOMPARE(type->completer()->filterMode(), Qt::MatchContains);
}

void TestBuilderPages::idlSettingsStoreUserFolders()
{
    TypeCatalog catalog(RTSTUDIO_IDL_DIR);
    IdlSettingsDialog dialog(&catalog);
    const QString folder = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builder");
    dialog.addDirectory(folder);
    dialog.addDirectory(folder);
    QCOMPARE(dialog.directories(), QStringList({folder}));
    QSignalSpy changed(&catalog, &TypeCatalog::typesChanged);
    dialog.accept(); // reads the folders in the background
    QTRY_COMPARE(changed.count(), 1);
    QCOMPARE(TypeCatalog::userDirectories(), QStringList({folder}));
    QCOMPARE(catalog.directories(), QStringList({RTSTUDIO_IDL_DIR, folder}));
    TypeCatalog::setUserDirectories({});
}

void TestBuilderPages::idlScanShowsProgressAndCancels()
{
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    const auto write = [&folder](const QString &name, const QByteArray &text) {
        QFile file(folder.filePath(name));
        return file.open(QIODevice::WriteOnly) && file.write(text) == text.size();
    };
    QVERIFY(write(QStringLiteral("known.idl"), "struct Known { long x; };\n"));
    TypeCatalog::setUserDirectories({folder.path()});
    const auto forget = qScopeGuard([] { TypeCatalog::setUserDirectories({}); });
    Editor e;
    e.types.reload();
    QVERIFY(e.types.dataTypes().contains(QStringLiteral("Known")));

    // A file whose include waits on a pipe: the scan is under way until the test writes to it.
    const QString pipe = folder.filePath(QStringLiteral("waiting"));
    QVERIFY(mkfifo(QFile::encodeName(pipe).constData(), 0600) == 0);
    QVERIFY(write(QStringLiteral("waits.idl"), "#include \"" + pipe.toUtf8() + "\"\nstruct Waiting { long y; };\n"));
    auto *page = e.page<DataPortsPage>("Data Ports");
    auto *strip = page->findChild<QWidget *>(QStringLiteral("idlScan"));
    auto *label = page->findChild<QLabel *>(QStringLiteral("idlScanLabel"));
    auto *cancel = page->findChild<QPushButton *>(QStringLiteral("idlScanCancel"));
    QVERIFY(strip && label && cancel);
    QVERIFY(strip->isHidden());
    QSignalSpy finished(&e.types, &TypeCatalog::loadingFinished);
    QSignalSpy changed(&e.types, &TypeCatalog::typesChanged);
    auto *reload = page->findChild<QPushButton *>(QStringLiteral("reloadTypes"));
    QVERIFY(reload);
    reload->click();
    QVERIFY(e.types.isLoading());
    QTRY_VERIFY(!strip->isHidden());
    QTRY_VERIFY2(label->text().contains(QStringLiteral("waits.idl")), qPrintable(label->text()));

    // Cancel answers at once although the file is still being read, and keeps the types.
    cancel->click();
    QVERIFY(strip->isHidden());
    QVERIFY(!e.types.isLoading());
    QCOMPARE(finished.count(), 1);
    QCOMPARE(finished.first().first().toBool(), true);
    const int fd = ::open(QFile::encodeName(pipe).constData(), O_WRONLY);
    QVERIFY(fd >= 0);
    ::close(fd);
    QTest::qWait(0);
    QCOMPARE(changed.count(), 0);
    QVERIFY(e.types.dataTypes().contains(QStringLiteral("Known")));
    QVERIFY(!e.types.dataTypes().contains(QStringLiteral("Waiting")));

    // Without the pipe the next scan completes and brings the new type.
    QVERIFY(QFile::remove(pipe));
    QVERIFY(write(QStringLiteral("waits.idl"), "struct Waiting { long y; };\n"));
    reload->click();
    QTRY_COMPARE(changed.count(), 1);
    QCOMPARE(finished.count(), 2);
    QCOMPARE(finished.last().first().toBool(), false);
    QVERIFY(e.types.dataTypes().contains(QStringLiteral("Waiting")));
    QVERIFY(strip->isHidden());
}

QTEST_MAIN(TestBuilderPages)
#include "tst_builderpages.moc"
