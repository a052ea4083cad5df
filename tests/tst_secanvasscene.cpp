// SPDX-License-Identifier: MIT
// The canvas scene: items follow the model (through undo), port sides and turning, colours,
// tool tips, resizing, routes.
#include "tst_secanvassupport.h"

#include "instancecommands.h"
#include "componentitem.h"
#include "componentfactory.h"
#include "connectorcommands.h"
#include "connectoritem.h"
#include "manhattanroute.h"
#include "portgeometry.h"
#include "portitem.h"
#include "systemscene.h"

#include <QTemporaryDir>
#include <QUndoStack>

using namespace SystemEditor;
using SeCanvasTest::loadModel;

Q_DECLARE_METATYPE(SystemEditor::PortSide)

namespace {

/// The side of the body a port item sits on, measured from the drawing.
PortSide measuredSide(const ComponentItem *component, const PortItem *port)
{
    const QRectF body = component->bodyRect();
    const QPointF at = port->pos();
    if (at.x() < body.left())
        return PortSide::Left;
    if (at.x() > body.right())
        return PortSide::Right;
    if (at.y() < body.top())
        return PortSide::Top;
    return PortSide::Bottom;
}

} // namespace

class TestSeCanvasScene : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void buildsItemsForTheModel();
    void addedComponentFollowsUndo();
    void renameKeepsItemAndConnector();
    void moveFollowsUndo();
    void removalTakesConnectorsAndUndoRestores();
    void portSides_data();
    void portSides();
    void turningMovesPorts();
    void portColoursFollowConnections();
    void toolTipsNameTypes();
    void resizeKeepsPortsLaidOut();
    void connectorFollowsComponent();
    void bendPointsShapeTheRoute();
    void routesAreManhattan_data();
    void routesAreManhattan();
    void routeGoesRoundBodiesFacingAway();
    void rtSystemEditorBendPointsMoveSegments();
    void savedCornersReadBackInBothForms();
    void rtSystemEditorFileRoutesAndSavesUnchanged();

private:
    std::unique_ptr<SystemModel> m_model;
    std::unique_ptr<QUndoStack> m_stack;
    std::unique_ptr<SystemScene> m_scene;
};

void TestSeCanvasScene::init()
{
    m_model = loadModel();
    QVERIFY(m_model);
    m_stack = std::make_unique<QUndoStack>();
    m_scene = std::make_unique<SystemScene>(m_model.get(), m_stack.get());
}

void TestSeCanvasScene::cleanup()
{
    m_scene.reset();
    m_stack.reset();
    m_model.reset();
}

void TestSeCanvasScene::buildsItemsForTheModel()
{
    QCOMPARE(m_scene->componentItemCount(), 3);
    QCOMPARE(m_scene->connectorItemCount(), 1);
    ComponentItem *filter = m_scene->componentItem(QStringLiteral("Filter0"));
    QVERIFY(filter);
    QCOMPARE(filter->pos(), QPointF(320, 60));
    QCOMPARE(filter->appearance().typeName, QStringLiteral("Filter"));
    QCOMPARE(filter->portItems().size(), 4);
    ConnectorItem *connector = m_scene->connectorItem(QStringLiteral("c-sensor-filter"));
    QVERIFY(connector);
    QCOMPARE(connector->sourcePort(),
             m_scene->portItem({QStringLiteral("Sensor0"), QStringLiteral("Sensor0.out")}));
    QCOMPARE(connector->targetPort(), filter->portItem(QStringLiteral("Filter0.in")));
}

