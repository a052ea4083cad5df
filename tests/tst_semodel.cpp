// SPDX-License-Identifier: MIT
#include "systemfile.h"
#include "systemmodel.h"

#include <QSignalSpy>
#include <QTest>

using namespace Profile;
using namespace SystemEditor;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/systemeditor/")) + name;
}

/// The demo system with its RTC profiles resolved.
std::unique_ptr<SystemModel> demoModel()
{
    Diagnostics diagnostics;
    std::optional<LoadedSystem> loaded = loadSystemFile(dataPath("system/system.xml"), &diagnostics);
    auto model = std::make_unique<SystemModel>();
    if (loaded)
        model->setProfile(loaded->profile, loaded->rtcProfiles);
    return model;
}

} // namespace

class TestSeModel : public QObject
{
    Q_OBJECT

private slots:
    void loadsComponentsAndResolvesRtcProfiles();
    void portsOfDescribedComponent();
    void portsFollowDirection();
    void portsOfUnknownComponentComeFromTheSystemFile();
    void servicePortInterfaces();
    void connectorInfo();
    void layoutAndDefaults();
    void uniqueInstanceNames();
    void renameFollowsEverything();
    void renameRefusesTakenNames();
    void mutatorsAnnounceChanges();
    void removeComponentSignalsInOrder();
    void bendPointText_data();
    void bendPointText();
    void systemInfoRoundTrip();
    void directionText_data();
    void directionText();
};

void TestSeModel::loadsComponentsAndResolvesRtcProfiles()
{
    const auto model = demoModel();
    QCOMPARE(model->componentIds(),
             QStringList({"ConsoleIn0", "ConsoleOut0", "Mystery0"}));
    QVERIFY(model->rtcProfile("ConsoleIn0"));
    QCOMPARE(model->rtcProfile("ConsoleIn0")->basicInfo.name, QStringLiteral("ConsoleIn"));
    QVERIFY(model->rtcProfile("ConsoleOut0"));
    QVERIFY(!model->rtcProfile("Mystery0"));
    QCOMPARE(model->componentIndex("ConsoleOut0"), 1);
    QCOMPARE(model->componentIndex("Nobody"), -1);
}

void TestSeModel::portsOfDescribedComponent()
{
    const auto model = demoModel();
    const QList<PortInfo> ports = model->ports("ConsoleIn0");
    QCOMPARE(ports.size(), 1);
    QCOMPARE(ports.at(0).name, QStringLiteral("ConsoleIn0.out"));
    QCOMPARE(ports.at(0).profileName, QStringLiteral("out"));
    QCOMPARE(ports.at(0).kind, PortKind::DataOut);
    QCOMPARE(ports.at(0).dataType, QStringLiteral("RTC::TimedLong"));
    QCOMPARE(ports.at(0).side, PortSide::Right);
    QVERIFY(ports.at(0).described);
    QVERIFY(model->isPortConnected("ConsoleIn0", "ConsoleIn0.out"));
}

void TestSeModel::portsFollowDirection()
{
    const auto model = demoModel();
    // ConsoleOut0 faces LEFT (written in lower case in the file): its inputs are drawn right.
    QCOMPARE(model->layout("ConsoleOut0").direction, Direction::Left);
    const std::optional<PortInfo> in = model->port("ConsoleOut0", "ConsoleOut0.in");
    QVERIFY(in);
    QCOMPARE(in->kind, PortKind::DataIn);
    QCOMPARE(in->profileSide, PortSide::Left);
    QCOMPARE(in->side, PortSide::Right);
    QVERIFY(!model->isPortConnected("ConsoleOut0", "ConsoleOut0.text"));

    QCOMPARE(rotatedSide(PortSide::Left, Direction::Down), PortSide::Top);
    QCOMPARE(rotatedSide(PortSide::Right, Direction::Down), PortSide::Bottom);
    QCOMPARE(rotatedSide(PortSide::Left, Direction::Up), PortSide::Bottom);
    QCOMPARE(rotatedSide(PortSide::Top, Direction::Right), PortSide::Top);
}

void TestSeModel::portsOfUnknownComponentComeFromTheSystemFile()
{
    const auto model = demoModel();
    const QList<PortInfo> ports = model->ports("Mystery0");
    QCOMPARE(ports.size(), 2);
    QCOMPARE(ports.at(0).name, QStringLiteral("Mystery0.raw"));
    QCOMPARE(ports.at(0).kind, PortKind::Unknown);
    QVERIFY(ports.at(0).isDataPort());
    QVERIFY(!ports.at(0).described);
    QCOMPARE(ports.at(1).kind, PortKind::Service);
    QVERIFY(model->ports("Nobody").isEmpty());
}

