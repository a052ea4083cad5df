// SPDX-License-Identifier: MIT
// The canvas view driven with mouse and keys on its viewport: connecting by dragging (legal
// targets highlighted, illegal drops refused with a reason), moving, rubber-band selection and
// delete, zoom and fit, inline rename, find, copy and paste.
#include "tst_secanvassupport.h"

#include "instancecommands.h"
#include "componentitem.h"
#include "connectoritem.h"
#include "portitem.h"
#include "systemscene.h"
#include "systemview.h"

#include <QApplication>
#include <QLineEdit>
#include <QScrollBar>
#include <QSignalSpy>
#include <QUndoStack>
#include <QWheelEvent>

using namespace SystemEditor;
using SeCanvasTest::loadModel;

class TestSeCanvasView : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void dragConnectAsksDialogAndConnects();
    void dragHighlightsLegalTargetsOnly();
    void illegalDropSaysWhy();
    void cancelledDialogConnectsNothing();
    void serviceDragAsksNameAndConnects();
    void doubleClickEditsConnector();
    void mouseMoveIsOneUndoStep();
    void rubberBandSelectDeleteUndo();
    void zoomWithKeysWheelAndFit();
    void inlineRename();
    void findComponent();
    void copyPaste();
    void arrowKeysNudge();
    void resizeHandleResizes();
    void draggingACornerSavesBendPoints();
    void middleButtonPans();
    void spaceDragPans();
    void alignLinesUpSelection();

private:
    QPoint viewPos(const QPointF &scenePos) const { return m_view->mapFromScene(scenePos); }
    QPoint portPos(const QString &instance, const QString &port) const;
    void dragOnViewport(const QPoint &from, const QPoint &to,
                        const std::function<void()> &halfway = {});

    std::unique_ptr<SystemModel> m_model;
    std::unique_ptr<QUndoStack> m_stack;
    std::unique_ptr<SystemScene> m_scene;
    std::unique_ptr<SystemView> m_view;
    QList<ConnectorSettings> m_asked;
    QList<ConnectorDialog::Choices> m_choices;
    std::optional<ConnectorSettings> m_answer;
};

void TestSeCanvasView::init()
{
    m_model = loadModel();
    QVERIFY(m_model);
    m_stack = std::make_unique<QUndoStack>();
    m_scene = std::make_unique<SystemScene>(m_model.get(), m_stack.get());
    m_view = std::make_unique<SystemView>(m_scene.get());
    m_asked.clear();
    m_answer.reset();
    // The dialog, answered by the test: record what was proposed, answer m_answer.
    m_choices.clear();
    m_view->setConnectorEditor([this](const ConnectorSettings &proposed,
                                      const ConnectorDialog::Choices &choices) {
        m_asked.append(proposed);
        m_choices.append(choices);
        return m_answer;
    });
    m_view->resize(1100, 600);
    m_view->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
    m_view->centerOn(m_scene->diagramRect().center());
}

void TestSeCanvasView::cleanup()
{
    m_view.reset();
    m_scene.reset();
    m_stack.reset();
    m_model.reset();
}

QPoint TestSeCanvasView::portPos(const QString &instance, const QString &port) const
{
    const PortItem *item = m_scene->portItem({instance, port});
    return item ? viewPos(item->scenePos()) : QPoint();
}

void TestSeCanvasView::dragOnViewport(const QPoint &from, const QPoint &to,
                                      const std::function<void()> &halfway)
{
    QWidget *viewport = m_view->viewport();
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    const QPoint middle = (from + to) / 2;
    QTest::mouseMove(viewport, from + QPoint(5, 5));
    QTest::mouseMove(viewport, middle);
    QTest::mouseMove(viewport, to);
    if (halfway)
        halfway();
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, to);
}

