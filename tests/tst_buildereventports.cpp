// SPDX-License-Identifier: MIT
// EventPorts and their FSM events in the Builder's Data Ports page, driven like a user: adding an
// EventPort, filling its events table through the view's editors, problems marked, undo/redo,
// the preview drawing it, and RTC.xml keeping every event.
#include "componenteditor.h"
#include "componentpreview.h"
#include "dataportspage.h"
#include "eventtablemodel.h"
#include "itemtablemodel.h"
#include "listeditor.h"
#include "rtcxml.h"
#include "typecatalog.h"

#include <QAbstractItemModelTester>
#include <QFile>
#include <QGroupBox>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QTabWidget>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace Builder;

namespace {

Profile::RtcProfile load(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("missing fixture %s", qPrintable(path));
    Profile::Diagnostics diagnostics;
    return *Profile::readRtcXml(file.readAll(), file.fileName(), &diagnostics);
}

Profile::RtcProfile fixture()
{
    return load(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builder/component.xml"));
}

struct Editor
{
    explicit Editor(const Profile::RtcProfile &profile = fixture())
        : model(profile)
    {
        editor.resize(1300, 850);
        editor.show();
        page = qobject_cast<DataPortsPage *>(editor.page(QStringLiteral("Data Ports")));
        editor.pages()->setCurrentWidget(page);
    }

    ComponentModel model;
    QUndoStack stack;
    TypeCatalog types {RTSTUDIO_IDL_DIR};
    ComponentEditor editor {&model, &stack, &types};
    DataPortsPage *page = nullptr;
};

/// Edits a cell through the view's own editor: start editing, type, press Enter.
void typeIntoCell(QTableView *view, int row, int column, const QString &text)
{
    const QModelIndex index = view->model()->index(row, column);
    view->scrollTo(index);
    view->setCurrentIndex(index);
    view->edit(index);
    // The editors of earlier cells are deleted later: take the one over this cell.
    QLineEdit *editor = nullptr;
    for (QLineEdit *line : view->viewport()->findChildren<QLineEdit *>()) {
        if (line->isVisible() && line->geometry().intersects(view->visualRect(index)))
            editor = line;
    }
    QVERIFY(editor);
    editor->selectAll();
    QTest::keyClicks(editor, text);
    const QPointer<QLineEdit> open(editor);
    QTest::keyClick(editor, Qt::Key_Return);
    // The delegate commits and closes the editor from the event loop.
    QTRY_VERIFY(!open || !open->isVisible());
}

const Profile::RtcDataPort *port(const ComponentModel &model, const QString &name)
{
    return model.profile().dataPort(name);
}

} // namespace

class TestBuilderEventPorts : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void addEventPortAndFillEvents();
    void eventProblemsAreMarked();
    void previewDrawsEventPorts();
    void eventTableFollowsPortMoves();
    void fsmFileRoundTrips();
    void tableModelIsConsistent();

private:
    QTemporaryDir m_settingsDir;
};

void TestBuilderEventPorts::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTests"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_buildereventports"));
    TypeCatalog::setUserDirectories({});
}

