// SPDX-License-Identifier: MIT
#include "rtseditor.h"

#include "healer.h"
#include "plan.h"
#include "planview.h"
#include "propertiespanel.h"
#include "repositoryview.h"
#include "rtcrepository.h"
#include "rtsdocument.h"
#include "systemcanvas.h"
#include "systeminfoform.h"
#include "systemoutlinemodel.h"
#include "systemview.h"

#include <QAction>
#include <QCoreApplication>
#include <QDir>
#include <QHeaderView>
#include <QLabel>
#include <QPointer>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QTabBar>
#include <QTabWidget>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

namespace Studio {

namespace {

const QString RepositorySourcesKey = QStringLiteral("systemEditor/repositorySources");

/// The RTCs folders of the examples shipped beside the executable (installed or in the build
/// tree's source), so that a first start has components to drag.
QStringList bundledExampleSources()
{
    QStringList sources;
    const QDir app(QCoreApplication::applicationDirPath());
    for (const QString &relative :
         {QStringLiteral("../share/rtstudio/examples"), QStringLiteral("../../resources/examples"),
          QStringLiteral("../resources/examples")}) {
        const QDir examples(app.filePath(relative));
        if (!examples.exists())
            continue;
        for (const QString &system : examples.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
            const QString rtcs = examples.filePath(system + QStringLiteral("/RTCs"));
            if (QDir(rtcs).exists())
                sources << QDir::cleanPath(rtcs);
        }
        break;
    }
    return sources;
}

/// Tabs that show their whole titles side by side instead of squeezing or eliding them.
void makeReadable(QTabWidget *tabs)
{
    tabs->setDocumentMode(true);
    tabs->setUsesScrollButtons(false);
    tabs->tabBar()->setElideMode(Qt::ElideNone);
    tabs->tabBar()->setExpanding(false);
    tabs->setMinimumWidth(tabs->tabBar()->sizeHint().width());
}

} // namespace

SystemEditor::RtcRepository *RtsEditor::sharedRepository()
{
    static QPointer<SystemEditor::RtcRepository> repository;
    if (!repository) {
        repository = new SystemEditor::RtcRepository(QCoreApplication::instance());
        QSettings settings;
        const QStringList sources = settings.contains(RepositorySourcesKey)
            ? settings.value(RepositorySourcesKey).toStringList()
            : bundledExampleSources();
        for (const QString &source : sources)
            repository->addSource(source);
    }
    return repository;
}

namespace {

RtsEditor::DeployHandler &deployHandler()
{
    static RtsEditor::DeployHandler handler;
    return handler;
}

} // namespace

void RtsEditor::setDeployHandler(DeployHandler handler)
{
    deployHandler() = std::move(handler);
}

void RtsEditor::deployPlan(const Planner::Plan &plan)
{
    if (!deployHandler())
        return;
    QHash<QString, QString> placement;
    for (const Planner::Placement &p : plan.placements)
        placement.insert(p.instanceName, p.node);
    Profile::RtsProfile system = m_document->profile();
    Deploy::pinPlacement(&system, placement);
    deployHandler()(system, m_planView->repositoryFolder());
}

RtsEditor::RtsEditor(RtsDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_outlineModel(new SystemOutlineModel(document, this))
    , m_outlineView(new QTreeView)
    , m_systemInfo(new SystemInfoForm(document))
    , m_canvas(new SystemEditor::SystemCanvas(document->model(), document->undoStack()))
    , m_properties(new SystemEditor::PropertiesPanel(document->model(), document->undoStack()))
    , m_repositoryView(new SystemEditor::RepositoryView(sharedRepository()))
    , m_planView(new SystemEditor::PlanView(document->model(), document->undoStack()))
    , m_status(new QLabel)
    , m_centre(new QSplitter(Qt::Vertical))
    , m_splitter(new QSplitter(Qt::Horizontal, this))
{
    m_properties->followScene(m_canvas->scene());
    connect(m_properties, &SystemEditor::PropertiesPanel::editConnectorRequested, m_canvas->view(),
            &SystemEditor::SystemView::editConnector);
    m_status->setObjectName(QStringLiteral("canvasStatus"));
    m_status->setContentsMargins(6, 2, 6, 2);
    connect(m_canvas, &SystemEditor::SystemCanvas::statusMessage, m_status, &QLabel::setText);
    connect(m_repositoryView, &SystemEditor::RepositoryView::statusMessage, m_status,
            &QLabel::setText);

    auto *centre = new QWidget;
    auto *centreLayout = new QVBoxLayout(centre);
    centreLayout->setContentsMargins(0, 0, 0, 0);
    centreLayout->setSpacing(0);
    centreLayout->addWidget(buildToolBar());
    // The plan shares the canvas's column: its lanes want the width, the diagram stays in view.
    m_centre->setObjectName(QStringLiteral("systemEditorCentre"));
    m_centre->setChildrenCollapsible(false);
    m_centre->addWidget(m_canvas);
    m_centre->addWidget(m_planView);
    m_planView->hide();
    m_planView->setDeployAvailable(bool(deployHandler()));
    connect(m_planView, &SystemEditor::PlanView::deployRequested, this, &RtsEditor::deployPlan);
    centreLayout->addWidget(m_centre, 1);
    centreLayout->addWidget(m_status);

    // The canvas gets the room: the window's left edge belongs to the Name Service dock, so
    // the repository, outline and properties share one column on the right.
    auto *side = new QSplitter(Qt::Vertical);
    side->setObjectName(QStringLiteral("systemEditorSide"));
    side->setChildrenCollapsible(false);
    side->addWidget(buildBrowserTabs());
    side->addWidget(buildDetailTabs());
    side->setStretchFactor(0, 2);
    side->setStretchFactor(1, 3);
    m_splitter->addWidget(centre);
    m_splitter->addWidget(side);
    m_splitter->setChildrenCollapsible(false);
    m_splitter->setStretchFactor(0, 1);
    m_splitter->setStretchFactor(1, 0);
    m_splitter->setSizes({900, 300});

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);
}

RtsEditor::~RtsEditor()
{
    // Remember where the repository's profiles come from for the next start.
    QSettings().setValue(RepositorySourcesKey, sharedRepository()->sources());
}

void RtsEditor::showPlanView(bool show)
{
    m_planAction->setChecked(show);
}

QString RtsEditor::statusText() const
{
    return m_status->text();
}

QWidget *RtsEditor::buildToolBar()
{
    auto *toolBar = new QToolBar;
    toolBar->setObjectName(QStringLiteral("systemEditorToolBar"));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (const char *name : {"actionAutoLayout", "actionZoomFit"})
        toolBar->addAction(m_canvas->action(QLatin1String(name)));
    toolBar->addSeparator();
    m_planAction = toolBar->addAction(tr("Plan"));
    m_planAction->setObjectName(QStringLiteral("actionShowPlan"));
    m_planAction->setCheckable(true);
    m_planAction->setToolTip(tr("Show where the planner puts each component, one lane per node"));
    connect(m_planAction, &QAction::toggled, this, [this](bool show) {
        m_planView->setVisible(show);
        // Opened, the plan gets most of the column: its lanes list components downwards.
        if (show)
            m_centre->setSizes({m_centre->height() * 2 / 5, m_centre->height() * 3 / 5});
    });
    return toolBar;
}

QWidget *RtsEditor::buildBrowserTabs()
{
    m_outlineView->setModel(m_outlineModel);
    m_outlineView->setUniformRowHeights(true);
    m_outlineView->setAlternatingRowColors(true);
    m_outlineView->header()->setSectionResizeMode(SystemOutlineModel::NameColumn,
                                                  QHeaderView::ResizeToContents);
    m_outlineView->expandAll();
    auto *tabs = new QTabWidget;
    tabs->setObjectName(QStringLiteral("systemEditorLeftTabs"));
    tabs->addTab(m_repositoryView, tr("Repository"));
    tabs->addTab(m_outlineView, tr("Outline"));
    makeReadable(tabs);
    return tabs;
}

QWidget *RtsEditor::buildDetailTabs()
{
    auto *systemPage = new QWidget;
    auto *systemLayout = new QVBoxLayout(systemPage);
    systemLayout->addWidget(m_systemInfo);
    systemLayout->addStretch(1);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(systemPage);
    auto *tabs = new QTabWidget;
    tabs->setObjectName(QStringLiteral("systemEditorRightTabs"));
    tabs->addTab(m_properties, tr("Properties"));
    tabs->addTab(scroll, tr("System"));
    makeReadable(tabs);
    return tabs;
}

} // namespace Studio
