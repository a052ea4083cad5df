// SPDX-License-Identifier: MIT
// The Builder's editing model and its undo commands: state A, do → B, undo → A, redo → B for every
// command; merging of typing; the model's change signals.
#include "componentcommands.h"
#include "componentmodel.h"
#include "itemcommands.h"
#include "rtcxml.h"

#include <QFile>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <functional>

using namespace Builder;
using Profile::RtcAction;

using CommandMaker = std::function<QUndoCommand *(ComponentModel *)>;
Q_DECLARE_METATYPE(CommandMaker)

namespace {

Profile::RtcProfile fixture()
{
    QFile file(RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/builder/component.xml"));
    if (!file.open(QIODevice::ReadOnly))
        qFatal("missing fixture component.xml");
    Profile::Diagnostics diagnostics;
    auto profile = Profile::readRtcXml(file.readAll(), file.fileName(), &diagnostics);
    if (!profile)
        qFatal("fixture component.xml does not read");
    return *profile;
}

template<typename T> T itemAt(ComponentModel *model, Part part, int index)
{
    return std::get<T>(model->item(part, index));
}

} // namespace

class TestBuilderCommands : public QObject
{
    Q_OBJECT

private slots:
    void doUndoRedo_data();
    void doUndoRedo();
    void renamePortTypingMerges();
    void differentFieldsDoNotMerge();
    void editBackToStartIsDropped();
    void actionDocTypingMerges();
    void insertAnnouncesPositionAndName();
    void removeAnnouncesBeforeAndAfter();
    void moveKeepsEveryElement();
    void replaceProfileIsOneStep();
};

void TestBuilderCommands::doUndoRedo_data()
{
    QTest::addColumn<CommandMaker>("make");
    QTest::addColumn<QString>("text");
    const auto row = [](const char *name, const char *text, CommandMaker make) {
        QTest::newRow(name) << make << QString::fromUtf8(text);
    };
    row("basic field", "Change vendor", [](ComponentModel *m) {
        return new SetBasicFieldCommand(m, BasicField::Vendor, QStringLiteral("Other"));
    });
    row("action on", "Change onStartup", [](ComponentModel *m) {
        auto status = m->action(RtcAction::OnStartup);
        status->setImplemented(true);
        return new SetActionCommand(m, RtcAction::OnStartup, status);
    });
    row("action added", "Change onModeChanged", [](ComponentModel *m) {
        Profile::RtcProfile p = Profile::RtcProfile::createDefault();
        m->setProfile(p);
        Profile::RtcActionStatus status;
        status.setImplemented(true);
        return new SetActionCommand(m, RtcAction::OnModeChanged, status);
    });
    row("component doc", "Change documentation", [](ComponentModel *m) {
        auto doc = m->profile().basicInfo.doc;
        doc->algorithm = QStringLiteral("Kalman filter");
        return new SetComponentDocCommand(m, doc);
    });
    row("language", "Change language and environment", [](ComponentModel *m) {
        auto language = m->profile().language;
        language->kind = QStringLiteral("Python");
        return new SetLanguageCommand(m, language);
    });
    row("add data port", "Add data port", [](ComponentModel *m) {
        Profile::RtcDataPort port;
        port.name = QStringLiteral("extra");
        port.portType = QStringLiteral("DataOutPort");
        return new InsertItemCommand(m, Part::DataPort, 1, port);
    });
    row("remove data port", "Remove data port ranges",
        [](ComponentModel *m) { return new RemoveItemCommand(m, Part::DataPort, 1); });
    row("move data port", "Move data port trigger",
        [](ComponentModel *m) { return new MoveItemCommand(m, Part::DataPort, 0, 2); });
    row("rename data port", "Change name of trigger", [](ComponentModel *m) {
        auto port = itemAt<Profile::RtcDataPort>(m, Part::DataPort, 0);
        port.name = QStringLiteral("start");
        return new EditItemCommand(m, Part::DataPort, 0, port, QStringLiteral("name"),
                                   QStringLiteral("Change name of trigger"));
    });
    row("add service port", "Add service port", [](ComponentModel *m) {
        Profile::RtcServicePort port;
        port.name = QStringLiteral("status");
        return new InsertItemCommand(m, Part::ServicePort, 1, port);
    });
    row("remove service port", "Remove service port control",
        [](ComponentModel *m) { return new RemoveItemCommand(m, Part::ServicePort, 0); });
    row("add interface", "Add interface status0 to control", [](ComponentModel *m) {
        Profile::RtcServiceInterface interface;
        interface.name = QStringLiteral("status0");
        interface.direction = QStringLiteral("Provided");
        return makeAddInterfaceCommand(m, 0, interface);
    });
    row("remove interface", "Remove interface client0 from control",
        [](ComponentModel *m) { return makeRemoveInterfaceCommand(m, 0, 1); });
    row("edit interface", "Change interface service1", [](ComponentModel *m) {
        auto interface = itemAt<Profile::RtcServicePort>(m, Part::ServicePort, 0).interfaces.at(0);
        interface.name = QStringLiteral("service1");
        return makeEditInterfaceCommand(m, 0, 0, interface, QStringLiteral("name"));
    });
    row("add configuration", "Add configuration parameter", [](ComponentModel *m) {
        Profile::RtcConfiguration c;
        c.name = QStringLiteral("threshold");
        return new InsertItemCommand(m, Part::Configuration, 2, c);
    });
    row("remove configuration", "Remove configuration parameter gain",
        [](ComponentModel *m) { return new RemoveItemCommand(m, Part::Configuration, 0); });
    row("edit configuration constraint", "Change constraint", [](ComponentModel *m) {
        auto c = itemAt<Profile::RtcConfiguration>(m, Part::Configuration, 0);
        c.constraint.reset();
        return new EditItemCommand(m, Part::Configuration, 0, c, QStringLiteral("constraint"),
                                   QStringLiteral("Change constraint"));
    });
    row("replace profile", "Edit RTC.xml", [](ComponentModel *m) {
        Profile::RtcProfile p = m->profile();
        p.dataPorts.clear();
        p.basicInfo.name = QStringLiteral("Other");
        return new ReplaceProfileCommand(m, p);
    });
}

void TestBuilderCommands::doUndoRedo()
{
    QFETCH(CommandMaker, make);
    QFETCH(QString, text);
    ComponentModel model(fixture());
    QUndoStack stack;
    QUndoCommand *command = make(&model);
    const Profile::RtcProfile stateA = model.profile();
    QCOMPARE(command->text(), text);

    stack.push(command);
    const Profile::RtcProfile stateB = model.profile();
    QVERIFY(stateB != stateA);
    stack.undo();
    QVERIFY(model.profile() == stateA);
    stack.redo();
    QVERIFY(model.profile() == stateB);
}

void TestBuilderCommands::renamePortTypingMerges()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    const Profile::RtcProfile stateA = model.profile();
    for (const char *name : {"t", "ti", "tic", "tick"}) {
        auto port = itemAt<Profile::RtcDataPort>(&model, Part::DataPort, 0);
        port.name = QString::fromLatin1(name);
        stack.push(new EditItemCommand(&model, Part::DataPort, 0, port, QStringLiteral("name"),
                                       QStringLiteral("Rename")));
    }
    QCOMPARE(stack.count(), 1);
    QCOMPARE(model.itemName(Part::DataPort, 0), QStringLiteral("tick"));
    stack.undo();
    QVERIFY(model.profile() == stateA);
    stack.redo();
    QCOMPARE(model.itemName(Part::DataPort, 0), QStringLiteral("tick"));
}

