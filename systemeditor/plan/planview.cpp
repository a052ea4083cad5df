// SPDX-License-Identifier: MIT
#include "planview.h"

#include "nodefactsfile.h"
#include "nodefactsreader.h"
#include "orb.h"
#include "pincommand.h"
#include "planlanes.h"
#include "planner.h"
#include "planrepository.h"
#include "planscene.h"
#include "requirements.h"
#include "systemmodel.h"

#include <QAction>
#include <QFileDialog>
#include <QGraphicsView>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QSplitter>
#include <QTabBar>
#include <QTabWidget>
#include <QThread>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <memory>

namespace SystemEditor {

namespace {

/// How long one call to a manager may take while reading facts.
constexpr int ManagerCallTimeoutMs = 3000;
const QColor UnmetColour(200, 30, 30);

/// The planner's input: the system's requirements from the RTC profiles of the repository's
/// packages and, winning over them, those the model knows; what could not be read in @p warnings.
Planner::PlanProblem planProblem(const SystemModel &model, const QList<Planner::NodeFacts> &nodes,
                                 const Deploy::PlanRepository &repository, QStringList *warnings)
{
    QHash<QString, Profile::RtcProfile> types = repository.typeProfiles;
    for (const Profile::RtcProfile &rtc : model.rtcProfiles())
        Planner::addTypeProfile(rtc, &types);
    const Planner::SystemRequirements requirements
        = Planner::readRequirements(model.profile(), types);
    *warnings = requirements.warnings;
    Planner::PlanProblem problem;
    problem.components = requirements.components;
    problem.links = requirements.links;
    problem.nodes = nodes;
    problem.packages = repository.packages;
    return problem;
}

struct RepositoryReading
{
    std::optional<Deploy::PlanRepository> repository;
    QString error;
};

struct FactsReading
{
    QList<Planner::NodeFacts> facts;
    QStringList errors;
};

} // namespace

PlanView::PlanView(SystemModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_scene(new PlanScene(this))
{
    buildUi();
    connect(m_scene, &PlanScene::pinRequested, this, &PlanView::pin);
    for (const auto signal : {&SystemModel::componentAdded, &SystemModel::componentRemoved,
                              &SystemModel::componentChanged, &SystemModel::connectorAdded,
                              &SystemModel::connectorRemoved, &SystemModel::connectorChanged})
        connect(model, signal, this, &PlanView::systemChanged);
    connect(model, &SystemModel::componentRenamed, this, &PlanView::systemChanged);
    connect(model, &SystemModel::reset, this, &PlanView::systemChanged);
    refresh();
}

PlanView::~PlanView()
{
    // Workers end by themselves: the solver within its budget, managers within their timeout.
    for (QThread *thread : std::as_const(m_threads)) {
        thread->disconnect(this);
        thread->wait();
        delete thread;
    }
}

void PlanView::buildUi()
{
    m_view = new QGraphicsView(m_scene);
    m_view->setObjectName(QStringLiteral("planLanes"));
    m_view->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_view->setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
    // The lanes take the height (a lane is a column of components); the lists sit beside them.
    auto *splitter = new QSplitter(Qt::Horizontal);
    splitter->addWidget(m_view);
    splitter->addWidget(buildDetails());
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 1);
    splitter->setChildrenCollapsible(false);
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("planStatus"));
    m_status->setWordWrap(true);
    m_progress = new QProgressBar;
    m_progress->setRange(0, 0);
    m_progress->setMaximumWidth(160);
    m_progress->hide();
    auto *statusRow = new QHBoxLayout;
    statusRow->addWidget(m_status, 1);
    statusRow->addWidget(m_progress);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(buildToolBar());
    layout->addWidget(splitter, 1);
    layout->addLayout(statusRow);
}

QWidget *PlanView::buildDetails()
{
    m_unmetList = new QListWidget;
    m_unmetList->setObjectName(QStringLiteral("planUnmet"));
    // Explanations are sentences: whole, not cut at the list's edge.
    m_unmetList->setWordWrap(true);
    m_unmetList->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_dryRunList = new QListWidget;
    m_dryRunList->setObjectName(QStringLiteral("planDryRun"));
    m_dryRunList->setWordWrap(true);
    m_dryRunList->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_details = new QTabWidget;
    m_details->setDocumentMode(true);
    m_details->addTab(m_unmetList, tr("Unmet Requirements"));
    m_details->addTab(m_dryRunList, tr("Dry Run"));
    // Whole tab titles, as the editor's other tabs show them.
    m_details->setUsesScrollButtons(false);
    m_details->tabBar()->setElideMode(Qt::ElideNone);
    m_details->setMinimumWidth(m_details->tabBar()->sizeHint().width());
    return m_details;
}

