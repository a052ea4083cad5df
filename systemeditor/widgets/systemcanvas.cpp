// SPDX-License-Identifier: MIT
#include "systemcanvas.h"

#include "autolayout.h"
#include "diagramexport.h"
#include "instancecommands.h"
#include "overviewwidget.h"
#include "systemscene.h"
#include "systemview.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QEvent>
#include <QGraphicsItem>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QScrollBar>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

namespace SystemEditor {

SystemCanvas::SystemCanvas(SystemModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_scene(new SystemScene(model, undoStack, this))
    , m_view(new SystemView(m_scene))
    , m_overview(new OverviewWidget(m_scene, m_view, m_view))
    , m_findBar(new QWidget)
    , m_findEdit(new QLineEdit)
{
    m_findEdit->setObjectName(QStringLiteral("findEdit"));
    m_findEdit->setPlaceholderText(tr("Find component by instance name"));
    m_findEdit->setClearButtonEnabled(true);
    auto *close = new QToolButton;
    close->setText(tr("Close"));
    auto *findLayout = new QHBoxLayout(m_findBar);
    findLayout->setContentsMargins(4, 2, 4, 2);
    findLayout->addWidget(new QLabel(tr("Find:")));
    findLayout->addWidget(m_findEdit, 1);
    findLayout->addWidget(close);
    m_findBar->hide();
    connect(m_findEdit, &QLineEdit::returnPressed, this,
            [this] { m_view->findComponent(m_findEdit->text()); });
    connect(close, &QToolButton::clicked, m_findBar, &QWidget::hide);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_findBar);

    createEditActions();
    createViewActions();
    createArrangeActions();
    m_compositeEditor = [this](const SystemModel &model, const QStringList &members)
        -> std::optional<CompositeDialog::Choice> {
        CompositeDialog dialog(model, members, this);
        if (dialog.exec() != QDialog::Accepted)
            return std::nullopt;
        return dialog.choice();
    };
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_view, &QWidget::customContextMenuRequested, this, &SystemCanvas::showContextMenu);
    connect(m_view, &SystemView::statusMessage, this, &SystemCanvas::statusMessage);
    connect(m_scene, &QGraphicsScene::selectionChanged, this, &SystemCanvas::updateActions);
    connect(m_scene, &SystemScene::componentActivated, this, [this] { m_view->startRename(); });
    updateActions();
    m_overview->updateVisibility();
    connect(QGuiApplication::clipboard(), &QClipboard::dataChanged, this,
            &SystemCanvas::updateActions);
    m_view->viewport()->installEventFilter(this);
    m_view->installEventFilter(this);
}

SystemCanvas::~SystemCanvas()
{
    // The scene (a child, deleted after this destructor) must not call back into a canvas that
    // is already gone; the view (and the overview on it) go before the scene they watch.
    m_scene->disconnect(this);
    delete m_view;
}

QAction *SystemCanvas::addCanvasAction(const QString &objectName, const QString &text,
                                       const QKeySequence &shortcut)
{
    auto *action = new QAction(text, this);
    action->setObjectName(objectName);
    action->setShortcut(shortcut);
    // Only while the canvas has focus, so that other editors keep their own shortcuts.
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    addAction(action);
    return action;
}

QAction *SystemCanvas::action(const QString &objectName) const
{
    return findChild<QAction *>(objectName);
}

void SystemCanvas::createEditActions()
{
    connect(addCanvasAction(QStringLiteral("actionDelete"), tr("&Delete"), QKeySequence::Delete),
            &QAction::triggered, m_scene, &SystemScene::deleteSelection);
    connect(addCanvasAction(QStringLiteral("actionCopy"), tr("&Copy"), QKeySequence::Copy),
            &QAction::triggered, m_scene, &SystemScene::copySelection);
    connect(addCanvasAction(QStringLiteral("actionPaste"), tr("&Paste"), QKeySequence::Paste),
            &QAction::triggered, this, [this] {
                m_scene->paste();
                updateActions();
            });
    connect(addCanvasAction(QStringLiteral("actionSelectAll"), tr("Select &All"),
                            QKeySequence::SelectAll),
            &QAction::triggered, this, [this] {
                for (QGraphicsItem *item : m_scene->items()) {
                    if (item->flags() & QGraphicsItem::ItemIsSelectable)
                        item->setSelected(true);
                }
            });
    connect(addCanvasAction(QStringLiteral("actionRename"), tr("&Rename Instance"),
                            QKeySequence(Qt::Key_F2)),
            &QAction::triggered, m_view, &SystemView::startRename);
    connect(addCanvasAction(QStringLiteral("actionGroupComposite"), tr("&Group as Composite…")),
            &QAction::triggered, this, &SystemCanvas::groupSelection);
    connect(addCanvasAction(QStringLiteral("actionDecompose"), tr("D&ecompose")),
            &QAction::triggered, this, [this] {
                m_scene->decomposeSelection();
                updateActions();
            });
    connect(addCanvasAction(QStringLiteral("actionFind"), tr("&Find Component…"),
                            QKeySequence::Find),
            &QAction::triggered, this, &SystemCanvas::showFind);
}