void TestSeCanvasView::dragConnectAsksDialogAndConnects()
{
    ConnectorSettings answer = ConnectorSettings::defaults(QStringLiteral("out"),
                                                           QStringLiteral("in"),
                                                           QStringLiteral("RTC::TimedLong"));
    answer.name = QStringLiteral("filter_sink");
    answer.inBuffer.length = QStringLiteral("16");
    m_answer = answer;
    dragOnViewport(portPos(QStringLiteral("Filter0"), QStringLiteral("Filter0.out")),
                   portPos(QStringLiteral("Sink0"), QStringLiteral("Sink0.in")));
    QCOMPARE(m_asked.size(), 1);
    QCOMPARE(m_asked.first().name, QStringLiteral("out_in"));
    QCOMPARE(m_asked.first().dataType, QStringLiteral("RTC::TimedLong"));
    QCOMPARE(m_model->connectorIds().size(), 2);
    const std::optional<ConnectorInfo> made = m_model->connector(m_model->connectorIds().last());
    QVERIFY(made);
    QCOMPARE(made->name, QStringLiteral("filter_sink"));
    QCOMPARE(made->source, (ConnectorEnd {QStringLiteral("Filter0"), QStringLiteral("Filter0.out")}));
    QCOMPARE(made->target, (ConnectorEnd {QStringLiteral("Sink0"), QStringLiteral("Sink0.in")}));
    QCOMPARE(Profile::rtsPropertyValue(m_model->dataConnector(made->id)->properties,
                                       QStringLiteral("dataport.inport.buffer.length")),
             QStringLiteral("16"));
    QVERIFY(m_scene->connectorItem(made->id));
    QVERIFY(m_scene->portItem({QStringLiteral("Sink0"), QStringLiteral("Sink0.in")})->isConnected());
    QVERIFY(!m_scene->isConnecting());
    m_stack->undo();
    QCOMPARE(m_model->connectorIds().size(), 1);
    QVERIFY(!m_scene->connectorItem(made->id));
    m_stack->redo();
    QVERIFY(m_scene->connectorItem(made->id));
}

void TestSeCanvasView::dragHighlightsLegalTargetsOnly()
{
    const auto highlight = [this](const QString &instance, const QString &port) {
        return m_scene->portItem({instance, port})->highlight();
    };
    bool checked = false;
    dragOnViewport(portPos(QStringLiteral("Sensor0"), QStringLiteral("Sensor0.status")),
                   QPoint(5, 5), [&] {
                       QVERIFY(m_scene->isConnecting());
                       QCOMPARE(highlight(QStringLiteral("Filter0"), QStringLiteral("Filter0.text")),
                                PortItem::Highlight::Legal);
                       // Wrong data type, wrong direction, a service port.
                       QCOMPARE(highlight(QStringLiteral("Sink0"), QStringLiteral("Sink0.in")),
                                PortItem::Highlight::Illegal);
                       QCOMPARE(highlight(QStringLiteral("Filter0"), QStringLiteral("Filter0.out")),
                                PortItem::Highlight::Illegal);
                       QCOMPARE(highlight(QStringLiteral("Filter0"),
                                          QStringLiteral("Filter0.control")),
                                PortItem::Highlight::Illegal);
                       checked = true;
                   });
    QVERIFY(checked);
    QCOMPARE(highlight(QStringLiteral("Filter0"), QStringLiteral("Filter0.text")),
             PortItem::Highlight::None);
    QVERIFY(m_asked.isEmpty());
    QCOMPARE(m_stack->count(), 0);
}

void TestSeCanvasView::illegalDropSaysWhy()
{
    QSignalSpy refused(m_scene.get(), &SystemScene::connectionRefused);
    QSignalSpy status(m_view.get(), &SystemView::statusMessage);
    dragOnViewport(portPos(QStringLiteral("Sensor0"), QStringLiteral("Sensor0.status")),
                   portPos(QStringLiteral("Sink0"), QStringLiteral("Sink0.in")));
    QCOMPARE(refused.size(), 1);
    const QString reason = refused.first().first().toString();
    QVERIFY(!reason.isEmpty());
    QCOMPARE(m_scene->lastRefusal(), reason);
    QVERIFY(!status.isEmpty());
    QCOMPARE(status.last().first().toString(), reason);
    QVERIFY(m_asked.isEmpty());
    QCOMPARE(m_model->connectorIds().size(), 1);
    QCOMPARE(m_stack->count(), 0);
}

