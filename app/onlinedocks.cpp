// SPDX-License-Identifier: MIT
#include "onlinedocks.h"

#include "configurationview.h"
#include "corbaerror.h"
#include "deployer.h"
#include "documentcontroller.h"
#include "driftview.h"
#include "executioncontextview.h"
#include "installation.h"
#include "orb.h"
#include "managerunit.h"
#include "managerview.h"
#include "nameservicemodel.h"
#include "nameserviceview.h"
#include "onlinediagram.h"
#include "onlinedocument.h"
#include "onlineservice.h"
#include "onlinesession.h"
#include "portmonitor.h"
#include "profileio.h"
#include "restoredialog.h"
#include "restoreplan.h"
#include "restorer.h"
#include "rtsdocument.h"
#include "sequencerunner.h"
#include "typecatalog.h"
#include "systemmodel.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QItemSelectionModel>
#include <QLabel>
#include <QSettings>
#include <QStatusBar>
#include <QMainWindow>
#include <QMenu>
#include <QPointer>
#include <QSortFilterProxyModel>
#include <QTreeView>

Q_DECLARE_METATYPE(Deploy::RestorePlan)

Q_DECLARE_METATYPE(Deploy::DeployReport)

namespace Studio {

using SystemEditor::NameServiceModel;
using SystemEditor::OnlineDiagram;

namespace {

const QString KeepLocalRuntimeKey = QStringLiteral("online/keepLocalRuntime");
/// Where Start a Manager at Boot writes its unit instead of systemd's user folder (no systemctl).
const QString UnitDirectoryKey = QStringLiteral("node/unitDirectory");

/// The name part of the system's id (`RTSystem:vendor:NAME:version`).
QString systemName(const Profile::RtsProfile &profile)
{
    const QString name = profile.id.section(QLatin1Char(':'), 2, 2);
    return name.isEmpty() ? profile.id : name;
}

} // namespace

OnlineDocks::OnlineDocks(QMainWindow *window, QSettings *settings)
    : QObject(window)
    , m_session(new SystemEditor::OnlineSession(this))
    , m_nameService(new SystemEditor::NameServiceView(m_session, settings))
    , m_configuration(new SystemEditor::ConfigurationView(m_session))
    , m_contexts(new SystemEditor::ExecutionContextView(m_session))
    , m_manager(new SystemEditor::ManagerView(m_session))
    , m_portMonitor(new SystemEditor::PortMonitor)
{
    qRegisterMetaType<Deploy::RestorePlan>();
    addDock(window, m_nameService, tr("Name Service"), QStringLiteral("nameServiceDock"),
            Qt::LeftDockWidgetArea);
    QDockWidget *configuration
        = addDock(window, m_configuration, tr("Configuration"), QStringLiteral("configurationDock"),
                  Qt::BottomDockWidgetArea);
    // Attach targets and participants' paths: the components the Name Service view knows.
    m_contexts->setComponentSource(m_nameService->model());
    QDockWidget *contexts
        = addDock(window, m_contexts, tr("Execution Contexts"),
                  QStringLiteral("executionContextDock"), Qt::BottomDockWidgetArea);
    QDockWidget *manager = addDock(window, m_manager, tr("Manager"), QStringLiteral("managerDock"),
                                   Qt::BottomDockWidgetArea);
    window->tabifyDockWidget(configuration, contexts);
    window->tabifyDockWidget(contexts, manager);
    QDockWidget *monitor = addDock(window, m_portMonitor, tr("Port Monitor"),
                                   QStringLiteral("portMonitorDock"), Qt::BottomDockWidgetArea);
    window->tabifyDockWidget(manager, monitor);
    configuration->raise();
    connect(m_session, &SystemEditor::OnlineSession::portMonitorRequested, this,
            [this, monitor](const QString &componentPath, const Corba::PortInfo &port) {
                monitor->show();
                monitor->raise();
                // The Builder's IDL folders hold the user's data types.
                m_portMonitor->setIdlDirectories(Builder::TypeCatalog::userDirectories());
                m_portMonitor->watch(componentPath, port);
            });
    connect(m_portMonitor, &SystemEditor::PortMonitor::statusMessage, this, &OnlineDocks::statusMessage);
    m_localRuntimeLabel = new QLabel(window);
    m_localRuntimeLabel->setObjectName(QStringLiteral("localRuntimeStatus"));
    window->statusBar()->addPermanentWidget(m_localRuntimeLabel);
    m_localRuntime = Deploy::LocalRuntime().status();
    showLocalRuntime();
    connect(m_nameService->treeView()->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &current) {
                showItem(m_nameService->filterModel()->mapToSource(current));
            });
    connect(m_nameService->treeView(), &QTreeView::doubleClicked, this,
            [this](const QModelIndex &index) {
                addToDiagram(m_nameService->filterModel()->mapToSource(index));
            });
}