void TestSeCanvasScene::addedComponentFollowsUndo()
{
    const Profile::RtcProfile rtc = *m_model->rtcProfile(QStringLiteral("Sink0"));
    const Profile::RtsComponent record
        = componentFromRtcProfile(rtc, QStringLiteral("Sink1"), QString(), QPointF(100, 300));
    m_stack->push(new AddComponentCommand(m_model.get(), record, rtc));
    ComponentItem *item = m_scene->componentItem(QStringLiteral("Sink1"));
    QVERIFY(item);
    QCOMPARE(item->pos(), QPointF(100, 300));
    QCOMPARE(item->portItems().size(), 1);
    m_stack->undo();
    QVERIFY(!m_scene->componentItem(QStringLiteral("Sink1")));
    QCOMPARE(m_scene->componentItemCount(), 3);
    m_stack->redo();
    QVERIFY(m_scene->componentItem(QStringLiteral("Sink1")));
}

void TestSeCanvasScene::renameKeepsItemAndConnector()
{
    ComponentItem *item = m_scene->componentItem(QStringLiteral("Sensor0"));
    QVERIFY(m_scene->renameComponent(QStringLiteral("Sensor0"), QStringLiteral("Camera")));
    QCOMPARE(m_scene->componentItem(QStringLiteral("Camera")), item);
    QVERIFY(!m_scene->componentItem(QStringLiteral("Sensor0")));
    QCOMPARE(item->appearance().instanceName, QStringLiteral("Camera"));
    ConnectorItem *connector = m_scene->connectorItem(QStringLiteral("c-sensor-filter"));
    QCOMPARE(connector->info().source.instanceName, QStringLiteral("Camera"));
    QVERIFY(connector->sourcePort());
    QCOMPARE(connector->sourcePort()->parentItem(), item);
    // A taken name is refused without an undo step.
    QVERIFY(!m_scene->renameComponent(QStringLiteral("Camera"), QStringLiteral("Filter0")));
    QCOMPARE(m_stack->count(), 1);
    m_stack->undo();
    QCOMPARE(m_scene->componentItem(QStringLiteral("Sensor0")), item);
    QCOMPARE(item->appearance().instanceName, QStringLiteral("Sensor0"));
    QCOMPARE(connector->sourcePort()->parentItem(), item);
}

void TestSeCanvasScene::moveFollowsUndo()
{
    ComponentItem *item = m_scene->componentItem(QStringLiteral("Sink0"));
    m_stack->push(new MoveComponentsCommand(m_model.get(),
                                            {{QStringLiteral("Sink0"), QPointF(500, 400)}}));
    QCOMPARE(item->pos(), QPointF(500, 400));
    m_stack->undo();
    QCOMPARE(item->pos(), QPointF(600, 60));
    m_stack->redo();
    QCOMPARE(item->pos(), QPointF(500, 400));
}

void TestSeCanvasScene::removalTakesConnectorsAndUndoRestores()
{
    m_scene->selectComponents({QStringLiteral("Filter0")});
    m_scene->deleteSelection();
    QVERIFY(!m_scene->componentItem(QStringLiteral("Filter0")));
    QCOMPARE(m_scene->connectorItemCount(), 0);
    // The other end is no longer connected: blue again.
    const PortItem *out
        = m_scene->portItem({QStringLiteral("Sensor0"), QStringLiteral("Sensor0.out")});
    QVERIFY(!out->isConnected());
    m_stack->undo();
    QVERIFY(m_scene->componentItem(QStringLiteral("Filter0")));
    QCOMPARE(m_scene->connectorItemCount(), 1);
    QVERIFY(m_scene->portItem({QStringLiteral("Sensor0"), QStringLiteral("Sensor0.out")})
                ->isConnected());
    QVERIFY(m_scene->connectorItem(QStringLiteral("c-sensor-filter"))->targetPort());
}