void TestSeCanvasView::cancelledDialogConnectsNothing()
{
    dragOnViewport(portPos(QStringLiteral("Filter0"), QStringLiteral("Filter0.out")),
                   portPos(QStringLiteral("Sink0"), QStringLiteral("Sink0.in")));
    QCOMPARE(m_asked.size(), 1);
    QCOMPARE(m_model->connectorIds().size(), 1);
    QCOMPARE(m_stack->count(), 0);
}

void TestSeCanvasView::serviceDragAsksNameAndConnects()
{
    QStringList proposed;
    QList<QList<InterfaceInfo>> shown;
    m_view->setServiceConnectorEditor([&](const ServiceConnectorSettings &settings,
                                          const ServicePortSide &source,
                                          const ServicePortSide &target) {
        proposed << settings.name;
        shown << source.interfaces << target.interfaces;
        ServiceConnectorSettings answer = settings;
        answer.name = QStringLiteral("control_link");
        return std::optional<ServiceConnectorSettings>(answer);
    });
    dragOnViewport(portPos(QStringLiteral("Filter0"), QStringLiteral("Filter0.control")),
                   portPos(QStringLiteral("Sensor0"), QStringLiteral("Sensor0.control")));
    QCOMPARE(proposed, QStringList {QStringLiteral("control_control")});
    QCOMPARE(shown.size(), 2);
    QCOMPARE(shown.at(0).size(), 1);
    QVERIFY(m_asked.isEmpty());
    QCOMPARE(m_model->connectorIds().size(), 2);
    const std::optional<ConnectorInfo> made = m_model->connector(m_model->connectorIds().last());
    QCOMPARE(made->kind, ConnectorKind::Service);
    QCOMPARE(made->name, QStringLiteral("control_link"));
    QVERIFY(m_scene->portItem({QStringLiteral("Sensor0"), QStringLiteral("Sensor0.control")})
                ->isConnected());
    m_stack->undo();
    QCOMPARE(m_model->connectorIds().size(), 1);
}

void TestSeCanvasView::doubleClickEditsConnector()
{
    ConnectorItem *connector = m_scene->connectorItem(QStringLiteral("c-sensor-filter"));
    const QPolygonF route = connector->route();
    const QPoint onLine = viewPos((route.at(1) + route.at(2)) / 2);
    ConnectorSettings answer = ConnectorSettings::fromConnector(
        *m_model->dataConnector(QStringLiteral("c-sensor-filter")));
    answer.name = QStringLiteral("renamed");
    m_answer = answer;
    QTest::mouseDClick(m_view->viewport(), Qt::LeftButton, {}, onLine);
    QCOMPARE(m_asked.size(), 1);
    QCOMPARE(m_asked.first().name, QStringLiteral("out_in"));
    // The choices are what both ports' RTC profiles offer (push,pull; flush,new,periodic).
    QCOMPARE(m_choices.first().dataflowTypes,
             (QStringList {QStringLiteral("push"), QStringLiteral("pull")}));
    QCOMPARE(m_choices.first().interfaceTypes, QStringList {QStringLiteral("corba_cdr")});
    QCOMPARE(m_model->connector(QStringLiteral("c-sensor-filter"))->name, QStringLiteral("renamed"));
    m_stack->undo();
    QCOMPARE(m_model->connector(QStringLiteral("c-sensor-filter"))->name, QStringLiteral("out_in"));
}

void TestSeCanvasView::mouseMoveIsOneUndoStep()
{
    ComponentItem *sink = m_scene->componentItem(QStringLiteral("Sink0"));
    const QPoint from = viewPos(sink->mapToScene(sink->bodyRect().center()));
    dragOnViewport(from, from + QPoint(103, 38));
    QCOMPARE(m_stack->count(), 1);
    // Snapped to the grid.
    QCOMPARE(m_model->layout(QStringLiteral("Sink0")).position, QPointF(700, 100));
    QCOMPARE(sink->pos(), QPointF(700, 100));
    m_stack->undo();
    QCOMPARE(sink->pos(), QPointF(600, 60));
}