void OnlineDocks::attach(DocumentController *documents,
                         const std::function<Document *()> &activeDocument,
                         const FileQuestion &askFile)
{
    m_documents = documents;
    m_activeDocument = activeDocument;
    m_askFile = askFile;
}

QDockWidget *OnlineDocks::addDock(QMainWindow *window, QWidget *view, const QString &title,
                                  const QString &name, Qt::DockWidgetArea area)
{
    auto *dock = new QDockWidget(title, window);
    dock->setObjectName(name);
    dock->setWidget(view);
    window->addDockWidget(area, dock);
    dock->hide();
    m_docks.append(dock);
    return dock;
}

QList<QAction *> OnlineDocks::toggleActions() const
{
    QList<QAction *> actions;
    for (QDockWidget *dock : m_docks)
        actions.append(dock->toggleViewAction());
    return actions;
}

void OnlineDocks::fillMenu(QMenu *menu)
{
    const auto add = [this, menu](const char *name, const QString &text, auto slot) {
        QAction *action = menu->addAction(text, this, slot);
        action->setObjectName(QLatin1String(name));
        return action;
    };
    add("actionNewOnlineDiagram", tr("&New Online Diagram"), [this] { newDiagram(); });
    add("actionOpenOnline", tr("&Open System Online"), [this] {
        const auto *system = qobject_cast<RtsDocument *>(m_activeDocument());
        if (system)
            openOnline(system->profile());
        else
            emit statusMessage(tr("Open a system to show it online."));
    });
    add("actionSaveLiveSystem", tr("&Save Live System As…"), [this] {
        if (OnlineDocument *online = currentDiagram())
            m_documents->saveAs(online);
        else
            emit statusMessage(tr("Open an online diagram to save its live system."));
    });
    add("actionCompareWithFile", tr("&Compare with File…"), [this] {
        const QString path = m_askFile ? m_askFile() : QString();
        if (!path.isEmpty())
            compareWithFile(path);
    });
    menu->addSeparator();
    add("actionStartLocalRuntime", tr("Start &Local Runtime"), [this] { startLocalRuntime(); });
    add("actionStartLocalRuntimeTls", tr("Start Local Runtime with &TLS"), [this] { startLocalRuntimeWithTls(); });
    add("actionStopLocalRuntime", tr("Stop Local Runtime"), [this] { stopLocalRuntime(); });
    m_keepLocalRuntime = add("actionKeepLocalRuntime", tr("&Keep Local Runtime After Quit"), [] {});
    m_keepLocalRuntime->setCheckable(true);
    m_keepLocalRuntime->setChecked(QSettings().value(KeepLocalRuntimeKey).toBool());
    connect(m_keepLocalRuntime, &QAction::toggled, this,
            [](bool keep) { QSettings().setValue(KeepLocalRuntimeKey, keep); });
    add("actionRunLocally", tr("&Run System on Local Runtime"), [this] {
        if (const auto *system = qobject_cast<RtsDocument *>(m_activeDocument()))
            runLocally(system->profile());
        else
            emit statusMessage(tr("Open a system to run it."));
    });
    add("actionManagerAtBoot", tr("Start a Manager at &Boot…"), [this] {
        const QString config = QFileDialog::getOpenFileName(
            m_nameService->window(), tr("The Manager's Configuration"), QString(),
            tr("Manager configuration (*.conf);;All files (*)"));
        if (config.isEmpty())
            return;
        setManagerAtBoot(true, config, [this](const SystemEditor::OnlineResult &result) {
            emit statusMessage(result.ok ? tr("rtmanager starts with your session: %1").arg(result.value.toString())
                                         : tr("No manager at boot: %1").arg(result.error));
        });
    });
    add("actionNoManagerAtBoot", tr("Do Not Start a Manager at Boot"), [this] {
        setManagerAtBoot(false, QString(), [this](const SystemEditor::OnlineResult &result) {
            emit statusMessage(result.ok ? tr("Removed %1.").arg(result.value.toString()) : result.error);
        });
    });
    for (const bool uninstall : {false, true}) {
        add(uninstall ? "actionUndeployUninstall" : "actionUndeploy",
            uninstall ? tr("Undeploy System and Uninstall Its &Packages") : tr("&Undeploy System"),
            [this, uninstall] {
                if (const auto *system = qobject_cast<RtsDocument *>(m_activeDocument()))
                    undeploy(system->profile(), uninstall);
                else
                    emit statusMessage(tr("Open a system to undeploy it."));
            });
    }
    menu->addSeparator();
    const std::pair<const char *, OnlineDiagram::Action> all[]
        = {{QT_TR_NOOP("Activate All"), OnlineDiagram::Action::Activate},
           {QT_TR_NOOP("Deactivate All"), OnlineDiagram::Action::Deactivate},
           {QT_TR_NOOP("Reset All"), OnlineDiagram::Action::Reset},
           {QT_TR_NOOP("Start All"), OnlineDiagram::Action::Start},
           {QT_TR_NOOP("Stop All"), OnlineDiagram::Action::Stop},
           {QT_TR_NOOP("Exit All"), OnlineDiagram::Action::Exit}};
    for (const auto &[text, action] : all) {
        const OnlineDiagram::Action what = action;
        QAction *a = menu->addAction(tr(text), this, [this, what] {
            if (OnlineDocument *online = currentDiagram(); online && online->diagram())
                online->diagram()->performAll(what);
        });
        a->setObjectName(QStringLiteral("menuAction")
                         + QString::fromLatin1(text).remove(QLatin1Char(' ')));
    }
}