void TestSeCanvasScene::portSides_data()
{
    QTest::addColumn<QString>("instance");
    QTest::addColumn<QString>("port");
    QTest::addColumn<PortSide>("side");
    // Sensor0 faces RIGHT: the profile's sides as they are.
    QTest::newRow("right out") << "Sensor0" << "Sensor0.out" << PortSide::Right;
    QTest::newRow("right bottom") << "Sensor0" << "Sensor0.status" << PortSide::Bottom;
    QTest::newRow("right service") << "Sensor0" << "Sensor0.control" << PortSide::Left;
    // Filter0 faces LEFT: mirrored.
    QTest::newRow("left in") << "Filter0" << "Filter0.in" << PortSide::Right;
    QTest::newRow("left out") << "Filter0" << "Filter0.out" << PortSide::Left;
    QTest::newRow("left top") << "Filter0" << "Filter0.text" << PortSide::Top;
    QTest::newRow("left bottom") << "Filter0" << "Filter0.control" << PortSide::Bottom;
    // Sink0 faces DOWN: its left side is on top.
    QTest::newRow("down in") << "Sink0" << "Sink0.in" << PortSide::Top;
}

void TestSeCanvasScene::portSides()
{
    QFETCH(QString, instance);
    QFETCH(QString, port);
    QFETCH(PortSide, side);
    const ComponentItem *component = m_scene->componentItem(instance);
    const PortItem *item = component->portItem(port);
    QVERIFY(item);
    QCOMPARE(item->port().side, side);
    QCOMPARE(measuredSide(component, item), side);
}

void TestSeCanvasScene::turningMovesPorts()
{
    ComponentItem *sensor = m_scene->componentItem(QStringLiteral("Sensor0"));
    m_scene->selectComponents({QStringLiteral("Sensor0")});
    m_scene->setDirectionOfSelection(Direction::Left);
    PortItem *out = sensor->portItem(QStringLiteral("Sensor0.out"));
    QCOMPARE(measuredSide(sensor, out), PortSide::Left);
    QCOMPARE(measuredSide(sensor, sensor->portItem(QStringLiteral("Sensor0.control"))),
             PortSide::Right);
    // The connector follows the port to its new side.
    const QPolygonF route = m_scene->connectorItem(QStringLiteral("c-sensor-filter"))->route();
    QCOMPARE(route.first(), out->connectionPoint());
    m_scene->setDirectionOfSelection(Direction::Up);
    QCOMPARE(measuredSide(sensor, sensor->portItem(QStringLiteral("Sensor0.out"))), PortSide::Top);
    m_stack->undo();
    m_stack->undo();
    QCOMPARE(measuredSide(sensor, sensor->portItem(QStringLiteral("Sensor0.out"))),
             PortSide::Right);
}

void TestSeCanvasScene::portColoursFollowConnections()
{
    const PortItem *connected
        = m_scene->portItem({QStringLiteral("Filter0"), QStringLiteral("Filter0.in")});
    const PortItem *free
        = m_scene->portItem({QStringLiteral("Filter0"), QStringLiteral("Filter0.out")});
    const PortItem *service
        = m_scene->portItem({QStringLiteral("Filter0"), QStringLiteral("Filter0.control")});
    QCOMPARE(connected->brush().color(), portColor(PortKind::DataIn, true));
    QCOMPARE(free->brush().color(), portColor(PortKind::DataOut, false));
    QCOMPARE(service->brush().color(), portColor(PortKind::Service, false));
    QVERIFY(portColor(PortKind::DataIn, true) != portColor(PortKind::DataIn, false));
    QVERIFY(portColor(PortKind::Service, true) != portColor(PortKind::Service, false));
    // Shapes differ by kind.
    QVERIFY(portShape(PortKind::DataIn, PortSide::Left)
            != portShape(PortKind::DataOut, PortSide::Left));
    QVERIFY(portShape(PortKind::Service, PortSide::Left)
            != portShape(PortKind::DataOut, PortSide::Left));
}

void TestSeCanvasScene::toolTipsNameTypes()
{
    const PortItem *data
        = m_scene->portItem({QStringLiteral("Sensor0"), QStringLiteral("Sensor0.status")});
    QVERIFY(data->toolTip().contains(QStringLiteral("RTC::TimedString")));
    QVERIFY(data->toolTip().contains(QStringLiteral("OutPort")));
    const PortItem *service
        = m_scene->portItem({QStringLiteral("Sensor0"), QStringLiteral("Sensor0.control")});
    QVERIFY(service->toolTip().contains(QStringLiteral("Demo::Control")));
    QVERIFY(service->toolTip().contains(QStringLiteral("provided")));
}

