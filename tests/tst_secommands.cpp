// SPDX-License-Identifier: MIT
#include "instancecommands.h"
#include "componentfactory.h"
#include "compositecommands.h"
#include "connectorcommands.h"
#include "pastecommand.h"
#include "systemcommands.h"
#include "systemfile.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <functional>

using namespace Profile;
using namespace SystemEditor;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/systemeditor/")) + name;
}

RtcProfile rtcFile(const QString &name)
{
    Diagnostics diagnostics;
    const std::optional<LoadedProfile> loaded = loadProfileFile(dataPath(name), &diagnostics);
    return loaded && loaded->rtc ? *loaded->rtc : RtcProfile();
}

} // namespace

class TestSeCommands : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void addComponentGetsUniqueNames();
    void removeComponentTakesItsConnectors();
    void removeSeveralRestoresOrder();
    void moveMerges();
    void alignLeftAndTop();
    void resize();
    void rename();
    void refusedEditsLeaveNoStep();
    void direction();
    void pasteKeepsInnerConnectors();
    void connectData();
    void connectService();
    void disconnect();
    void editConnectorProperties();
    void bendPointsMerge();
    void configurationSets();
    void compositeCreateAndDecompose();
    void systemInfo();
    void systemInfoTypingMerges();

private:
    /// A → push → B (checked by `checkB`) → undo → A → redo → B.
    void roundTrip(QUndoCommand *command, const std::function<void()> &checkB);

    std::unique_ptr<SystemModel> m_model;
    std::unique_ptr<QUndoStack> m_stack;
};

void TestSeCommands::init()
{
    Diagnostics diagnostics;
    std::optional<LoadedSystem> loaded = loadSystemFile(dataPath("system/system.xml"), &diagnostics);
    QVERIFY(loaded);
    m_model = std::make_unique<SystemModel>();
    m_model->setProfile(loaded->profile, loaded->rtcProfiles);
    m_stack = std::make_unique<QUndoStack>();
}

void TestSeCommands::roundTrip(QUndoCommand *command, const std::function<void()> &checkB)
{
    QVERIFY(command);
    const RtsProfile a = m_model->profile();
    const QStringList aRtc = m_model->rtcProfiles().keys();
    QVERIFY(!command->text().isEmpty());
    m_stack->push(command);
    const RtsProfile b = m_model->profile();
    QVERIFY(b != a);
    checkB();
    m_stack->undo();
    QCOMPARE(m_model->profile(), a);
    QCOMPARE(QSet<QString>(m_model->rtcProfiles().keyBegin(), m_model->rtcProfiles().keyEnd()),
             QSet<QString>(aRtc.cbegin(), aRtc.cend()));
    m_stack->redo();
    QCOMPARE(m_model->profile(), b);
    checkB();
}

void TestSeCommands::addComponentGetsUniqueNames()
{
    const RtcProfile rtc = rtcFile("rtcs/ConsoleIn.xml");
    const RtsComponent component = componentFromRtcProfile(rtc, {}, "x/ConsoleIn.xml", {5, 6});
    auto *add = new AddComponentCommand(m_model.get(), component, rtc);
    QCOMPARE(add->instanceName(), QStringLiteral("ConsoleIn1"));
    roundTrip(add, [&] {
        QVERIFY(m_model->hasComponent("ConsoleIn1"));
        QCOMPARE(m_model->ports("ConsoleIn1").at(0).name, QStringLiteral("ConsoleIn1.out"));
        QCOMPARE(m_model->layout("ConsoleIn1").position, QPointF(5, 6));
        QVERIFY(m_model->rtcProfile("ConsoleIn1"));
    });
    auto *second = new AddComponentCommand(m_model.get(), component, rtc);
    QCOMPARE(second->instanceName(), QStringLiteral("ConsoleIn2"));
    delete second;

    // A new component carries the parameters' defaults as its active "default" set.
    const RtcProfile out = rtcFile("rtcs/ConsoleOut.xml");
    const RtsComponent consoleOut = componentFromRtcProfile(out, "C", "p", {});
    QCOMPARE(consoleOut.activeConfigurationSet, std::optional<QString>("default"));
    QCOMPARE(consoleOut.configurationSets.at(0).data.at(0).data, std::optional<QString>("1.5"));
    QCOMPARE(consoleOut.id, QStringLiteral("RTC:TestVendor:example:ConsoleOut:1.0.0"));
}