void OnlineDocks::showLocalRuntime(const QString &failure)
{
    // A failed start stays in the label (the status bar's message goes after a few seconds); the
    // reason is in its tooltip.
    m_localRuntimeLabel->setText(
        m_localRuntime.running()
            ? (m_localRuntime.tls ? tr("Local runtime (TLS): name server %1, manager port %2")
                                  : tr("Local runtime: name server %1, manager port %2"))
                  .arg(m_localRuntime.nameServerAddress())
                  .arg(m_localRuntime.manager.port)
        : failure.isEmpty() ? tr("Local runtime: stopped")
                            : tr("Local runtime: did not start"));
    m_localRuntimeLabel->setToolTip(m_localRuntime.running() || failure.isEmpty()
                                        ? QString()
                                        : tr("The local runtime did not start: %1").arg(failure));
}

void OnlineDocks::startLocalRuntimeWithTls()
{
    if (!Corba::Orb::usesTls() && Corba::Orb::isInitialised()) {
        // The process's connections are plain TCP from their first one on.
        emit statusMessage(tr("RT Studio talks plain TCP since it started: quit it, run \"rtctl local start "
                              "--tls\" and start RT Studio again."));
        return;
    }
    startLocalRuntime({}, {}, true);
}

void OnlineDocks::startLocalRuntime(const std::function<void(const Deploy::LocalRuntimeState &)> &then,
                                    const std::function<void(const QString &)> &failed)
{
    startLocalRuntime(then, failed, Corba::Orb::usesTls());
}

void OnlineDocks::startLocalRuntime(const std::function<void(const Deploy::LocalRuntimeState &)> &then,
                                    const std::function<void(const QString &)> &failed, bool tls)
{
    emit statusMessage(tr("Starting the local runtime…"));
    m_session->submit(
        SystemEditor::OnlineSession::deploymentHost(),
        [ownership = m_ownership, tls] {
            QString error;
            const Deploy::LocalRuntimeState state
                = Deploy::LocalRuntime().start(Codegen::Installation::managerProgram(), tls, &error);
            if (!error.isEmpty())
                throw Corba::Error(Corba::Error::Kind::System, error);
            // Before this program's first remote call: present the user's certificate of the runtime.
            if (tls && !Corba::Orb::usesTls()) {
                const Deploy::LocalRuntimeTls files = Deploy::LocalRuntime().tls();
                if (!Corba::Orb::setTls(files.certificateAuthorityFile, files.userKeyFile, QString(), &error))
                    throw Corba::Error(Corba::Error::Kind::System, error);
            }
            std::lock_guard lock(ownership->mutex);
            ownership->started = ownership->started || state.startedNow;
            if (ownership->quitting && ownership->started) {
                // The window quit while this start was under way.
                Deploy::LocalRuntime().stop(nullptr);
                ownership->started = false;
            }
            return QVariant::fromValue(state);
        },
        this,
        [this, then, failed](const SystemEditor::OnlineResult &result) {
            if (!result.ok) {
                emit statusMessage(tr("The local runtime did not start: %1").arg(result.error));
                showLocalRuntime(result.error);
                if (failed)
                    failed(result.error);
                return;
            }
            m_localRuntime = result.value.value<Deploy::LocalRuntimeState>();
            m_nameService->addServer(m_localRuntime.nameServerAddress());
            m_docks.first()->show();
            showLocalRuntime();
            emit statusMessage(m_localRuntime.startedNow ? tr("Local runtime started.")
                                                         : tr("The local runtime was already running."));
            if (then)
                then(m_localRuntime);
        });
}