void TestBuilderEventPorts::addEventPortAndFillEvents()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    auto *box = e.page->findChild<QGroupBox *>(QStringLiteral("eventsBox"));
    QVERIFY(!box->isEnabled()); // no EventPort selected yet
    QTest::mouseClick(e.page->eventPorts()->findChild<QPushButton *>(QStringLiteral("add")),
                      Qt::LeftButton);
    const Profile::RtcDataPort *added = port(e.model, QStringLiteral("event"));
    QVERIFY(added);
    QCOMPARE(added->portType, QStringLiteral("EventPort"));
    QCOMPARE(added->type, QStringLiteral("Any"));
    QCOMPARE(e.page->eventPorts()->table()->rowCount(), 1);
    QCOMPARE(e.page->inPorts()->table()->rowCount(), 2); // the other tables stay as they were
    QVERIFY(box->isEnabled());

    QTest::mouseClick(box->findChild<QPushButton *>(QStringLiteral("addEvent")), Qt::LeftButton);
    QCOMPARE(e.page->eventTable()->rowCount(), 1);
    QTableView *events = e.page->events();
    typeIntoCell(events, 0, EventTableModel::Name, QStringLiteral("start"));
    typeIntoCell(events, 0, EventTableModel::DataType, QStringLiteral("RTC::TimedLong"));
    typeIntoCell(events, 0, EventTableModel::Source, QStringLiteral("Idle"));
    typeIntoCell(events, 0, EventTableModel::Target, QStringLiteral("Running"));
    typeIntoCell(events, 0, EventTableModel::Description, QStringLiteral("Starts the work"));
    const Profile::RtcEvent event = port(e.model, QStringLiteral("event"))->events.value(0);
    QCOMPARE(event.name, QStringLiteral("start"));
    QCOMPARE(event.type, QStringLiteral("RTC::TimedLong"));
    QCOMPARE(event.source, QStringLiteral("Idle"));
    QCOMPARE(event.target, QStringLiteral("Running"));
    QVERIFY(event.doc);
    QCOMPARE(event.doc->description, QStringLiteral("Starts the work"));
    QCOMPARE(e.stack.count(), 7);
    QCOMPARE(e.stack.undoText(), QStringLiteral("Change event start"));

    // The saved RTC.xml carries the event, and reads back the same.
    const QByteArray xml = Profile::writeRtcXml(e.model.profile());
    QVERIFY(xml.contains("rtc:portType=\"EventPort\""));
    QVERIFY(xml.contains("rtc:source=\"Idle\""));
    Profile::Diagnostics diagnostics;
    const auto reread = Profile::readRtcXml(xml, QStringLiteral("RTC.xml"), &diagnostics);
    QVERIFY(reread);
    QVERIFY(*reread == e.model.profile());

    const Profile::RtcProfile filled = e.model.profile();
    while (e.stack.canUndo())
        e.stack.undo();
    QVERIFY(e.model.profile() == fixture());
    QCOMPARE(e.page->eventPorts()->table()->rowCount(), 0);
    while (e.stack.canRedo())
        e.stack.redo();
    QVERIFY(e.model.profile() == filled);
    QCOMPARE(e.page->eventPorts()->table()->rowCount(), 1);
}

void TestBuilderEventPorts::eventProblemsAreMarked()
{
    Editor e;
    QVERIFY(QTest::qWaitForWindowExposed(&e.editor));
    e.page->eventPorts()->addItem();
    EventTableModel *table = e.page->eventTable();
    QVERIFY(table->addEvent());
    QVERIFY(table->addEvent());
    QCOMPARE(port(e.model, QStringLiteral("event"))->events.value(1).name,
             QStringLiteral("event1"));
    QCOMPARE(table->problem(0, EventTableModel::Source),
             QStringLiteral("An event needs the state it leaves."));
    QVERIFY(!table->index(0, EventTableModel::Target).data(EventTableModel::ProblemRole).isNull());
    QVERIFY(table->setData(table->index(1, EventTableModel::Name), QStringLiteral("event")));
    QCOMPARE(table->problem(1, EventTableModel::Name),
             QStringLiteral("The event name 'event' is already used by event #1."));
    QCOMPARE(table->index(1, 0).data(Qt::ToolTipRole).toString(), table->problem(1, 0));
    QVERIFY(table->setData(table->index(1, EventTableModel::Name), QStringLiteral("stop")));
    QCOMPARE(table->problem(1, EventTableModel::Name), QString());
    // Removing through the button takes the current row.
    e.page->events()->setCurrentIndex(table->index(0, 0));
    QTest::mouseClick(e.page->findChild<QPushButton *>(QStringLiteral("removeEvent")),
                      Qt::LeftButton);
    QCOMPARE(table->rowCount(), 1);
    QCOMPARE(port(e.model, QStringLiteral("event"))->events.value(0).name, QStringLiteral("stop"));
    QCOMPARE(e.stack.undoText(), QStringLiteral("Remove event event from event"));
}