void TestSeCommands::removeComponentTakesItsConnectors()
{
    roundTrip(new RemoveComponentsCommand(m_model.get(), {"ConsoleIn0"}), [&] {
        QVERIFY(!m_model->hasComponent("ConsoleIn0"));
        QVERIFY(m_model->connectorIds().isEmpty());
        QVERIFY(!m_model->rtcProfile("ConsoleIn0"));
    });
    QCOMPARE(m_stack->undoText(), QStringLiteral("Delete ConsoleIn0"));
}

void TestSeCommands::removeSeveralRestoresOrder()
{
    roundTrip(new RemoveComponentsCommand(m_model.get(), {"Mystery0", "ConsoleIn0"}), [&] {
        QCOMPARE(m_model->componentIds(), QStringList {"ConsoleOut0"});
    });
}

void TestSeCommands::moveMerges()
{
    roundTrip(new MoveComponentsCommand(m_model.get(), {{"ConsoleIn0", QPointF(1, 2)}}), [&] {
        QCOMPARE(m_model->layout("ConsoleIn0").position, QPointF(1, 2));
    });
    m_stack->push(new MoveComponentsCommand(m_model.get(), {{"ConsoleIn0", QPointF(7, 8)}}));
    QCOMPARE(m_stack->count(), 1);
    QCOMPARE(m_model->layout("ConsoleIn0").position, QPointF(7, 8));
    m_stack->undo();
    QCOMPARE(m_model->layout("ConsoleIn0").position, QPointF(100, 50));
    // Moving a component without a Location and undoing leaves it without one.
    m_stack->push(new MoveComponentsCommand(m_model.get(), {{"Mystery0", QPointF(3, 3)}}));
    m_stack->undo();
    QVERIFY(!m_model->component("Mystery0")->layout);
}

void TestSeCommands::alignLeftAndTop()
{
    roundTrip(alignComponentsCommand(m_model.get(), {"ConsoleIn0", "ConsoleOut0"}, Alignment::Left),
              [&] { QCOMPARE(m_model->layout("ConsoleOut0").position, QPointF(100, 60)); });
    roundTrip(alignComponentsCommand(m_model.get(), {"ConsoleIn0", "ConsoleOut0"}, Alignment::Top),
              [&] { QCOMPARE(m_model->layout("ConsoleOut0").position.y(), 50.0); });
    // Align never merges with a move.
    QCOMPARE(m_stack->count(), 2);
    QVERIFY(!alignComponentsCommand(m_model.get(), {"ConsoleIn0"}, Alignment::Left));
    const QSizeF size = componentSize(*m_model, "ConsoleOut0");
    const QHash<QString, QPointF> right =
        alignedPositions(*m_model, {"ConsoleIn0", "ConsoleOut0"}, Alignment::Right);
    QCOMPARE(right.value("ConsoleOut0").x() + size.width(),
             100 + componentSize(*m_model, "ConsoleIn0").width());
}

void TestSeCommands::resize()
{
    roundTrip(new ResizeComponentCommand(m_model.get(), "ConsoleIn0", QSizeF(150, 90)), [&] {
        QCOMPARE(m_model->layout("ConsoleIn0").size, QSizeF(150, 90));
        QCOMPARE(componentSize(*m_model, "ConsoleIn0"), QSizeF(150, 90));
    });
    m_stack->push(new ResizeComponentCommand(m_model.get(), "ConsoleIn0", QSizeF(160, 95)));
    QCOMPARE(m_stack->count(), 1);
}

void TestSeCommands::rename()
{
    roundTrip(new RenameComponentCommand(m_model.get(), "ConsoleOut0", "Display"), [&] {
        QVERIFY(m_model->hasComponent("Display"));
        QCOMPARE(m_model->connector("c-1")->target,
                 (ConnectorEnd {"Display", "Display.in"}));
    });
}

void TestSeCommands::refusedEditsLeaveNoStep()
{
    const RtsProfile before = m_model->profile();
    m_stack->push(new RenameComponentCommand(m_model.get(), "ConsoleIn0", "ConsoleOut0"));
    QCOMPARE(m_stack->count(), 0);
    QCOMPARE(m_model->profile(), before);
    RtsDataPortConnector duplicate = *m_model->dataConnector("c-1");
    duplicate.name = "other";
    m_stack->push(new ConnectCommand(m_model.get(), duplicate));
    QCOMPARE(m_stack->count(), 0);
    QCOMPARE(m_model->dataConnector("c-1")->name, QStringLiteral("out_in"));
}

