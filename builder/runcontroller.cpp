// SPDX-License-Identifier: MIT
#include "runcontroller.h"

#include "buildcontroller.h"
#include "componenteditor.h"
#include "componentmodel.h"
#include "generatecontroller.h"
#include "pythonproject.h"
#include "runmanagerdialog.h"
#include "workerthread.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QThread>
#include <QToolBar>

namespace Builder {

namespace {

const char AddressKey[] = "builder/run/managerAddress";
const char RecentAddressesKey[] = "builder/run/recentManagerAddresses";
const int MaxRecentAddresses = 10;

QString defaultAddress()
{
    return QStringLiteral("localhost:2810");
}

} // namespace

RunController::RunController(std::function<QString()> projectFolder,
                             std::function<QString()> componentName, QObject *parent)
    : QObject(parent)
    , m_projectFolder(std::move(projectFolder))
    , m_componentName(std::move(componentName))
    , m_run(new QAction(tr("&Run in Manager…"), this))
    , m_thread(new QThread)
    , m_worker(new QObject)
{
    qRegisterMetaType<ModuleRunRequest>();
    qRegisterMetaType<ModuleRunResult>();
    m_run->setObjectName(QStringLiteral("actionRunInManager"));
    m_run->setToolTip(tr("Load the built module into a running manager and create the component"));
    connect(m_run, &QAction::triggered, this,
            [this] { chooseManager(qobject_cast<QWidget *>(this->parent())); });
    m_thread->setObjectName(QStringLiteral("builder:run"));
    m_worker->moveToThread(m_thread);
    m_thread->start();
    updateActions();
}

RunController::~RunController()
{
    // A run inside a call to a hung manager ends with its timeout.
    Corba::retireWorkerThread(m_thread, m_worker, QDeadlineTimer(m_timeout + 1000));
}

QString RunController::componentName() const
{
    return m_componentName ? m_componentName().trimmed() : QString();
}

QString RunController::modulePath() const
{
    const QString folder = m_projectFolder ? m_projectFolder() : QString();
    const QString name = componentName();
    if (folder.isEmpty() || name.isEmpty())
        return QString();
    // A Python project's module is its source, which managers run as it is.
    const Codegen::PythonProject python(folder, name);
    if (python.exists())
        return python.modulePath();
    // Where the generated src/CMakeLists.txt puts the module: no "lib" prefix, in build/src.
    return QDir::cleanPath(
        QDir(folder).absoluteFilePath(QStringLiteral("build/src/%1.so").arg(name)));
}

bool RunController::canRun() const
{
    const QString path = modulePath();
    return !m_running && !path.isEmpty() && QFileInfo(path).isFile();
}

QString RunController::managerAddress()
{
    return QSettings().value(QLatin1String(AddressKey), defaultAddress()).toString();
}

QStringList RunController::recentManagerAddresses()
{
    QStringList addresses = QSettings().value(QLatin1String(RecentAddressesKey)).toStringList();
    if (addresses.isEmpty())
        addresses << defaultAddress();
    return addresses;
}

void RunController::rememberManagerAddress(const QString &address)
{
    QStringList addresses = QSettings().value(QLatin1String(RecentAddressesKey)).toStringList();
    addresses.removeAll(address);
    addresses.prepend(address);
    while (addresses.size() > MaxRecentAddresses)
        addresses.removeLast();
    QSettings settings;
    settings.setValue(QLatin1String(AddressKey), address);
    settings.setValue(QLatin1String(RecentAddressesKey), addresses);
}

bool RunController::runInManager(const QString &address)
{
    const QString name = componentName();
    const QString path = modulePath();
    if (path.isEmpty() || !QFileInfo(path).isFile()) {
        reportFailure(path.isEmpty() ? tr("Nothing to run: generate and build the component first.")
                                     : tr("Nothing to run: %1 was not built yet.").arg(path));
        return false;
    }
    return runModule({address.trimmed(), path, name + QStringLiteral("Init"), name});
}

bool RunController::runModule(const ModuleRunRequest &request)
{
    if (m_running)
        return false;
    m_running = true;
    rememberManagerAddress(request.managerAddress);
    updateActions();
    emit runStarted(request);
    const int timeout = m_timeout;
    // The queued invocation runs in the worker thread; the result comes back queued as well, and
    // is dropped by Qt if this controller is gone by then.
    QMetaObject::invokeMethod(
        m_worker,
        [this, request, timeout] {
            const ModuleRunResult result = ModuleRun::run(request, timeout);
            QMetaObject::invokeMethod(
                this, [this, result] { finish(result); }, Qt::QueuedConnection);
        },
        Qt::QueuedConnection);
    return true;
}

RunManagerDialog *RunController::dialog() const
{
    return m_dialog;
}

void RunController::chooseManager(QWidget *parent)
{
    if (m_dialog) {
        m_dialog->raise();
        m_dialog->activateWindow();
        return;
    }
    m_dialog = new RunManagerDialog(recentManagerAddresses(), modulePath(), parent);
    m_dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_dialog, &RunManagerDialog::runRequested, this, &RunController::runInManager);
    m_dialog->show();
}