void TestBuilderEventPorts::previewDrawsEventPorts()
{
    Editor e;
    e.page->eventPorts()->addItem();
    e.page->eventTable()->addEvent();
    ComponentPreview *preview = e.editor.preview();
    preview->resize(420, 320);
    ComponentPreview::Port event;
    for (const ComponentPreview::Port &p : preview->ports()) {
        if (p.name == QLatin1String("event"))
            event = p;
    }
    QCOMPARE(event.kind, ComponentPreview::Port::Event);
    QCOMPARE(event.type, QStringLiteral("event"));
    QCOMPARE(event.side, QStringLiteral("LEFT"));
    QVERIFY(event.marker.right() <= preview->box().left() + 0.5);
    // The diamond is painted in its own colour at the marker.
    const QImage image = preview->grab().toImage();
    const QPoint centre = event.marker.center().toPoint();
    QCOMPARE(image.pixelColor(centre), QColor(196, 160, 230));

    // Transitions that share an event show it once.
    EventTableModel *table = e.page->eventTable();
    QVERIFY(table->addEvent());
    QVERIFY(table->setData(table->index(1, EventTableModel::Name), table->index(0, EventTableModel::Name).data()));
    for (const ComponentPreview::Port &p : preview->ports()) {
        if (p.name == QLatin1String("event"))
            QCOMPARE(p.type, table->index(0, EventTableModel::Name).data().toString());
    }
}

void TestBuilderEventPorts::eventTableFollowsPortMoves()
{
    Editor e;
    e.page->eventPorts()->addItem();
    EventTableModel *table = e.page->eventTable();
    const int index = e.model.indexOf(Part::DataPort, QStringLiteral("event"));
    QCOMPARE(table->portIndex(), index);
    Profile::RtcDataPort in;
    in.name = QStringLiteral("first");
    in.portType = QStringLiteral("DataInPort");
    e.model.insertItem(Part::DataPort, 0, in);
    QCOMPARE(table->portIndex(), index + 1);
    QVERIFY(table->addEvent());
    QCOMPARE(port(e.model, QStringLiteral("event"))->events.size(), 1);
    e.model.removeItem(Part::DataPort, e.model.indexOf(Part::DataPort, QStringLiteral("event")));
    QCOMPARE(table->portIndex(), -1);
    QCOMPARE(table->rowCount(), 0);
    QVERIFY(!table->addEvent());
}

void TestBuilderEventPorts::fsmFileRoundTrips()
{
    // A file written by OpenRTP's RTC Builder: part of the shared conformance corpus, when it is there.
    const QString file = RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/rtc/rtcb_fsm_eventName.xml");
    if (!QFile::exists(file))
        QSKIP("no conformance corpus beside the checkout (../shared/conformance)");
    const Profile::RtcProfile fsm = load(file);
    Editor e(fsm);
    QCOMPARE(e.page->eventPorts()->table()->rowCount(), 1);
    QCOMPARE(e.page->eventPorts()->table()->index(0, 0).data().toString(),
             QStringLiteral("FSMEventPort"));
    e.page->eventPorts()->selectItem(
        e.model.indexOf(Part::DataPort, QStringLiteral("FSMEventPort")));
    EventTableModel *table = e.page->eventTable();
    QCOMPARE(table->rowCount(), 2);
    QCOMPARE(table->index(1, EventTableModel::Name).data().toString(),
             QStringLiteral("Event02_Final"));
    QCOMPARE(table->index(1, EventTableModel::Target).data().toString(),
             QStringLiteral("FinalState"));
    QCOMPARE(table->problem(0, EventTableModel::Name), QString());
    // Editing and undoing leaves the file's content exactly as it was.
    QVERIFY(table->setData(table->index(0, EventTableModel::Condition), QStringLiteral("x > 0")));
    QCOMPARE(port(e.model, QStringLiteral("FSMEventPort"))->events.at(0).condition,
             QStringLiteral("x > 0"));
    e.stack.undo();
    QVERIFY(e.model.profile() == fsm);
    Profile::Diagnostics diagnostics;
    const auto reread
        = Profile::readRtcXml(Profile::writeRtcXml(e.model.profile()), QString(), &diagnostics);
    QVERIFY(reread && *reread == fsm);
}

void TestBuilderEventPorts::tableModelIsConsistent()
{
    Editor e;
    EventTableModel *table = e.page->eventTable();
    QAbstractItemModelTester tester(table, QAbstractItemModelTester::FailureReportingMode::QtTest);
    e.page->eventPorts()->addItem();
    table->addEvent();
    table->addEvent();
    table->setData(table->index(0, EventTableModel::Source), QStringLiteral("A"));
    e.stack.undo();
    e.stack.undo();
    QCOMPARE(table->rowCount(), 1);
    e.model.setProfile(fixture());
    QCOMPARE(table->rowCount(), 0);
    QCOMPARE(table->portIndex(), -1);
}

QTEST_MAIN(TestBuilderEventPorts)
#include "tst_buildereventports.moc"