void TestSeCommands::direction()
{
    roundTrip(new SetDirectionCommand(m_model.get(), "ConsoleIn0", Direction::Down), [&] {
        QCOMPARE(m_model->layout("ConsoleIn0").direction, Direction::Down);
        QCOMPARE(m_model->ports("ConsoleIn0").at(0).side, PortSide::Bottom);
    });
}

void TestSeCommands::pasteKeepsInnerConnectors()
{
    const ComponentClipboard clipboard =
        ComponentClipboard::copy(*m_model, {"ConsoleIn0", "ConsoleOut0"});
    QCOMPARE(clipboard.components.size(), 2);
    QCOMPARE(clipboard.dataConnectors.size(), 1);
    auto *paste = new PasteComponentsCommand(m_model.get(), clipboard, QPointF(10, 10));
    QCOMPARE(paste->pastedNames(), QStringList({"ConsoleIn1", "ConsoleOut1"}));
    roundTrip(paste, [&] {
        QCOMPARE(m_model->layout("ConsoleIn1").position, QPointF(110, 60));
        QCOMPARE(m_model->connectorIds().size(), 2);
        const ConnectorInfo pasted = *m_model->connector(m_model->connectorIds().at(1));
        QVERIFY(pasted.id != "c-1");
        QCOMPARE(pasted.source, (ConnectorEnd {"ConsoleIn1", "ConsoleIn1.out"}));
        QCOMPARE(pasted.target, (ConnectorEnd {"ConsoleOut1", "ConsoleOut1.in"}));
        QVERIFY(m_model->rtcProfile("ConsoleOut1"));
    });
    // Copying only one end leaves the connector behind.
    QVERIFY(ComponentClipboard::copy(*m_model, {"ConsoleIn0"}).dataConnectors.isEmpty());
}

void TestSeCommands::connectData()
{
    const ConnectorSettings settings =
        ConnectorSettings::defaults("ConsoleIn0.out", "ConsoleOut0.in", "RTC::TimedLong");
    const RtsDataPortConnector connector = makeDataConnector(
        *m_model, {"ConsoleIn0", "ConsoleIn0.out"}, {"ConsoleOut0", "ConsoleOut0.in"}, settings);
    QCOMPARE(connector.name, QStringLiteral("out_in"));
    QVERIFY(!QUuid::fromString(connector.connectorId).isNull());
    QCOMPARE(connector.source.componentId, QStringLiteral("RTC:TestVendor:example:ConsoleIn:1.0.0"));
    auto *connect = new ConnectCommand(m_model.get(), connector);
    QCOMPARE(connect->connectorId(), connector.connectorId);
    roundTrip(connect, [&] {
        QCOMPARE(m_model->connectorIds().size(), 2);
        QCOMPARE(m_model->dataConnector(connector.connectorId)->dataflowType,
                 QStringLiteral("push"));
    });
}

void TestSeCommands::connectService()
{
    const RtsServicePortConnector connector =
        makeServiceConnector(*m_model, {"Mystery0", "Mystery0.ctl"}, {"ConsoleIn0", "x"});
    QCOMPARE(connector.name, QStringLiteral("ctl_x"));
    roundTrip(new ConnectCommand(m_model.get(), connector), [&] {
        QCOMPARE(m_model->connector(connector.connectorId)->kind, ConnectorKind::Service);
    });
}

void TestSeCommands::disconnect()
{
    roundTrip(new DisconnectCommand(m_model.get(), "c-1"),
              [&] { QVERIFY(m_model->connectorIds().isEmpty()); });
}

void TestSeCommands::editConnectorProperties()
{
    ConnectorSettings settings = ConnectorSettings::fromConnector(*m_model->dataConnector("c-1"));
    settings.name = "renamed";
    settings.subscriptionType = "periodic";
    settings.pushRate = "50";
    roundTrip(EditConnectorCommand::fromSettings(m_model.get(), "c-1", settings), [&] {
        const RtsDataPortConnector *c = m_model->dataConnector("c-1");
        QCOMPARE(c->name, QStringLiteral("renamed"));
        QCOMPARE(c->pushInterval, std::optional<QString>("50"));
        // The drawing's bend points and the unknown property survive the dialog.
        QVERIFY(rtsPropertyValue(c->properties, "BEND_POINT"));
        QCOMPARE(rtsPropertyValue(c->properties, "vendor.custom"), std::optional<QString>("42"));
    });
    QVERIFY(!EditConnectorCommand::fromSettings(m_model.get(), "none", settings));
}

