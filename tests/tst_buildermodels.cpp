// SPDX-License-Identifier: MIT
// The Builder's item models (port, parameter, callback, service port and library tables) follow
// the editing model and push commands; checked with QAbstractItemModelTester. Also the rules
// behind the inline marks and the change list of the RTC.xml page.
#include "actiontablemodel.h"
#include "componentcommands.h"
#include "componentrules.h"
#include "configurationpage.h"
#include "constraintsyntax.h"
#include "itemcommands.h"
#include "itemtablemodel.h"
#include "librarytablemodel.h"
#include "profilechanges.h"
#include "rtcxml.h"
#include "serviceporttreemodel.h"

#include <QAbstractItemModelTester>
#include <QFile>
#include <QTest>
#include <QUndoStack>

using namespace Builder;
using Profile::RtcDataPort;

namespace {

Profile::RtcProfile fixture()
{
    QFile file(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builder/component.xml"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("missing fixture component.xml");
    Profile::Diagnostics diagnostics;
    return *Profile::readRtcXml(file.readAll(), file.fileName(), &diagnostics);
}

QList<ItemField> portColumns()
{
    return {
        textField<RtcDataPort>(QStringLiteral("name"), QStringLiteral("Name"), &RtcDataPort::name),
        textField<RtcDataPort>(QStringLiteral("type"), QStringLiteral("Type"), &RtcDataPort::type)};
}

ItemTableModel::Filter inPorts()
{
    return [](const PartItem &item) {
        return std::get<RtcDataPort>(item).kind() == Profile::RtcPortType::DataIn;
    };
}

QStringList column(const QAbstractItemModel &model, int column, int role = Qt::DisplayRole)
{
    QStringList values;
    for (int row = 0; row < model.rowCount(); ++row)
        values << model.index(row, column).data(role).toString();
    return values;
}

RtcDataPort port(const QString &name, const QString &portType)
{
    RtcDataPort p;
    p.name = name;
    p.portType = portType;
    p.type = QStringLiteral("RTC::TimedLong");
    p.position = QStringLiteral("LEFT");
    return p;
}

} // namespace

class TestBuilderModels : public QObject
{
    Q_OBJECT

private slots:
    void inPortTableShowsOnlyInPorts();
    void inPortTableFollowsInsertRemoveMoveAndReset();
    void changingThePortTypeMovesTheRow();
    void editingACellIsAnUndoStep();
    void duplicateNameIsMarkedWithReason();
    void configurationConstraintAndWidget();
    void actionTableChecksCallbacks();
    void servicePortTreeFollowsInterfaces();
    void libraryTable();
    void itemRules_data();
    void itemRules();
    void compositeCategoryHasNoPorts();
    void describeChangesNamesEachChange();
};

void TestBuilderModels::inPortTableShowsOnlyInPorts()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ItemTableModel table(&model, &stack, Part::DataPort, portColumns(), inPorts());
    QAbstractItemModelTester tester(&table, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(column(table, 0), QStringList({QStringLiteral("trigger"), QStringLiteral("speed")}));
    QCOMPARE(table.itemIndex(1), 2);
    QCOMPARE(table.rowOf(1), -1); // "ranges" is an OutPort
    QCOMPARE(table.headerData(1, Qt::Horizontal, Qt::DisplayRole).toString(),
             QStringLiteral("Type"));
}

void TestBuilderModels::inPortTableFollowsInsertRemoveMoveAndReset()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ItemTableModel table(&model, &stack, Part::DataPort, portColumns(), inPorts());
    QAbstractItemModelTester tester(&table, QAbstractItemModelTester::FailureReportingMode::QtTest);
    stack.push(new InsertItemCommand(&model, Part::DataPort, 2,
                                     port(QStringLiteral("in2"), QStringLiteral("DataInPort"))));
    QCOMPARE(
        column(table, 0),
        QStringList({QStringLiteral("trigger"), QStringLiteral("in2"), QStringLiteral("speed")}));
    stack.push(new InsertItemCommand(&model, Part::DataPort, 0,
                                     port(QStringLiteral("out2"), QStringLiteral("DataOutPort"))));
    QCOMPARE(table.rowCount(), 3);
    QCOMPARE(table.itemIndex(0), 1); // positions shifted by the OutPort in front
    stack.push(new MoveItemCommand(&model, Part::DataPort, 4, 1));
    QCOMPARE(
        column(table, 0),
        QStringList({QStringLiteral("speed"), QStringLiteral("trigger"), QStringLiteral("in2")}));
    stack.push(new RemoveItemCommand(&model, Part::DataPort, 2));
    QCOMPARE(column(table, 0), QStringList({QStringLiteral("speed"), QStringLiteral("in2")}));
    stack.push(new ReplaceProfileCommand(&model, Profile::RtcProfile::createDefault()));
    QCOMPARE(table.rowCount(), 0);
    while (stack.canUndo())
        stack.undo();
    QCOMPARE(column(table, 0), QStringList({QStringLiteral("trigger"), QStringLiteral("speed")}));
}