void TestBuilderCommands::differentFieldsDoNotMerge()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    auto port = itemAt<Profile::RtcDataPort>(&model, Part::DataPort, 0);
    port.name = QStringLiteral("a");
    stack.push(new EditItemCommand(&model, Part::DataPort, 0, port, QStringLiteral("name"), {}));
    port.type = QStringLiteral("RTC::TimedShort");
    stack.push(new EditItemCommand(&model, Part::DataPort, 0, port, QStringLiteral("type"), {}));
    // The same field of another port does not merge either.
    auto other = itemAt<Profile::RtcDataPort>(&model, Part::DataPort, 2);
    other.name = QStringLiteral("b");
    stack.push(new EditItemCommand(&model, Part::DataPort, 2, other, QStringLiteral("name"), {}));
    QCOMPARE(stack.count(), 3);
    stack.undo();
    QCOMPARE(model.itemName(Part::DataPort, 2), QStringLiteral("speed"));
    QCOMPARE(itemAt<Profile::RtcDataPort>(&model, Part::DataPort, 0).type,
             QStringLiteral("RTC::TimedShort"));
}

void TestBuilderCommands::editBackToStartIsDropped()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    auto port = itemAt<Profile::RtcDataPort>(&model, Part::DataPort, 0);
    port.name = QStringLiteral("triggerX");
    stack.push(new EditItemCommand(&model, Part::DataPort, 0, port, QStringLiteral("name"), {}));
    QCOMPARE(stack.count(), 1);
    port.name = QStringLiteral("trigger");
    stack.push(new EditItemCommand(&model, Part::DataPort, 0, port, QStringLiteral("name"), {}));
    QCOMPARE(stack.count(), 0);
    QVERIFY(model.profile() == fixture());
}