QWidget *PlanView::buildToolBar()
{
    auto *toolBar = new QToolBar;
    toolBar->setObjectName(QStringLiteral("planToolBar"));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    const auto add = [&](const QString &text, const char *name, auto slot) {
        QAction *action = toolBar->addAction(text);
        action->setObjectName(QLatin1String(name));
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    m_openFacts = add(tr("Open Facts…"), "planOpenFacts", &PlanView::askFactsFile);
    m_readManagers = add(tr("Read Managers…"), "planReadManagers", &PlanView::askManagers);
    m_openRepository = add(tr("Repository…"), "planOpenRepository", &PlanView::askRepository);
    toolBar->addSeparator();
    m_replan = add(tr("Re-plan"), "planReplan", &PlanView::replan);
    m_cancel = add(tr("Cancel"), "planCancel", &PlanView::cancel);
    m_dryRun = add(tr("Dry Run"), "planDryRunAction", &PlanView::dryRun);
    toolBar->addSeparator();
    m_deploy = add(tr("Deploy"), "planDeploy", [this] { emit deployRequested(m_plan); });
    updateActions();
    return toolBar;
}

void PlanView::askFactsFile()
{
    const QString path
        = QFileDialog::getOpenFileName(this, tr("Open Node Facts"), QString(),
                                       tr("Node facts (*.yaml *.yml *.json);;All files (*)"));
    if (!path.isEmpty())
        openFactsFile(path);
}

void PlanView::askRepository()
{
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Component Repository"));
    if (!folder.isEmpty())
        openRepository(folder);
}

void PlanView::openRepository(const QString &folder)
{
    runInBackground<RepositoryReading>(
        tr("Reading the repository…"),
        [folder] {
            RepositoryReading reading;
            QStringList warnings;
            reading.repository = Deploy::readPlanRepository(folder, &warnings, &reading.error);
            return reading;
        },
        [this, folder](const RepositoryReading &reading) {
            if (!reading.repository) {
                m_message = tr("Could not read the repository: %1").arg(reading.error);
                refresh();
                return;
            }
            m_repository = *reading.repository;
            m_repositoryFolder = folder;
            m_message = tr("Packages in the repository: %1.").arg(m_repository.packages.size());
            replan();
        });
}

void PlanView::askManagers()
{
    QStringList current;
    for (const Planner::NodeFacts &node : std::as_const(m_facts))
        current << node.name;
    bool ok = false;
    const QString text = QInputDialog::getText(
        this, tr("Read Managers"),
        tr("Managers to plan on (corbaloc or name-service paths, separated by commas):"),
        QLineEdit::Normal, current.join(QStringLiteral(", ")), &ok);
    const QStringList addresses = text.split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (ok && !addresses.isEmpty())
        readFactsFromManagers(addresses);
}

bool PlanView::openFactsFile(const QString &path)
{
    QString error;
    const auto facts = Planner::readNodeFactsFile(path, &error);
    if (!facts) {
        m_message = tr("Could not read the node facts: %1").arg(error);
        refresh();
        return false;
    }
    setFacts(*facts, {});
    return true;
}

void PlanView::readFactsFromManagers(const QStringList &addresses)
{
    QStringList trimmed;
    for (const QString &address : addresses)
        trimmed << address.trimmed();
    runInBackground<FactsReading>(
        tr("Reading the managers…"),
        [trimmed] {
            const Corba::ThreadCallTimeout timeout(ManagerCallTimeoutMs);
            FactsReading reading;
            for (const Deploy::NodeFactsReading &r : Deploy::readNodeFacts(trimmed)) {
                if (r.error.isEmpty())
                    reading.facts << r.facts;
                else
                    reading.errors << QStringLiteral("%1: %2").arg(r.facts.name, r.error);
            }
            return reading;
        },
        [this](const FactsReading &reading) { setFacts(reading.facts, reading.errors); });
}

void PlanView::setFacts(const QList<Planner::NodeFacts> &facts, const QStringList &errors)
{
    m_facts = facts;
    m_factErrors = errors;
    m_message = tr("Nodes read: %1.").arg(facts.size());
    emit factsChanged();
    replan();
}

void PlanView::replan()
{
    if (m_facts.isEmpty()) {
        m_message = tr("Open a facts file or read the managers to plan on their nodes.");
        refresh();
        return;
    }
    QStringList warnings;
    const Planner::PlanProblem problem = planProblem(*m_model, m_facts, m_repository, &warnings);
    runInBackground<Planner::Plan>(
        tr("Planning…"),
        [problem, warnings] {
            Planner::Plan plan = Planner::DeploymentPlanner().plan(problem);
            // Shown with the plan: a type without its RTC profile has fewer requirements.
            plan.warnings << warnings;
            return plan;
        },
        [this](const Planner::Plan &plan) { setPlan(plan); });
}

template<typename Result, typename Work, typename Done>
void PlanView::runInBackground(const QString &what, Work work, Done done)
{
    const quint64 generation = ++m_generation;
    auto result = std::make_shared<Result>();
    QThread *thread = QThread::create([work, result] { *result = work(); });
    connect(thread, &QThread::finished, this, [this, thread, generation, result, done] {
        m_threads.removeOne(thread);
        thread->deleteLater();
        // Cancelled or overtaken by a newer request: not what the user waits for any more.
        if (generation != m_generation)
            return;
        setBusy(false, {});
        done(*result);
    });
    m_threads << thread;
    setBusy(true, what);
    thread->start();
}

void PlanView::cancel()
{
    if (!m_busy)
        return;
    ++m_generation;
    setBusy(false, {});
    m_message = tr("Cancelled.");
    refresh();
}

void PlanView::setPlan(const Planner::Plan &plan)
{
    m_plan = plan;
    m_planned = true;
    m_outOfDate = false;
    m_message.clear();
    m_dryRunList->clear();
    showUnmet();
    refresh();
    emit planChanged();
}

void PlanView::showUnmet()
{
    m_unmetList->clear();
    for (const Planner::Unmet &u : std::as_const(m_plan.unmet)) {
        auto *item = new QListWidgetItem(unmetText(u), m_unmetList);
        item->setForeground(UnmetColour);
    }
    for (const QString &warning : std::as_const(m_plan.warnings))
        new QListWidgetItem(warning, m_unmetList);
    if (!m_plan.unmet.isEmpty())
        m_details->setCurrentWidget(m_unmetList);
}

void PlanView::dryRun()
{
    m_dryRunList->clear();
    const QStringList steps = m_planned && m_plan.feasible
        ? dryRunSteps(m_plan)
        : QStringList {tr("Nothing to deploy: there is no plan.")};
    m_dryRunList->addItems(steps);
    m_details->setCurrentWidget(m_dryRunList);
}

void PlanView::pin(const QString &instanceName, const QString &node)
{
    m_undoStack->push(new PinComponentCommand(m_model, instanceName, node));
}

void PlanView::systemChanged()
{
    m_outOfDate = m_planned;
    refresh();
}

void PlanView::setDeployAvailable(bool available)
{
    m_deployAvailable = available;
    updateActions();
}

void PlanView::setBusy(bool busy, const QString &what)
{
    m_busy = busy;
    m_progress->setVisible(busy);
    m_progress->setFormat(what);
    m_progress->setTextVisible(busy);
    if (busy)
        m_message = what;
    updateActions();
    refresh();
    emit busyChanged(busy);
}

void PlanView::updateActions()
{
    m_openFacts->setEnabled(!m_busy);
    m_readManagers->setEnabled(!m_busy);
    m_openRepository->setEnabled(!m_busy);
    m_replan->setEnabled(!m_busy && !m_facts.isEmpty());
    m_cancel->setEnabled(m_busy);
    m_dryRun->setEnabled(!m_busy && m_planned);
    const bool deployable = m_planned && m_plan.feasible && !m_outOfDate && !m_busy;
    m_deploy->setEnabled(m_deployAvailable && deployable);
    m_deploy->setToolTip(m_deployAvailable
                             ? tr("Install, create and connect the components as planned (opens the Restore dialog)")
                             : tr("Deploying needs the online tools of RT Studio's main window"));
}

void PlanView::refresh()
{
    m_scene->showLanes(planLanes(m_plan, m_facts, *m_model));
    m_status->setText(statusText());
    updateActions();
}

QString PlanView::planSummary() const
{
    if (!m_planned)
        return tr("Not planned yet.");
    if (!m_plan.feasible)
        return tr("No plan: requirements that no node meets, in red: %1.").arg(m_plan.unmet.size());
    QString summary
        = tr("Components placed: %1; packages to install: %2; connectors between hosts: "
             "%3 Hz; solved in %4 ms.")
              .arg(m_plan.placements.size())
              .arg(m_plan.installs.size())
              .arg(m_plan.crossHostRate)
              .arg(m_plan.solveMs, 0, 'f', 0);
    if (!m_plan.optimal)
        summary += QLatin1Char(' ') + tr("Not proven best: the solver's time ran out.");
    return summary;
}

QString PlanView::statusText() const
{
    QStringList parts {planSummary()};
    if (m_outOfDate)
        parts << tr("The system changed since: re-plan to see where everything goes now.");
    if (!m_message.isEmpty())
        parts << m_message;
    // Until other facts are read: the plan is without these nodes.
    if (!m_factErrors.isEmpty())
        parts << tr("Not read: %1").arg(m_factErrors.join(QStringLiteral("; ")));
    return parts.join(QLatin1Char(' '));
}

} // namespace SystemEditor