void TestBuilderModels::changingThePortTypeMovesTheRow()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ItemTableModel in(&model, &stack, Part::DataPort, portColumns(), inPorts());
    QAbstractItemModelTester tester(&in, QAbstractItemModelTester::FailureReportingMode::QtTest);
    auto ranges = std::get<RtcDataPort>(model.item(Part::DataPort, 1));
    ranges.portType = QStringLiteral("DataInPort");
    stack.push(new EditItemCommand(&model, Part::DataPort, 1, ranges, QString(), QString()));
    QCOMPARE(column(in, 0),
             QStringList(
                 {QStringLiteral("trigger"), QStringLiteral("ranges"), QStringLiteral("speed")}));
    stack.undo();
    QCOMPARE(column(in, 0), QStringList({QStringLiteral("trigger"), QStringLiteral("speed")}));
}

void TestBuilderModels::editingACellIsAnUndoStep()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ItemTableModel table(&model, &stack, Part::DataPort, portColumns(), inPorts());
    QAbstractItemModelTester tester(&table, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(table.flags(table.index(0, 1)).testFlag(Qt::ItemIsEditable));
    QVERIFY(table.setData(table.index(1, 1), QStringLiteral("RTC::TimedFloat"), Qt::EditRole));
    QCOMPARE(model.profile().dataPorts.at(2).type, QStringLiteral("RTC::TimedFloat"));
    QCOMPARE(stack.count(), 1);
    QCOMPARE(stack.undoText(), QStringLiteral("Change type of speed"));
    QVERIFY(!table.setData(table.index(1, 1), QStringLiteral("RTC::TimedFloat"), Qt::EditRole));
    QCOMPARE(stack.count(), 1); // the same value is no edit
    stack.undo();
    QCOMPARE(table.index(1, 1).data().toString(), QStringLiteral("RTC::TimedDouble"));
}

void TestBuilderModels::duplicateNameIsMarkedWithReason()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ItemTableModel table(&model, &stack, Part::DataPort, portColumns(), inPorts());
    QVERIFY(table.index(1, 0).data(ItemTableModel::ProblemRole).isNull());
    // A service port's name clashes as well: ports share one name space.
    QVERIFY(table.setData(table.index(1, 0), QStringLiteral("control"), Qt::EditRole));
    QCOMPARE(table.index(1, 0).data(ItemTableModel::ProblemRole).toString(),
             QStringLiteral("The port name 'control' is already used by service port #1."));
    QCOMPARE(table.index(1, 0).data(Qt::ToolTipRole),
             table.index(1, 0).data(ItemTableModel::ProblemRole));
    QVERIFY(table.index(1, 0).data(Qt::BackgroundRole).isValid());
    QVERIFY(table.index(1, 1).data(Qt::BackgroundRole).isNull()); // only the name cell
    QVERIFY(table.setData(table.index(1, 0), QStringLiteral("trigger"), Qt::EditRole));
    QCOMPARE(table.index(0, 0).data(ItemTableModel::ProblemRole).toString(),
             QStringLiteral("The port name 'trigger' is already used by data port #3."));
    stack.undo();
    QVERIFY(table.index(0, 0).data(ItemTableModel::ProblemRole).isNull());
}