void TestSeCanvasScene::resizeKeepsPortsLaidOut()
{
    ComponentItem *filter = m_scene->componentItem(QStringLiteral("Filter0"));
    const QSizeF before = filter->bodyRect().size();
    const QSizeF larger(before.width() * 2, before.height() * 3);
    m_stack->push(new ResizeComponentCommand(m_model.get(), QStringLiteral("Filter0"), larger));
    QCOMPARE(filter->bodyRect().size(), larger);
    for (PortItem *port : filter->portItems()) {
        const QPointF at = port->pos();
        const QRectF body = filter->bodyRect();
        const bool onVerticalEdge = qFuzzyCompare(std::abs(at.x() - body.left()) + 1, PortHalfSize + 1)
            || qFuzzyCompare(std::abs(at.x() - body.right()) + 1, PortHalfSize + 1);
        const bool onHorizontalEdge = qFuzzyCompare(std::abs(at.y() - body.top()) + 1, PortHalfSize + 1)
            || qFuzzyCompare(std::abs(at.y() - body.bottom()) + 1, PortHalfSize + 1);
        QVERIFY2(onVerticalEdge || onHorizontalEdge, qPrintable(port->port().name));
    }
    // Too small a size is grown to what the ports need.
    m_stack->push(new ResizeComponentCommand(m_model.get(), QStringLiteral("Filter0"),
                                             QSizeF(10, 10)));
    QCOMPARE(filter->bodyRect().size(), before);
    m_stack->undo();
    m_stack->undo();
    QCOMPARE(filter->bodyRect().size(), before);
}

void TestSeCanvasScene::connectorFollowsComponent()
{
    ConnectorItem *connector = m_scene->connectorItem(QStringLiteral("c-sensor-filter"));
    const QPointF before = connector->route().last();
    ComponentItem *filter = m_scene->componentItem(QStringLiteral("Filter0"));
    // A drag in progress (item moved, model not yet) already reroutes.
    filter->setPos(filter->pos() + QPointF(0, 100));
    QCOMPARE(connector->route().last(), before + QPointF(0, 100));
    QCOMPARE(connector->route().last(), connector->targetPort()->connectionPoint());
}

void TestSeCanvasScene::bendPointsShapeTheRoute()
{
    ConnectorItem *connector = m_scene->connectorItem(QStringLiteral("c-sensor-filter"));
    QCOMPARE(connector->sourcePort()->port().side, PortSide::Right);
    QCOMPARE(connector->targetPort()->port().side, PortSide::Right);
    // Corners as this editor saves them: a right-angled path from one port's lead to the other's.
    const qreal startY = qRound(connector->route().first().y());
    const qreal endY = qRound(connector->route().last().y());
    const QList<QPointF> bends {QPointF(200, startY), QPointF(200, 300), QPointF(700, 300),
                                QPointF(700, endY)};
    m_stack->push(new SetBendPointsCommand(m_model.get(), QStringLiteral("c-sensor-filter"), bends));
    QCOMPARE(connector->info().bendPoints, bends);
    for (const QPointF &bend : bends)
        QVERIFY(connector->route().contains(bend));
    m_stack->undo();
    QVERIFY(connector->info().bendPoints.isEmpty());
    QVERIFY(!connector->route().contains(bends.first()));
}