void OnlineDocks::stopLocalRuntime()
{
    m_session->submit(
        SystemEditor::OnlineSession::deploymentHost(),
        [ownership = m_ownership] {
            QString error;
            std::lock_guard lock(ownership->mutex);
            if (!Deploy::LocalRuntime().stop(&error))
                throw Corba::Error(Corba::Error::Kind::System, error);
            ownership->started = false;
            return QVariant();
        },
        this,
        [this](const SystemEditor::OnlineResult &result) {
            if (!result.ok) {
                emit statusMessage(result.error);
                return;
            }
            m_localRuntime = Deploy::LocalRuntimeState();
            showLocalRuntime();
            m_nameService->refresh();
            emit statusMessage(tr("Local runtime stopped."));
        });
}

void OnlineDocks::quitting()
{
    if (m_keepLocalRuntime && m_keepLocalRuntime->isChecked())
        return;
    std::lock_guard lock(m_ownership->mutex);
    m_ownership->quitting = true;
    if (m_ownership->started) {
        Deploy::LocalRuntime().stop(nullptr);
        m_ownership->started = false;
    }
}

void OnlineDocks::setManagerAtBoot(bool start, const QString &configFile,
                                   const std::function<void(const SystemEditor::OnlineResult &)> &done)
{
    // systemctl may wait on the session's systemd: it runs beside the other deployment calls.
    const Deploy::ManagerUnit unit(false, configFile, QSettings().value(UnitDirectoryKey).toString(),
                                   Codegen::Installation::managerProgram());
    m_session->submit(
        SystemEditor::OnlineSession::deploymentHost(),
        [unit, start]() -> QVariant {
            QString error;
            if (!(start ? unit.enable(&error) : unit.disable(&error)))
                throw std::runtime_error(error.toLocal8Bit().toStdString());
            return unit.path();
        },
        this, done);
}

void OnlineDocks::undeploy(const Profile::RtsProfile &profile, bool uninstall,
                           const std::function<void(const Deploy::DeployReport &)> &done)
{
    const Deploy::TargetOptions target = targetOptions();
    emit statusMessage(tr("Undeploying %1…").arg(systemName(profile)));
    m_session->submit(
        SystemEditor::OnlineSession::deploymentHost(),
        [profile, target, uninstall] {
            return QVariant::fromValue(
                Deploy::undeploySystem(profile, Deploy::planRestore(profile, target), target, uninstall));
        },
        this,
        [this, profile, done](const SystemEditor::OnlineResult &result) {
            Deploy::DeployReport report;
            if (result.ok) {
                report = result.value.value<Deploy::DeployReport>();
            } else {
                report.ok = false;
                report.error = result.error;
            }
            const auto count = [&report](const QString &action) {
                int n = 0;
                for (const Deploy::DeployStep &step : std::as_const(report.steps))
                    n += step.action == action && step.status == Deploy::StepStatus::Done ? 1 : 0;
                return n;
            };
            emit statusMessage(report.ok ? tr("%1 undeployed: %2 component(s) exited, %3 package(s) uninstalled.")
                                               .arg(systemName(profile))
                                               .arg(count(QStringLiteral("exit")))
                                               .arg(count(QStringLiteral("uninstall")))
                                         : tr("%1 was not undeployed: %2").arg(systemName(profile), report.error));
            m_nameService->refresh();
            if (done)
                done(report);
        });
}