void TestBuilderModels::configurationConstraintAndWidget()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ItemTableModel table(&model, &stack, Part::Configuration, ConfigurationPage::columns());
    QAbstractItemModelTester tester(&table, QAbstractItemModelTester::FailureReportingMode::QtTest);
    const int constraint = table.columnOf(QStringLiteral("constraint"));
    const int widget = table.columnOf(QStringLiteral("widget"));
    const int step = table.columnOf(QStringLiteral("step"));
    QCOMPARE(column(table, constraint),
             QStringList({QStringLiteral("0..10"), QStringLiteral("(fast,slow)")}));
    QCOMPARE(column(table, widget),
             QStringList({QStringLiteral("slider"), QStringLiteral("radio")}));
    QCOMPARE(table.index(0, step).data().toString(), QStringLiteral("0.5"));

    // A syntax error is not stored; a valid string is.
    QVERIFY(!table.setData(table.index(0, constraint), QStringLiteral("0<=x<="), Qt::EditRole));
    QCOMPARE(stack.count(), 0);
    QVERIFY(table.setData(table.index(0, constraint), QStringLiteral("0<=x<=100"), Qt::EditRole));
    QCOMPARE(Profile::constraintToString(model.profile().configurations.at(0).constraint),
             QStringLiteral("0<=x<=100"));
    QVERIFY(table.setData(table.index(0, step), QStringLiteral("2"), Qt::EditRole));
    QCOMPARE(model.profile().configurations.at(0).widget(), QStringLiteral("slider.2"));

    // A radio needs an enumeration.
    QVERIFY(table.index(1, widget).data(ItemTableModel::ProblemRole).isNull());
    QVERIFY(table.setData(table.index(1, constraint), QStringLiteral("x>0"), Qt::EditRole));
    QVERIFY(table.index(1, widget)
                .data(ItemTableModel::ProblemRole)
                .toString()
                .contains(QStringLiteral("enumeration")));
    // No widget at all removes the property.
    QVERIFY(table.setData(table.index(1, widget), QString(), Qt::EditRole));
    QVERIFY(!model.profile().configurations.at(1).widget());
    while (stack.canUndo())
        stack.undo();
    QVERIFY(model.profile() == fixture());
}