void TestSeCanvasView::rubberBandSelectDeleteUndo()
{
    const QRectF around = m_scene->componentItem(QStringLiteral("Sensor0"))->sceneBoundingRect()
                              .united(m_scene->componentItem(QStringLiteral("Filter0"))
                                          ->sceneBoundingRect());
    dragOnViewport(viewPos(around.topLeft() - QPointF(15, 15)),
                   viewPos(around.bottomRight() + QPointF(15, 15)));
    QCOMPARE(m_scene->selectedComponents(),
             (QStringList {QStringLiteral("Sensor0"), QStringLiteral("Filter0")}));
    QCOMPARE(m_stack->count(), 0);
    m_scene->deleteSelection();
    QCOMPARE(m_model->componentIds(), QStringList {QStringLiteral("Sink0")});
    QCOMPARE(m_scene->componentItemCount(), 1);
    QCOMPARE(m_scene->connectorItemCount(), 0);
    QCOMPARE(m_stack->count(), 1);
    m_stack->undo();
    QCOMPARE(m_model->componentIds().size(), 3);
    QCOMPARE(m_scene->componentItemCount(), 3);
    QCOMPARE(m_scene->connectorItemCount(), 1);
    QVERIFY(m_scene->connectorItem(QStringLiteral("c-sensor-filter"))->sourcePort());
}

void TestSeCanvasView::zoomWithKeysWheelAndFit()
{
    QCOMPARE(m_view->zoomFactor(), 1.0);
    QTest::keyClick(m_view.get(), Qt::Key_Plus);
    QCOMPARE(m_view->zoomFactor(), 1.25);
    QTest::keyClick(m_view.get(), Qt::Key_Minus);
    QTest::keyClick(m_view.get(), Qt::Key_Minus);
    QCOMPARE(m_view->zoomFactor(), 0.8);
    QTest::keyClick(m_view.get(), Qt::Key_0);
    QCOMPARE(m_view->zoomFactor(), 1.0);
    const QPointF at = m_view->viewport()->rect().center();
    QWheelEvent wheel(at, m_view->viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::ControlModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(m_view->viewport(), &wheel);
    QCOMPARE(m_view->zoomFactor(), 1.25);
    // Without Ctrl the wheel scrolls.
    QWheelEvent scroll(at, m_view->viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120),
                       Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(m_view->viewport(), &scroll);
    QCOMPARE(m_view->zoomFactor(), 1.25);
    // Fit: far apart components still all show.
    m_stack->push(new MoveComponentsCommand(m_model.get(),
                                            {{QStringLiteral("Sink0"), QPointF(3000, 2000)}}));
    m_view->fitToDiagram();
    QVERIFY(m_view->zoomFactor() < 0.5);
    const QRect visible = m_view->viewport()->rect();
    for (const QString &name : m_model->componentIds()) {
        const QRect item = m_view->mapFromScene(m_scene->componentItem(name)->sceneBoundingRect())
                               .boundingRect();
        QVERIFY2(visible.contains(item), qPrintable(name));
    }
}

void TestSeCanvasView::inlineRename()
{
    m_scene->selectComponents({QStringLiteral("Sink0")});
    m_view->startRename();
    QLineEdit *editor = m_view->renameEditor();
    QVERIFY(editor);
    QCOMPARE(editor->text(), QStringLiteral("Sink0"));
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("Display"));
    QTest::keyClick(editor, Qt::Key_Return);
    QVERIFY(!m_view->renameEditor());
    QVERIFY(m_model->hasComponent(QStringLiteral("Display")));
    QVERIFY(m_scene->componentItem(QStringLiteral("Display")));
    QCOMPARE(m_stack->count(), 1);
    // Escape leaves the name alone.
    m_scene->selectComponents({QStringLiteral("Display")});
    m_view->startRename();
    QTest::keyClicks(m_view->renameEditor(), QStringLiteral("Other"));
    QTest::keyClick(m_view->renameEditor(), Qt::Key_Escape);
    QVERIFY(!m_view->renameEditor());
    QVERIFY(m_model->hasComponent(QStringLiteral("Display")));
    QCOMPARE(m_stack->count(), 1);
    m_stack->undo();
    QVERIFY(m_model->hasComponent(QStringLiteral("Sink0")));
}