void OnlineDocks::runLocally(const Profile::RtsProfile &profile,
                             const std::function<void(const QString &)> &done)
{
    startLocalRuntime([this, profile, done](const Deploy::LocalRuntimeState &state) {
        Deploy::TargetOptions target;
        target.nameServers = {state.nameServerAddress()};
        target.manager = QStringLiteral("corbaloc::127.0.0.1:%1").arg(state.manager.port);
        target.create = true;
        emit statusMessage(tr("Restoring %1 on the local runtime…").arg(systemName(profile)));
        m_session->submit(
            SystemEditor::OnlineSession::deploymentHost(),
            [profile, target] {
                const Deploy::RestorePlan plan = Deploy::planRestore(profile, target);
                Deploy::DeployReport report = Deploy::restoreSystem(profile, plan, target);
                if (report.ok)
                    report = Deploy::startSystem(profile, Deploy::planRestore(profile, target));
                if (!report.ok)
                    throw Corba::Error(Corba::Error::Kind::Refused, report.error);
                return QVariant();
            },
            this,
            [this, profile, done](const SystemEditor::OnlineResult &result) {
                if (!result.ok) {
                    emit statusMessage(tr("%1 did not run: %2").arg(systemName(profile), result.error));
                    if (done)
                        done(result.error);
                    return;
                }
                // The name server now holds the system's components: show them in the tree.
                m_nameService->refresh();
                OnlineDocument *online = openOnline(profile);
                watchFirstConnection(online, profile);
                emit statusMessage(tr("%1 runs on the local runtime.").arg(systemName(profile)));
                if (done)
                    done(QString());
            });
    }, done);
}

void OnlineDocks::watchFirstConnection(OnlineDocument *online, const Profile::RtsProfile &profile)
{
    // The OutPort of the first data connector, once its component is on the diagram.
    if (!online || !online->diagram() || profile.dataPortConnectors.isEmpty())
        return;
    const Profile::RtsTargetPort source = profile.dataPortConnectors.first().source;
    const QString instance = source.instanceName;
    const QString port = source.portName.section(QLatin1Char('.'), -1);
    const QPointer<OnlineDiagram> diagram(online->diagram());
    connect(diagram, &OnlineDiagram::componentAdded, this, [diagram, instance, port](const QString &added) {
        if (diagram && added == instance)
            diagram->monitorPort(instance, port);
    });
}

OnlineDocument *OnlineDocks::newDiagram()
{
    return m_documents ? m_documents->newOnlineDiagram(m_session) : nullptr;
}

OnlineDocument *OnlineDocks::currentDiagram() const
{
    if (auto *current
        = qobject_cast<OnlineDocument *>(m_activeDocument ? m_activeDocument() : nullptr))
        return current;
    if (!m_documents)
        return nullptr;
    const QList<Document *> documents = m_documents->documents();
    for (auto it = documents.crbegin(); it != documents.crend(); ++it) {
        if (auto *online = qobject_cast<OnlineDocument *>(*it))
            return online;
    }
    return nullptr;
}

void OnlineDocks::setPerspectiveActive(bool systemEditor)
{
    // The first switch to the System Editor opens the Name Service; later the user's choice holds.
    if (systemEditor && !m_shownOnce) {
        m_shownOnce = true;
        m_docks.first()->show();
        return;
    }
    if (!systemEditor) {
        for (QDockWidget *dock : m_docks)
            dock->hide();
    }
}

void OnlineDocks::showItem(const QModelIndex &index)
{
    if (!index.isValid())
        return;
    const auto type = Corba::NodeType(index.data(NameServiceModel::TypeRole).toInt());
    const QString path = index.data(NameServiceModel::PathRole).toString();
    const QString ior = index.data(NameServiceModel::IorRole).toString();
    if (ior.isEmpty())
        return;
    if (type == Corba::NodeType::Component) {
        m_configuration->setComponent(path, ior);
        m_contexts->setComponent(path, ior);
        m_docks.at(1)->show();
        m_docks.at(2)->show();
        m_docks.at(1)->raise();
    } else if (type == Corba::NodeType::Manager) {
        m_manager->setManager(path, ior);
        m_docks.at(3)->show();
        m_docks.at(3)->raise();
    }
}

Deploy::TargetOptions OnlineDocks::targetOptions() const
{
    Deploy::TargetOptions options;
    options.nameServers = m_nameService->model()->servers();
    return options;
}