void TestBuilderModels::actionTableChecksCallbacks()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ActionTableModel table(&model, &stack);
    QAbstractItemModelTester tester(&table, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(table.rowCount(), 12);
    QCOMPARE(column(table, 0).first(), QStringLiteral("onInitialize"));
    QCOMPARE(column(table, 0).last(), QStringLiteral("onRateChanged"));
    QVERIFY(!table.flags(table.index(0, 0)).testFlag(Qt::ItemIsUserCheckable));
    QVERIFY(!table.setData(table.index(0, 0), Qt::Unchecked, Qt::CheckStateRole));
    const int startup
        = int(ActionTableModel::editedActions().indexOf(Profile::RtcAction::OnStartup));
    QCOMPARE(table.index(startup, 0).data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    QVERIFY(table.setData(table.index(startup, 0), Qt::Checked, Qt::CheckStateRole));
    QCOMPARE(table.index(startup, 0).data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
    QVERIFY(model.profile().actions.isImplemented(Profile::RtcAction::OnStartup));
    const int execute
        = int(ActionTableModel::editedActions().indexOf(Profile::RtcAction::OnExecute));
    QCOMPARE(table.index(execute, 1).data().toString(), QStringLiteral("Reads one scan"));
    QVERIFY(
        table.setData(table.index(execute, 1), QStringLiteral("Reads two scans"), Qt::EditRole));
    QCOMPARE(stack.count(), 2);
    stack.undo();
    stack.undo();
    QVERIFY(model.profile() == fixture());
}

void TestBuilderModels::servicePortTreeFollowsInterfaces()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    ServicePortTreeModel tree(&model);
    QAbstractItemModelTester tester(&tree, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(tree.rowCount(), 1);
    const QModelIndex control = tree.index(0, 0);
    QCOMPARE(control.data().toString(), QStringLiteral("control"));
    QCOMPARE(tree.rowCount(control), 2);
    QCOMPARE(tree.index(1, 1, control).data().toString(),
             QStringLiteral("Required SimpleService::MyService"));
    QCOMPARE(ServicePortTreeModel::portOf(tree.index(1, 0, control)), 0);
    QCOMPARE(ServicePortTreeModel::interfaceOf(tree.index(1, 0, control)), 1);

    Profile::RtcServiceInterface interface;
    interface.name = QStringLiteral("service0"); // a duplicate within the port
    interface.direction = QStringLiteral("Provided");
    stack.push(makeAddInterfaceCommand(&model, 0, interface));
    QCOMPARE(tree.rowCount(tree.index(0, 0)), 3);
    QVERIFY(tree.indexFor(0, 2)
                .data(Qt::ToolTipRole)
                .toString()
                .contains(QStringLiteral("already used")));
    Profile::RtcServicePort port;
    port.name = QStringLiteral("status");
    port.position = QStringLiteral("LEFT");
    stack.push(new InsertItemCommand(&model, Part::ServicePort, 1, port));
    QCOMPARE(tree.rowCount(), 2);
    stack.undo();
    stack.undo();
    QCOMPARE(tree.rowCount(tree.index(0, 0)), 2);
}

void TestBuilderModels::libraryTable()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    LibraryTableModel table(&model, &stack);
    QAbstractItemModelTester tester(&table, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QCOMPARE(column(table, 0), QStringList({QStringLiteral("Eigen")}));
    QCOMPARE(table.index(0, 1).data().toString(), QStringLiteral("3.4"));
    table.addLibrary(QStringLiteral("Boost"));
    QCOMPARE(column(table, 0), QStringList({QStringLiteral("Eigen"), QStringLiteral("Boost")}));
    QVERIFY(table.setData(table.index(1, 1), QStringLiteral("1.74"), Qt::EditRole));
    QCOMPARE(model.profile().language->targets.first().libraries.at(1).version,
             QStringLiteral("1.74"));
    table.removeLibrary(0);
    QCOMPARE(column(table, 0), QStringList({QStringLiteral("Boost")}));
    QCOMPARE(stack.count(), 3);
    while (stack.canUndo())
        stack.undo();
    QVERIFY(model.profile() == fixture());
}

void TestBuilderModels::itemRules_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("problemKey");
    QTest::addColumn<QString>("problemPart");
    QTest::newRow("name charset") << "name"
                                  << "my port"
                                  << "name"
                                  << "' '";
    QTest::newRow("name empty") << "name"
                                << ""
                                << "name"
                                << "required";
    QTest::newRow("type empty") << "type"
                                << ""
                                << "type"
                                << "required";
    QTest::newRow("bad position") << "position"
                                  << "left"
                                  << "position"
                                  << "LEFT";
    QTest::newRow("variable not an identifier") << "variableName"
                                                << "1x"
                                                << "variableName"
                                                << "letter";
    QTest::newRow("variable used by a parameter") << "variableName"
                                                  << "gain"
                                                  << "variableName"
                                                  << "configuration parameter gain";
}

void TestBuilderModels::itemRules()
{
    QFETCH(QString, field);
    QFETCH(QString, value);
    QFETCH(QString, problemKey);
    QFETCH(QString, problemPart);
    Profile::RtcProfile profile = fixture();
    QVERIFY(itemProblems(profile, Part::DataPort, 0).isEmpty());
    RtcDataPort &p = profile.dataPorts[0];
    if (field == QLatin1String("name"))
        p.name = value;
    else if (field == QLatin1String("type"))
        p.type = value;
    else if (field == QLatin1String("position"))
        p.position = value;
    else
        p.variableName = value;
    const FieldProblems problems = itemProblems(profile, Part::DataPort, 0);
    QVERIFY2(problems.value(problemKey).contains(problemPart),
             qPrintable(problems.value(problemKey)));
    QVERIFY(!generationProblems(profile).isEmpty());
}

void TestBuilderModels::compositeCategoryHasNoPorts()
{
    Profile::RtcProfile profile = fixture();
    QVERIFY(generationProblems(profile).isEmpty());
    profile.basicInfo.category = QStringLiteral("composite.PeriodicECShared");
    profile.id = profile.idFromBasicInfo();
    QVERIFY(compositePortsProblem(profile).contains(QStringLiteral("no ports")));
    QCOMPARE(generationProblems(profile).size(), 1);
    profile.dataPorts.clear();
    profile.servicePorts.clear();
    QVERIFY(compositePortsProblem(profile).isEmpty());
    QVERIFY(generationProblems(profile).isEmpty());
}

void TestBuilderModels::describeChangesNamesEachChange()
{
    const Profile::RtcProfile before = fixture();
    QVERIFY(describeChanges(before, before).isEmpty());
    Profile::RtcProfile after = before;
    after.basicInfo.vendor = QStringLiteral("Other");
    after.dataPorts.removeAt(0);
    after.configurations[1].defaultValue = QStringLiteral("slow");
    after.actions.setImplemented(Profile::RtcAction::OnError, true);
    Profile::RtcServicePort extra;
    extra.name = QStringLiteral("status");
    after.servicePorts.append(extra);
    QCOMPARE(describeChanges(before, after),
             QStringList({QStringLiteral("Basic: vendor 'AIST' → 'Other'"),
                          QStringLiteral("onError: off → on"),
                          QStringLiteral("Data port 'trigger' removed"),
                          QStringLiteral("Service port 'status' added"),
                          QStringLiteral("Configuration parameter 'mode' changed")}));
}

QTEST_GUILESS_MAIN(TestBuilderModels)
#include "tst_buildermodels.moc"