void TestSeCanvasScene::routesAreManhattan_data()
{
    QTest::addColumn<QPointF>("start");
    QTest::addColumn<PortSide>("startSide");
    QTest::addColumn<QPointF>("end");
    QTest::addColumn<PortSide>("endSide");
    QTest::addColumn<QList<QPointF>>("bends");
    QTest::newRow("facing") << QPointF(0, 0) << PortSide::Right << QPointF(200, 80)
                            << PortSide::Left << QList<QPointF>();
    QTest::newRow("backwards") << QPointF(200, 0) << PortSide::Right << QPointF(0, 80)
                               << PortSide::Left << QList<QPointF>();
    QTest::newRow("facing away") << QPointF(0, 0) << PortSide::Right << QPointF(300, 0)
                                 << PortSide::Right << QList<QPointF>();
    QTest::newRow("perpendicular") << QPointF(0, 0) << PortSide::Right << QPointF(200, 100)
                                   << PortSide::Top << QList<QPointF>();
    QTest::newRow("top to bottom") << QPointF(0, 0) << PortSide::Bottom << QPointF(50, 200)
                                   << PortSide::Top << QList<QPointF>();
    QTest::newRow("bends") << QPointF(0, 0) << PortSide::Right << QPointF(300, 10)
                           << PortSide::Left << QList<QPointF> {{100, 90}, {170, 130}};
}

void TestSeCanvasScene::routesAreManhattan()
{
    QFETCH(QPointF, start);
    QFETCH(PortSide, startSide);
    QFETCH(QPointF, end);
    QFETCH(PortSide, endSide);
    QFETCH(QList<QPointF>, bends);
    const QPolygonF route = manhattanRoute(start, startSide, end, endSide, bends);
    QCOMPARE(route.first(), start);
    QCOMPARE(route.last(), end);
    for (int i = 1; i < route.size(); ++i) {
        const QPointF a = route.at(i - 1);
        const QPointF b = route.at(i);
        QVERIFY2(qFuzzyCompare(a.x(), b.x()) || qFuzzyCompare(a.y(), b.y()),
                 qPrintable(QStringLiteral("segment %1 is diagonal").arg(i)));
    }
    // It leaves and enters straight out of the ports' sides.
    const QPointF first = route.at(1) - route.at(0);
    QVERIFY(QPointF::dotProduct(first, outwardNormal(startSide)) > 0);
    const QPointF last = route.at(route.size() - 2) - route.last();
    QVERIFY(QPointF::dotProduct(last, outwardNormal(endSide)) > 0);
    for (const QPointF &bend : bends)
        QVERIFY(route.contains(bend));
}

void TestSeCanvasScene::routeGoesRoundBodiesFacingAway()
{
    // Filter0 faces LEFT, so its InPort is on its far side from Sensor0's OutPort.
    const QPolygonF route = m_scene->connectorItem(QStringLiteral("c-sensor-filter"))->route();
    const QRectF filterBody = m_scene->componentItem(QStringLiteral("Filter0"))
                                  ->mapRectToScene(m_scene->componentItem(QStringLiteral("Filter0"))
                                                       ->bodyRect());
    for (int i = 1; i < route.size(); ++i) {
        const QRectF segment = QRectF(route.at(i - 1), route.at(i)).normalized().adjusted(-0.5, -0.5,
                                                                                          0.5, 0.5);
        QVERIFY2(!segment.intersects(filterBody.adjusted(1, 1, -1, -1)),
                 qPrintable(QStringLiteral("segment %1 crosses the body").arg(i)));
    }
    QCOMPARE(route.last(), m_scene->portItem({QStringLiteral("Filter0"), QStringLiteral("Filter0.in")})
                               ->connectionPoint());
}

void TestSeCanvasScene::rtSystemEditorBendPointsMoveSegments()
{
    // Ports facing each other: RT System Editor's automatic route and ours are start, two
    // corners halfway, end; its BEND_POINT keys are those segments (0 leaves the start).
    const QPointF start(100, 100);
    const QPointF end(300, 200);
    const QPolygonF automatic = manhattanRoute(start, PortSide::Right, end, PortSide::Left);
    QCOMPARE(automatic, QPolygonF({start, QPointF(200, 100), QPointF(200, 200), end}));
    // Segment 1 (vertical) takes the entry's x only; the point's y is where the handle was let go.
    QCOMPARE(savedRouteCorners(start, PortSide::Right, end, PortSide::Left,
                               {{1, QPointF(150, 170)}}),
             QList<QPointF>({QPointF(150, 100), QPointF(150, 200)}));
    // Segment 2 (horizontal, entering the end) takes its y; segments it does not have are ignored.
    QCOMPARE(constrainedRoute(automatic, {{2, QPointF(0, 220)}, {9, QPointF(5, 5)}}),
             QPolygonF({start, QPointF(200, 100), QPointF(200, 220), QPointF(300, 220)}));
    // A straight route gets RT System Editor's zero-length jog halfway, which can be moved.
    QCOMPARE(constrainedRoute(QPolygonF({start, QPointF(300, 100)}), {{1, QPointF(260, 0)}}),
             QPolygonF({start, QPointF(260, 100), QPointF(260, 100), QPointF(300, 100)}));
}