void TestSeModel::servicePortInterfaces()
{
    SystemModel model;
    Diagnostics warnings;
    RtsProfile profile = RtsProfile::createNew("V", "S", "1");
    RtsComponent consumer;
    consumer.instanceName = "Consumer0";
    consumer.pathUri = dataPath("rtcs/sub/Consumer.xml");
    profile.components << consumer;
    model.setProfile(profile, resolveRtcProfiles(profile, dataPath("x.xml"), &warnings));
    QVERIFY(warnings.isEmpty());
    const QList<PortInfo> ports = model.ports("Consumer0");
    QCOMPARE(ports.size(), 1);
    QCOMPARE(ports.at(0).name, QStringLiteral("Consumer0.svc"));
    QCOMPARE(ports.at(0).kind, PortKind::Service);
    QCOMPARE(ports.at(0).side, PortSide::Left);
    QCOMPARE(ports.at(0).interfaces.size(), 2);
    const InterfaceInfo expected {"IRequired", "Demo::Calculator", "calc", RtcDirection::Required};
    QCOMPARE(ports.at(0).interfaces.at(0), expected);
}

void TestSeModel::connectorInfo()
{
    const auto model = demoModel();
    QCOMPARE(model->connectorIds(), QStringList {"c-1"});
    const std::optional<ConnectorInfo> c = model->connector("c-1");
    QVERIFY(c);
    QCOMPARE(c->kind, ConnectorKind::Data);
    QCOMPARE(c->name, QStringLiteral("out_in"));
    QCOMPARE(c->source, (ConnectorEnd {"ConsoleIn0", "ConsoleIn0.out"}));
    QCOMPARE(c->target, (ConnectorEnd {"ConsoleOut0", "ConsoleOut0.in"}));
    QCOMPARE(c->bendPoints, (QList<QPointF> {{200, 70}, {250, 70}}));
    QCOMPARE(model->connectorsOf("ConsoleOut0"), QStringList {"c-1"});
    QCOMPARE(model->connectorsOf("ConsoleOut0", "ConsoleOut0.text"), QStringList());
    QVERIFY(!model->connector("none"));
}

void TestSeModel::layoutAndDefaults()
{
    const auto model = demoModel();
    const ComponentLayout layout = model->layout("ConsoleIn0");
    QCOMPARE(layout.position, QPointF(100, 50));
    QCOMPARE(layout.size, QSizeF(-1, -1));
    QCOMPARE(layout.direction, Direction::Right);
    // No Location: origin, default size, facing right.
    QCOMPARE(model->layout("Mystery0"), ComponentLayout());
}

void TestSeModel::uniqueInstanceNames()
{
    const auto model = demoModel();
    QCOMPARE(model->uniqueInstanceName("ConsoleIn"), QStringLiteral("ConsoleIn1"));
    QCOMPARE(model->uniqueInstanceName("Camera"), QStringLiteral("Camera0"));
}

void TestSeModel::renameFollowsEverything()
{
    const auto model = demoModel();
    QSignalSpy renamed(model.get(), &SystemModel::componentRenamed);
    QSignalSpy connectorChanged(model.get(), &SystemModel::connectorChanged);
    QVERIFY(model->renameComponent("ConsoleIn0", "Keyboard"));
    QCOMPARE(renamed.size(), 1);
    QCOMPARE(renamed.at(0).at(1).toString(), QStringLiteral("Keyboard"));
    QCOMPARE(connectorChanged.size(), 1);
    const RtsProfile &p = model->profile();
    QCOMPARE(p.components.at(0).dataPorts.at(0).name, QStringLiteral("Keyboard.out"));
    QCOMPARE(p.dataPortConnectors.at(0).source.instanceName, QStringLiteral("Keyboard"));
    QCOMPARE(p.dataPortConnectors.at(0).source.portName, QStringLiteral("Keyboard.out"));
    QCOMPARE(p.groups.at(0).members.at(0).instanceName, QStringLiteral("Keyboard"));
    QCOMPARE(p.startUp->targets.at(0).targetComponent.instanceName, QStringLiteral("Keyboard"));
    QVERIFY(model->rtcProfile("Keyboard"));
    QVERIFY(!model->rtcProfile("ConsoleIn0"));
    QCOMPARE(model->ports("Keyboard").at(0).kind, PortKind::DataOut);
}

void TestSeModel::renameRefusesTakenNames()
{
    const auto model = demoModel();
    const RtsProfile before = model->profile();
    QVERIFY(!model->renameComponent("ConsoleIn0", "ConsoleOut0"));
    QVERIFY(!model->renameComponent("ConsoleIn0", ""));
    QVERIFY(!model->renameComponent("Nobody", "X"));
    QCOMPARE(model->profile(), before);
}