void SystemCanvas::createViewActions()
{
    // Any zoom the user asks for, or a scroll bar grabbed, ends the fitting of a fresh diagram.
    connect(m_view, &SystemView::zoomChanged, this, [this] {
        if (!m_fitting)
            m_keepFitted = false;
    });
    for (QScrollBar *bar : {m_view->horizontalScrollBar(), m_view->verticalScrollBar()})
        connect(bar, &QScrollBar::sliderPressed, this, [this] { m_keepFitted = false; });
    connect(addCanvasAction(QStringLiteral("actionZoomIn"), tr("Zoom &In"), QKeySequence::ZoomIn),
            &QAction::triggered, m_view, &SystemView::zoomIn);
    connect(addCanvasAction(QStringLiteral("actionZoomOut"), tr("Zoom &Out"),
                            QKeySequence::ZoomOut),
            &QAction::triggered, m_view, &SystemView::zoomOut);
    connect(addCanvasAction(QStringLiteral("actionZoomReset"), tr("&Actual Size")),
            &QAction::triggered, m_view, &SystemView::resetZoom);
    connect(addCanvasAction(QStringLiteral("actionZoomFit"), tr("&Fit Diagram")),
            &QAction::triggered, m_view, &SystemView::fitToDiagram);
    QAction *grid = addCanvasAction(QStringLiteral("actionSnapToGrid"), tr("Snap to &Grid"));
    grid->setCheckable(true);
    grid->setChecked(m_scene->snapsToGrid());
    connect(grid, &QAction::toggled, this, [this](bool on) {
        m_scene->setSnapToGrid(on);
        m_scene->setGridVisible(on);
    });
}

void SystemCanvas::createArrangeActions()
{
    const QList<QPair<Direction, QString>> directions {
        {Direction::Right, tr("Face &Right")},
        {Direction::Left, tr("Face &Left")},
        {Direction::Up, tr("Face &Up")},
        {Direction::Down, tr("Face &Down")}};
    for (const auto &[direction, text] : directions) {
        const Direction d = direction;
        connect(addCanvasAction(QStringLiteral("actionDirection") + directionText(d).toLower(),
                                text),
                &QAction::triggered, this, [this, d] { m_scene->setDirectionOfSelection(d); });
    }
    const QList<QPair<Alignment, QString>> alignments {
        {Alignment::Left, tr("Align &Left Edges")},
        {Alignment::Right, tr("Align &Right Edges")},
        {Alignment::Top, tr("Align &Top Edges")},
        {Alignment::Bottom, tr("Align &Bottom Edges")},
        {Alignment::HorizontalCenter, tr("Align &Centres Horizontally")},
        {Alignment::VerticalCenter, tr("Align Centres &Vertically")}};
    int index = 0;
    for (const auto &[alignment, text] : alignments) {
        const Alignment a = alignment;
        connect(addCanvasAction(QStringLiteral("actionAlign%1").arg(index++), text),
                &QAction::triggered, this, [this, a] { m_scene->alignSelection(a); });
    }
    connect(addCanvasAction(QStringLiteral("actionAutoLayout"), tr("Auto &Layout")),
            &QAction::triggered, this, &SystemCanvas::autoLayout);
}