void TestSeCommands::bendPointsMerge()
{
    roundTrip(new SetBendPointsCommand(m_model.get(), "c-1", {{1, 1}}), [&] {
        QCOMPARE(m_model->connector("c-1")->bendPoints, QList<QPointF> {QPointF(1, 1)});
    });
    m_stack->push(new SetBendPointsCommand(m_model.get(), "c-1", {{2, 2}, {3, 3}}));
    QCOMPARE(m_stack->count(), 1);
    // Dragging back to where it started makes the step disappear.
    m_stack->push(new SetBendPointsCommand(m_model.get(), "c-1", {{200, 70}, {250, 70}}));
    QCOMPARE(m_stack->count(), 0);
}

void TestSeCommands::configurationSets()
{
    RtsConfigurationSet second;
    second.id = "fast";
    RtsConfigurationData gain;
    gain.name = "gain";
    gain.data = "9";
    second.data << gain;
    QList<RtsConfigurationSet> sets = m_model->component("ConsoleOut0")->configurationSets;
    sets << second;
    roundTrip(new SetConfigurationSetsCommand(m_model.get(), "ConsoleOut0", sets, QString("fast")),
              [&] {
                  const RtsComponent *c = m_model->component("ConsoleOut0");
                  QCOMPARE(c->configurationSets.size(), 2);
                  QCOMPARE(c->activeConfigurationSet, std::optional<QString>("fast"));
              });
}

void TestSeCommands::compositeCreateAndDecompose()
{
    auto *create = new CreateCompositeCommand(m_model.get(), "PeriodicECShared",
                                              {"ConsoleIn0", "ConsoleOut0"},
                                              {{"ConsoleOut0", "ConsoleOut0.text"}});
    QCOMPARE(create->instanceName(), QStringLiteral("PeriodicECShared0"));
    roundTrip(create, [&] {
        const RtsComponent *c = m_model->component("PeriodicECShared0");
        QVERIFY(c);
        QCOMPARE(c->compositeType, std::optional<QString>("PeriodicECShared"));
        QCOMPARE(c->participants.size(), 2);
        QCOMPARE(c->participants.at(1).participant.instanceName, QStringLiteral("ConsoleOut0"));
        const std::optional<PortInfo> exported =
            m_model->port("PeriodicECShared0", "ConsoleOut0.text");
        QVERIFY(exported);
        QCOMPARE(exported->kind, PortKind::DataIn);
        QCOMPARE(exported->dataType, QStringLiteral("RTC::TimedString"));
        // Members stay in the system.
        QVERIFY(m_model->hasComponent("ConsoleIn0"));
    });
    roundTrip(new DecomposeCommand(m_model.get(), "PeriodicECShared0"), [&] {
        QVERIFY(!m_model->hasComponent("PeriodicECShared0"));
        QVERIFY(m_model->hasComponent("ConsoleOut0"));
    });
    QCOMPARE(compositeKinds().size(), 3);
}

void TestSeCommands::systemInfo()
{
    SystemProfileInfo info = m_model->systemInfo();
    info.vendor = "NewVendor";
    info.requiredComponents.insert("ConsoleOut0");
    QSignalSpy spy(m_model.get(), &SystemModel::systemInfoChanged);
    roundTrip(new SetSystemInfoCommand(m_model.get(), info), [&] {
        QCOMPARE(m_model->profile().id, QStringLiteral("RTSystem:NewVendor:Demo:1.0"));
        QCOMPARE(m_model->component("ConsoleOut0")->isRequired, QStringLiteral("true"));
    });
    QCOMPARE(spy.size(), 3);
}

void TestSeCommands::systemInfoTypingMerges()
{
    m_model->setSystemId("not an id");
    SystemProfileInfo info = m_model->systemInfo();
    info.vendor = "V";
    m_stack->push(new SetSystemInfoCommand(m_model.get(), info, 1));
    info.vendor = "Ve";
    m_stack->push(new SetSystemInfoCommand(m_model.get(), info, 1));
    QCOMPARE(m_stack->count(), 1);
    QCOMPARE(m_model->profile().id, QStringLiteral("RTSystem:Ve::"));
    m_stack->undo();
    // Undo restores the malformed id exactly as it was.
    QCOMPARE(m_model->profile().id, QStringLiteral("not an id"));
}

QTEST_GUILESS_MAIN(TestSeCommands)
#include "tst_secommands.moc"