SystemEditor::RestoreDialog *OnlineDocks::openRestore(const Profile::RtsProfile &profile)
{
    auto *dialog = new SystemEditor::RestoreDialog(m_session, profile, targetOptions(),
                                                   m_nameService->window());
    dialog->setObjectName(QStringLiteral("restoreDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setManagers(knownManagers());
    // A restore registers the components it creates: the tree shows them without a Refresh.
    connect(dialog, &SystemEditor::RestoreDialog::restored, m_nameService,
            &SystemEditor::NameServiceView::refresh);
    dialog->show();
    dialog->plan();
    return dialog;
}

QStringList OnlineDocks::knownManagers() const
{
    // The managers the Name Service tree has found so far, in tree order.
    QStringList managers;
    const NameServiceModel *model = m_nameService->model();
    QList<QModelIndex> pending {QModelIndex()};
    while (!pending.isEmpty()) {
        const QModelIndex parent = pending.takeFirst();
        for (int row = 0; row < model->rowCount(parent); ++row) {
            const QModelIndex child = model->index(row, 0, parent);
            if (Corba::NodeType(child.data(NameServiceModel::TypeRole).toInt())
                == Corba::NodeType::Manager)
                managers.append(child.data(NameServiceModel::PathRole).toString());
            pending.append(child);
        }
    }
    return managers;
}

SystemEditor::DriftView *OnlineDocks::compareWithFile(const QString &path)
{
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(path, &diagnostics);
    if (!loaded || !loaded->rts) {
        emit statusMessage(diagnostics.isEmpty()
                               ? tr("%1 is not a system profile.").arg(QFileInfo(path).fileName())
                               : diagnostics.first().toString());
        return nullptr;
    }
    auto *view = new SystemEditor::DriftView(m_session, *loaded->rts, targetOptions(),
                                             QFileInfo(path).fileName(), m_nameService->window());
    view->setObjectName(QStringLiteral("driftView"));
    view->setAttribute(Qt::WA_DeleteOnClose);
    view->show();
    view->refresh();
    return view;
}

QPointF OnlineDocks::nextPosition(int count)
{
    // New components go below each other, left of the data flow they will join.
    return QPointF(40 + 260 * (count % 3), 40 + 180 * (count / 3));
}

void OnlineDocks::addToDiagram(const QModelIndex &index)
{
    const auto type = Corba::NodeType(index.data(NameServiceModel::TypeRole).toInt());
    const QString ior = index.data(NameServiceModel::IorRole).toString();
    if (type != Corba::NodeType::Component || ior.isEmpty())
        return;
    OnlineDocument *online = currentDiagram();
    if (!online)
        online = newDiagram();
    if (!online || !online->diagram())
        return;
    OnlineDiagram *diagram = online->diagram();
    diagram->addComponent(index.data(NameServiceModel::PathRole).toString(), ior,
                          nextPosition(int(diagram->model()->componentIds().size())));
    emit m_documents->activationRequested(online);
}

OnlineDocument *OnlineDocks::openOnline(const Profile::RtsProfile &profile)
{
    OnlineDocument *online = newDiagram();
    if (!online || !online->diagram())
        return online;
    const QPointer<OnlineDiagram> diagram(online->diagram());
    const Deploy::TargetOptions options = targetOptions();
    // Start All and Stop All of this tab run the system's plan, as rtctl start / stop do.
    diagram->setSystem(profile, options);
    diagram->setHealRepository(QSettings().value(SystemEditor::RestoreDialog::RepositorySettingKey).toString());
    m_session->submit(
        SystemEditor::OnlineSession::deploymentHost(),
        [profile, options] { return QVariant::fromValue(Deploy::planRestore(profile, options)); },
        diagram,
        [this, diagram, profile](const SystemEditor::OnlineResult &result) {
            if (!result.ok)
                emit statusMessage(result.error);
            else if (diagram)
                placeMapped(diagram, profile, result.value);
        });
    return online;
}

void OnlineDocks::placeMapped(OnlineDiagram *diagram, const Profile::RtsProfile &profile,
                              const QVariant &plan)
{
    QStringList missing;
    int count = 0;
    for (const Deploy::ComponentMapping &c : plan.value<Deploy::RestorePlan>().components) {
        if (c.kind != Deploy::MappingKind::Existing) {
            missing.append(c.instanceName);
            continue;
        }
        QPointF position = nextPosition(count++);
        for (const Profile::RtsComponent &saved : profile.components) {
            if (saved.instanceName != c.instanceName || !saved.layout)
                continue;
            const auto x = Profile::RtsLocation::toInt(saved.layout->x);
            const auto y = Profile::RtsLocation::toInt(saved.layout->y);
            if (x && y)
                position = QPointF(*x, *y);
        }
        diagram->addComponent(c.path, c.ior, position);
    }
    if (!missing.isEmpty())
        emit statusMessage(tr("Not running: %1").arg(missing.join(QStringLiteral(", "))));
}

} // namespace Studio