void TestSeCanvasView::findComponent()
{
    QVERIFY(m_view->findComponent(QStringLiteral("filt")));
    QCOMPARE(m_scene->selectedComponents(), QStringList {QStringLiteral("Filter0")});
    QVERIFY(m_view->viewport()->rect().contains(
        viewPos(m_scene->componentItem(QStringLiteral("Filter0"))->sceneBoundingRect().center())));
    QVERIFY(!m_view->findComponent(QStringLiteral("nothing")));
    QCOMPARE(m_scene->selectedComponents(), QStringList {QStringLiteral("Filter0")});
}

void TestSeCanvasView::copyPaste()
{
    m_scene->selectComponents({QStringLiteral("Sensor0"), QStringLiteral("Filter0")});
    m_scene->copySelection();
    QVERIFY(SystemScene::canPaste());
    QVERIFY(m_scene->paste());
    QCOMPARE(m_model->componentIds().size(), 5);
    QCOMPARE(m_model->connectorIds().size(), 2);
    QCOMPARE(m_scene->componentItemCount(), 5);
    QCOMPARE(m_scene->connectorItemCount(), 2);
    QCOMPARE(m_scene->selectedComponents().size(), 2);
    // The pasted connector joins the pasted components.
    const std::optional<ConnectorInfo> pasted = m_model->connector(m_model->connectorIds().last());
    QVERIFY(m_scene->selectedComponents().contains(pasted->source.instanceName));
    QVERIFY(m_scene->connectorItem(pasted->id)->sourcePort());
    m_stack->undo();
    QCOMPARE(m_scene->componentItemCount(), 3);
    QCOMPARE(m_scene->connectorItemCount(), 1);
}

void TestSeCanvasView::arrowKeysNudge()
{
    m_scene->selectComponents({QStringLiteral("Sink0")});
    m_view->setFocus();
    QTest::keyClick(m_view.get(), Qt::Key_Right);
    QTest::keyClick(m_view.get(), Qt::Key_Right);
    QTest::keyClick(m_view.get(), Qt::Key_Down, Qt::ShiftModifier);
    QCOMPARE(m_model->layout(QStringLiteral("Sink0")).position, QPointF(640, 61));
    // Nudges of the same selection merge into one step.
    QCOMPARE(m_stack->count(), 1);
    m_stack->undo();
    QCOMPARE(m_model->layout(QStringLiteral("Sink0")).position, QPointF(600, 60));
}

void TestSeCanvasView::resizeHandleResizes()
{
    ComponentItem *sink = m_scene->componentItem(QStringLiteral("Sink0"));
    const QSizeF before = sink->bodyRect().size();
    m_scene->selectComponents({QStringLiteral("Sink0")});
    const QPoint handle = viewPos(sink->mapToScene(sink->resizeHandleRect().center()));
    dragOnViewport(handle, handle + QPoint(60, 40));
    QCOMPARE(m_stack->count(), 1);
    QCOMPARE(m_model->layout(QStringLiteral("Sink0")).size, before + QSizeF(60, 40));
    QCOMPARE(sink->bodyRect().size(), before + QSizeF(60, 40));
    // Its port stays centred on the (new) top edge.
    const PortItem *in = sink->portItem(QStringLiteral("Sink0.in"));
    QCOMPARE(in->pos().x(), sink->bodyRect().center().x());
    // Resizing did not move it.
    QCOMPARE(sink->pos(), QPointF(600, 60));
    m_stack->undo();
    QCOMPARE(sink->bodyRect().size(), before);
}