void TestBuilderCommands::actionDocTypingMerges()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    for (const char *text : {"R", "Re", "Res"}) {
        auto status = model.action(RtcAction::OnReset);
        status->doc = Profile::RtcActionDoc();
        status->doc->description = QString::fromLatin1(text);
        stack.push(new SetActionCommand(&model, RtcAction::OnReset, status,
                                        QStringLiteral("description")));
    }
    QCOMPARE(stack.count(), 1);
    QCOMPARE(model.action(RtcAction::OnReset)->doc->description, QStringLiteral("Res"));
    // Typing into another action's description is a step of its own.
    auto startup = model.action(RtcAction::OnStartup).value_or(Profile::RtcActionStatus());
    startup.doc = Profile::RtcActionDoc();
    startup.doc->description = QStringLiteral("S");
    stack.push(
        new SetActionCommand(&model, RtcAction::OnStartup, startup, QStringLiteral("description")));
    QCOMPARE(stack.count(), 2);
    QCOMPARE(model.action(RtcAction::OnReset)->doc->description, QStringLiteral("Res"));
    // Switching the action on is a step of its own.
    auto status = model.action(RtcAction::OnReset);
    status->setImplemented(true);
    stack.push(new SetActionCommand(&model, RtcAction::OnReset, status));
    QCOMPARE(stack.count(), 3);
    stack.undo();
    stack.undo();
    QCOMPARE(model.action(RtcAction::OnReset)->doc->description, QStringLiteral("Res"));
    QVERIFY(!model.action(RtcAction::OnStartup) || !model.action(RtcAction::OnStartup)->doc);
    stack.undo();
    QVERIFY(!model.action(RtcAction::OnReset)->doc);
}

void TestBuilderCommands::insertAnnouncesPositionAndName()
{
    ComponentModel model(fixture());
    QSignalSpy inserted(&model, &ComponentModel::itemInserted);
    QSignalSpy changed(&model, &ComponentModel::changed);
    Profile::RtcConfiguration c;
    c.name = QStringLiteral("rate");
    model.insertItem(Part::Configuration, 99, c); // clamped to the end
    QCOMPARE(inserted.count(), 1);
    QCOMPARE(inserted.at(0).at(0).value<Part>(), Part::Configuration);
    QCOMPARE(inserted.at(0).at(1).toInt(), 2);
    QCOMPARE(inserted.at(0).at(2).toString(), QStringLiteral("rate"));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(model.indexOf(Part::Configuration, QStringLiteral("rate")), 2);
}

void TestBuilderCommands::removeAnnouncesBeforeAndAfter()
{
    ComponentModel model(fixture());
    QStringList order;
    connect(&model, &ComponentModel::itemAboutToBeRemoved, this,
            [&](Part, int index, const QString &name) {
                order << QStringLiteral("about %1 %2 %3")
                             .arg(index)
                             .arg(name)
                             .arg(model.itemCount(Part::DataPort));
            });
    connect(&model, &ComponentModel::itemRemoved, this, [&](Part, int index, const QString &name) {
        order << QStringLiteral("removed %1 %2 %3")
                     .arg(index)
                     .arg(name)
                     .arg(model.itemCount(Part::DataPort));
    });
    model.removeItem(Part::DataPort, 1);
    QCOMPARE(
        order,
        QStringList({QStringLiteral("about 1 ranges 3"), QStringLiteral("removed 1 ranges 2")}));
    model.removeItem(Part::DataPort, 7); // out of range: nothing
    QCOMPARE(order.size(), 2);
}

void TestBuilderCommands::moveKeepsEveryElement()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    QSignalSpy moved(&model, &ComponentModel::itemMoved);
    stack.push(new MoveItemCommand(&model, Part::DataPort, 2, 0));
    const QStringList names = {model.itemName(Part::DataPort, 0), model.itemName(Part::DataPort, 1),
                               model.itemName(Part::DataPort, 2)};
    QCOMPARE(names,
             QStringList(
                 {QStringLiteral("speed"), QStringLiteral("trigger"), QStringLiteral("ranges")}));
    QCOMPARE(moved.count(), 1);
    QCOMPARE(moved.at(0).at(3).toString(), QStringLiteral("speed"));
    stack.undo();
    QVERIFY(model.profile() == fixture());
}

void TestBuilderCommands::replaceProfileIsOneStep()
{
    ComponentModel model(fixture());
    QUndoStack stack;
    QSignalSpy aboutToReset(&model, &ComponentModel::profileAboutToBeReset);
    QSignalSpy reset(&model, &ComponentModel::profileReset);
    Profile::RtcProfile other = Profile::RtcProfile::createDefault();
    stack.push(new ReplaceProfileCommand(&model, other));
    QCOMPARE(stack.count(), 1);
    QCOMPARE(aboutToReset.count(), 1);
    QCOMPARE(reset.count(), 1);
    QVERIFY(model.profile() == other);
    stack.undo();
    QVERIFY(model.profile() == fixture());
    QCOMPARE(reset.count(), 2);
}

QTEST_GUILESS_MAIN(TestBuilderCommands)
#include "tst_buildercommands.moc"