void RunController::updateActions()
{
    m_run->setEnabled(canRun());
}

void RunController::finish(const ModuleRunResult &result)
{
    m_running = false;
    updateActions();
    GenerateOutcome outcome;
    outcome.succeeded = result.ok;
    const QString manager = tr("manager %1").arg(result.request.managerAddress);
    if (result.ok) {
        outcome.summary = tr("Created %1 in manager %2.")
                              .arg(result.instanceName, result.request.managerAddress);
        Profile::Diagnostic created;
        created.severity = Profile::Diagnostic::Severity::Info;
        created.object = manager;
        created.message = outcome.summary;
        if (result.alreadyLoaded) {
            Profile::Diagnostic loaded = created;
            loaded.message = tr("%1 was loaded already: the manager keeps the code it loaded "
                                "first.")
                                 .arg(result.request.modulePath);
            outcome.diagnostics << loaded;
        }
        outcome.diagnostics << created;
    } else {
        outcome.summary = result.error;
        Profile::Diagnostic error = Profile::Diagnostic::error(QString(), 0, 0, result.error);
        error.object = manager;
        outcome.diagnostics << error;
    }
    emit runFinished(result);
    emit reported(outcome);
}

void RunController::reportFailure(const QString &message)
{
    GenerateOutcome outcome;
    outcome.summary = message;
    outcome.diagnostics << Profile::Diagnostic::error(QString(), 0, 0, message);
    emit reported(outcome);
}

RunController *installRunController(ComponentEditor *editor, GenerateController *generate,
                                    BuildController *build)
{
    const QPointer<GenerateController> source(generate);
    const QPointer<ComponentModel> model(editor->model());
    auto *controller = new RunController(
        [source] { return source ? source->outputFolder() : QString(); },
        [model] { return model ? model->profile().basicInfo.name : QString(); }, editor);
    QToolBar *bar = editor->toolBar();
    // Right after Build, before Cancel Build and the settings.
    bar->insertAction(build->cancelAction(), controller->runAction());
    QObject::connect(controller, &RunController::reported, editor,
                     &ComponentEditor::reportGeneration);
    // The module appears when a build ends, and its name follows the component's.
    QObject::connect(build, &BuildController::reported, controller, &RunController::updateActions);
    QObject::connect(generate, &GenerateController::generated, controller,
                     &RunController::updateActions);
    if (ComponentModel *m = editor->model()) {
        QObject::connect(m, &ComponentModel::componentIdChanged, controller,
                         &RunController::updateActions);
        QObject::connect(m, &ComponentModel::profileReset, controller,
                         &RunController::updateActions);
    }
    return controller;
}

} // namespace Builder