void TestSeCanvasScene::savedCornersReadBackInBothForms()
{
    const QPointF start(100, 100);
    const QPointF end(300, 200);
    // A route dragged in this editor is saved as its corners keyed 1…n and reads back as such.
    const QList<QPointF> dragged {QPointF(116, 100), QPointF(116, 40), QPointF(250, 40),
                                  QPointF(250, 200)};
    const QPolygonF route = manhattanRoute(start, PortSide::Right, end, PortSide::Left, dragged);
    const std::optional<QMap<int, QPointF>> saved
        = bendPointEntriesFromText(bendPointsToText(routeCorners(route)));
    QVERIFY(saved);
    QCOMPARE(saved->firstKey(), 1);
    QCOMPARE(savedRouteCorners(start, PortSide::Right, end, PortSide::Left, *saved),
             routeCorners(route));
    // RT System Editor reads corner i as a point of its segment i: a route with its automatic
    // route's segments opens there as drawn here.
    const QList<QPointF> moved {QPointF(150, 100), QPointF(150, 200)};
    const QPolygonF ours = manhattanRoute(start, PortSide::Right, end, PortSide::Left, moved);
    const std::optional<QMap<int, QPointF>> written
        = bendPointEntriesFromText(bendPointsToText(routeCorners(ours)));
    QVERIFY(written);
    QCOMPARE(constrainedRoute(manhattanRoute(start, PortSide::Right, end, PortSide::Left),
                              *written),
             ours);
}

void TestSeCanvasScene::rtSystemEditorFileRoutesAndSavesUnchanged()
{
    const QString path = SeCanvasTest::dataPath(QStringLiteral("rtsebendpoints.xml"));
    std::unique_ptr<SystemModel> model = loadModel(path);
    QVERIFY(model);
    const Profile::RtsProfile loaded = model->profile();
    {
        const SystemScene scene(model.get(), nullptr);
        // Drawn where RT System Editor drew it: its middle segment moved to x = 230.
        const QPolygonF route = scene.connectorItem(QStringLiteral("c-sensor-filter"))->route();
        QCOMPARE(route.size(), 4);
        QCOMPARE(route.at(1), QPointF(230, route.first().y()));
        QCOMPARE(route.at(2), QPointF(230, route.last().y()));
        QVERIFY(route.first().y() < route.last().y());
    }
    QTemporaryDir dir;
    const QString savedPath = dir.filePath(QStringLiteral("rtsebendpoints.xml"));
    Profile::Diagnostics diagnostics;
    QVERIFY(saveSystemFile(*model, savedPath, &diagnostics));
    const std::unique_ptr<SystemModel> again = loadModel(savedPath);
    QVERIFY(again);
    QCOMPARE(Profile::rtsPropertyValue(
                 again->dataConnector(QStringLiteral("c-sensor-filter"))->properties,
                 SystemModel::BendPointProperty),
             std::optional<QString>(QStringLiteral("{1:(230,150)}")));
    QCOMPARE(again->profile().dataPortConnectors, loaded.dataPortConnectors);
    QCOMPARE(again->profile().components.size(), loaded.components.size());
}

QTEST_MAIN(TestSeCanvasScene)
#include "tst_secanvasscene.moc"