void TestSeModel::mutatorsAnnounceChanges()
{
    const auto model = demoModel();
    QSignalSpy changed(model.get(), &SystemModel::componentChanged);
    QVERIFY(model->moveComponent("ConsoleIn0", QPointF(10.4, 20.6)));
    QCOMPARE(model->layout("ConsoleIn0").position, QPointF(10, 21));
    QCOMPARE(changed.size(), 1);
    QVERIFY(model->moveComponent("ConsoleIn0", QPointF(10, 21)));
    QCOMPARE(changed.size(), 1); // no change, no signal
    QVERIFY(model->resizeComponent("Mystery0", QSizeF(120, 90)));
    QCOMPARE(model->layout("Mystery0").size, QSizeF(120, 90));
    QVERIFY(model->setDirection("Mystery0", Direction::Down));
    QCOMPARE(model->component("Mystery0")->layout->direction, QStringLiteral("DOWN"));
    QCOMPARE(changed.size(), 3);
    QVERIFY(!model->moveComponent("Nobody", QPointF()));

    QSignalSpy connectorChanged(model.get(), &SystemModel::connectorChanged);
    QVERIFY(model->setBendPoints("c-1", {}));
    QVERIFY(!rtsPropertyValue(model->dataConnector("c-1")->properties, "BEND_POINT"));
    QCOMPARE(connectorChanged.size(), 1);
    // The unknown property beside it stays.
    QCOMPARE(rtsPropertyValue(model->dataConnector("c-1")->properties, "vendor.custom"),
             std::optional<QString>("42"));
}

void TestSeModel::removeComponentSignalsInOrder()
{
    const auto model = demoModel();
    QStringList events;
    connect(model.get(), &SystemModel::componentAboutToBeRemoved, this, [&](const QString &n) {
        events << "about:" + n + ":" + QString::number(model->hasComponent(n));
    });
    connect(model.get(), &SystemModel::componentRemoved, this, [&](const QString &n) {
        events << "removed:" + n + ":" + QString::number(model->hasComponent(n));
    });
    QVERIFY(model->removeComponent("Mystery0"));
    QCOMPARE(events, QStringList({"about:Mystery0:1", "removed:Mystery0:0"}));
    QVERIFY(!model->removeComponent("Mystery0"));
}

void TestSeModel::bendPointText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("valid");
    QTest::addColumn<QList<QPointF>>("points");
    QTest::newRow("two") << "{1:(10,20),2:(30,-40)}" << true << QList<QPointF> {{10, 20}, {30, -40}};
    QTest::newRow("spaces, order by key") << " { 2:(3, 4) , 1:(1,2) } " << true
                                          << QList<QPointF> {{1, 2}, {3, 4}};
    QTest::newRow("empty") << "{}" << true << QList<QPointF>();
    QTest::newRow("no braces") << "1:(1,2)" << false << QList<QPointF>();
    QTest::newRow("garbage") << "{1:(a,b)}" << false << QList<QPointF>();
}

void TestSeModel::bendPointText()
{
    QFETCH(QString, text);
    QFETCH(bool, valid);
    QFETCH(QList<QPointF>, points);
    const std::optional<QList<QPointF>> parsed = bendPointsFromText(text);
    QCOMPARE(parsed.has_value(), valid);
    if (valid) {
        QCOMPARE(*parsed, points);
        QCOMPARE(bendPointsFromText(bendPointsToText(points)), parsed);
    }
}

void TestSeModel::systemInfoRoundTrip()
{
    const auto model = demoModel();
    SystemProfileInfo info = model->systemInfo();
    QCOMPARE(info.vendor, QStringLiteral("TestVendor"));
    QCOMPARE(info.systemName, QStringLiteral("Demo"));
    QCOMPARE(info.version, QStringLiteral("1.0"));
    QCOMPARE(info.requiredComponents, (QSet<QString> {"ConsoleIn0", "Mystery0"}));
    QSignalSpy infoChanged(model.get(), &SystemModel::systemInfoChanged);
    info.systemName = "Other";
    info.requiredComponents = {"ConsoleOut0"};
    model->setSystemInfo(info);
    QCOMPARE(infoChanged.size(), 1);
    QCOMPARE(model->profile().id, QStringLiteral("RTSystem:TestVendor:Other:1.0"));
    QCOMPARE(model->component("ConsoleIn0")->isRequired, QStringLiteral("false"));
    QCOMPARE(model->component("ConsoleOut0")->isRequired, QStringLiteral("true"));
    QCOMPARE(model->systemInfo(), info);
    info.vendor = "a:b";
    QCOMPARE(info.problems().size(), 1);
}

void TestSeModel::directionText_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<Direction>("direction");
    QTest::newRow("RIGHT") << "RIGHT" << Direction::Right;
    QTest::newRow("left") << "left" << Direction::Left;
    QTest::newRow("Up") << "Up" << Direction::Up;
    QTest::newRow("DOWN") << "DOWN" << Direction::Down;
    QTest::newRow("bad") << "sideways" << Direction::Right;
}

void TestSeModel::directionText()
{
    QFETCH(QString, text);
    QFETCH(Direction, direction);
    QCOMPARE(directionFromText(text), direction);
    if (text != "sideways")
        QCOMPARE(SystemEditor::directionText(direction), text.toUpper());
}

QTEST_GUILESS_MAIN(TestSeModel)
#include "tst_semodel.moc"