void SystemCanvas::updateActions()
{
    const int components = int(m_scene->selectedComponents().size());
    const bool any = components + m_scene->selectedConnectors().size() > 0;
    action(QStringLiteral("actionDelete"))->setEnabled(any);
    action(QStringLiteral("actionCopy"))->setEnabled(components > 0);
    action(QStringLiteral("actionPaste"))->setEnabled(SystemScene::canPaste());
    action(QStringLiteral("actionRename"))->setEnabled(components == 1);
    action(QStringLiteral("actionGroupComposite"))->setEnabled(components > 0);
    action(QStringLiteral("actionDecompose"))->setEnabled(!m_scene->selectedComposites().isEmpty());
    for (QAction *a : actions()) {
        if (a->objectName().startsWith(QLatin1String("actionDirection")))
            a->setEnabled(components > 0);
        else if (a->objectName().startsWith(QLatin1String("actionAlign")))
            a->setEnabled(components > 1);
    }
}

void SystemCanvas::showFind()
{
    m_findBar->show();
    m_findEdit->setFocus();
    m_findEdit->selectAll();
}

void SystemCanvas::showContextMenu(const QPoint &pos)
{
    updateActions();
    QMenu menu(this);
    for (const char *name : {"actionRename", "actionDelete", "actionCopy", "actionPaste"})
        menu.addAction(action(QLatin1String(name)));
    menu.addSeparator();
    for (const char *name : {"actionGroupComposite", "actionDecompose"})
        menu.addAction(action(QLatin1String(name)));
    QMenu *turn = menu.addMenu(tr("&Direction"));
    QMenu *align = menu.addMenu(tr("A&lign"));
    for (QAction *a : actions()) {
        if (a->objectName().startsWith(QLatin1String("actionDirection")))
            turn->addAction(a);
        else if (a->objectName().startsWith(QLatin1String("actionAlign")))
            align->addAction(a);
    }
    menu.addSeparator();
    for (const char *name : {"actionSelectAll", "actionAutoLayout", "actionZoomFit",
                             "actionSnapToGrid"})
        menu.addAction(action(QLatin1String(name)));
    menu.exec(m_view->viewport()->mapToGlobal(pos));
}

void SystemCanvas::groupSelection()
{
    const QStringList members = m_scene->selectedComponents();
    if (members.isEmpty() || !m_scene->undoStack())
        return;
    const std::optional<CompositeDialog::Choice> choice
        = m_compositeEditor(*m_scene->model(), members);
    if (!choice)
        return;
    const QString name = m_scene->groupSelection(choice->compositeType, choice->exportedPorts);
    emit statusMessage(tr("Grouped %n component(s) as %1.", nullptr, int(members.size()))
                           .arg(name));
    updateActions();
}

QList<QAction *> SystemCanvas::editActions() const
{
    QList<QAction *> list;
    for (const char *name : {"actionDelete", "actionCopy", "actionPaste", "actionSelectAll",
                             "actionRename", "actionGroupComposite", "actionDecompose",
                             "actionFind"})
        list.append(action(QLatin1String(name)));
    return list;
}

void SystemCanvas::autoLayout()
{
    QUndoStack *stack = m_scene->undoStack();
    QUndoCommand *command = stack ? autoLayoutCommand(m_scene->model(),
                                                      DiagramExport::drawnLayoutOptions(*m_scene))
                                  : nullptr;
    if (!command) {
        emit statusMessage(tr("Nothing to lay out."));
        return;
    }
    stack->push(command);
    emit statusMessage(tr("Laid out %n component(s).", nullptr,
                          int(m_scene->model()->componentIds().size())));
}

void SystemCanvas::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (m_keepFitted && isVisible())
        fitFreshDiagram();
    placeOverview();
}

void SystemCanvas::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_keepFitted) {
        fitFreshDiagram();
        placeOverview();
    }
}

void SystemCanvas::fitFreshDiagram()
{
    m_fitting = true;
    m_view->fitToDiagram();
    m_fitting = false;
}

bool SystemCanvas::eventFilter(QObject *watched, QEvent *event)
{
    switch (event->type()) {
    case QEvent::Wheel:
    case QEvent::MouseButtonPress:
    case QEvent::KeyPress:
        m_keepFitted = false; // the user navigates now; never move the view under them
        break;
    default:
        break;
    }
    return QWidget::eventFilter(watched, event);
}

void SystemCanvas::placeOverview()
{
    // Bottom-right corner of the view, clear of its scroll bars.
    const QRect viewport = m_view->viewport()->geometry();
    m_overview->move(viewport.right() - m_overview->width() - 8,
                     viewport.bottom() - m_overview->height() - 8);
    m_overview->updateVisibility();
}

} // namespace SystemEditor