void TestSeCanvasView::draggingACornerSavesBendPoints()
{
    ConnectorItem *connector = m_scene->connectorItem(QStringLiteral("c-sensor-filter"));
    connector->setSelected(true);
    const QPolygonF route = connector->route();
    QVERIFY(route.size() > 3);
    const QPointF corner = route.at(2);
    QCOMPARE(connector->handleAt(corner), 1);
    dragOnViewport(viewPos(corner), viewPos(corner + QPointF(0, 60)));
    QCOMPARE(m_stack->count(), 1);
    const std::optional<ConnectorInfo> info = m_model->connector(QStringLiteral("c-sensor-filter"));
    QVERIFY(!info->bendPoints.isEmpty());
    QVERIFY(info->bendPoints.contains(corner + QPointF(0, 60)));
    QVERIFY(Profile::rtsPropertyValue(
        m_model->dataConnector(QStringLiteral("c-sensor-filter"))->properties,
        SystemModel::BendPointProperty));
    QVERIFY(connector->route().contains(corner + QPointF(0, 60)));
    // Nothing else moved.
    QCOMPARE(m_scene->componentItem(QStringLiteral("Filter0"))->pos(), QPointF(320, 60));
    m_stack->undo();
    QVERIFY(m_model->connector(QStringLiteral("c-sensor-filter"))->bendPoints.isEmpty());
    QCOMPARE(connector->route(), route);
}

void TestSeCanvasView::middleButtonPans()
{
    m_view->setZoomFactor(3.0);
    m_view->centerOn(m_scene->diagramRect().center());
    QScrollBar *horizontal = m_view->horizontalScrollBar();
    QScrollBar *vertical = m_view->verticalScrollBar();
    // Room to scroll both ways.
    QVERIFY(horizontal->maximum() - horizontal->value() > 100);
    QVERIFY(vertical->maximum() - vertical->value() > 50);
    const QPoint before(horizontal->value(), vertical->value());
    QWidget *viewport = m_view->viewport();
    const QPoint from = viewport->rect().center();
    QTest::mousePress(viewport, Qt::MiddleButton, {}, from);
    for (int step = 1; step <= 3; ++step)
        QTest::mouseMove(viewport, from - QPoint(30, 15) * step);
    QTest::mouseRelease(viewport, Qt::MiddleButton, {}, from - QPoint(90, 45));
    // Dragging the canvas left and up shows what lies right and below.
    QCOMPARE(QPoint(horizontal->value(), vertical->value()) - before, QPoint(90, 45));
    QCOMPARE(m_stack->count(), 0);
    QVERIFY(m_scene->selectedComponents().isEmpty());
}

void TestSeCanvasView::spaceDragPans()
{
    m_view->setZoomFactor(3.0);
    m_view->centerOn(m_scene->diagramRect().center());
    QScrollBar *horizontal = m_view->horizontalScrollBar();
    const int before = horizontal->value();
    QWidget *viewport = m_view->viewport();
    // Over a component: with space held the drag pans instead of moving it.
    const QPoint from = viewPos(m_scene->componentItem(QStringLiteral("Filter0"))->sceneBoundingRect()
                                    .center());
    m_view->setFocus();
    QTest::keyPress(m_view.get(), Qt::Key_Space);
    QTest::mousePress(viewport, Qt::LeftButton, {}, from);
    QTest::mouseMove(viewport, from + QPoint(40, 0));
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, from + QPoint(40, 0));
    QTest::keyRelease(m_view.get(), Qt::Key_Space);
    QCOMPARE(horizontal->value(), before - 40);
    QCOMPARE(m_stack->count(), 0);
    QCOMPARE(m_scene->componentItem(QStringLiteral("Filter0"))->pos(), QPointF(320, 60));
}

void TestSeCanvasView::alignLinesUpSelection()
{
    m_stack->push(new MoveComponentsCommand(m_model.get(),
                                            {{QStringLiteral("Sink0"), QPointF(600, 200)}}));
    m_scene->selectComponents({QStringLiteral("Sensor0"), QStringLiteral("Sink0")});
    m_scene->alignSelection(Alignment::Top);
    QCOMPARE(m_model->layout(QStringLiteral("Sink0")).position.y(),
             m_model->layout(QStringLiteral("Sensor0")).position.y());
    QCOMPARE(m_scene->componentItem(QStringLiteral("Sink0"))->pos().y(), 60.0);
    QCOMPARE(m_stack->count(), 2);
    m_stack->undo();
    QCOMPARE(m_scene->componentItem(QStringLiteral("Sink0"))->pos().y(), 200.0);
}

QTEST_MAIN(TestSeCanvasView)
#include "tst_secanvasview.moc"
