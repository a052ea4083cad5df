// SPDX-License-Identifier: MIT
#include "packagecontroller.h"

#include "buildcontroller.h"
#include "buildoutputpanel.h"
#include "componenteditor.h"
#include "componentmodel.h"
#include "componentpackager.h"
#include "generatecontroller.h"
#include "repository.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QThread>
#include <QToolBar>

using namespace Profile;

namespace Builder {

namespace {

const char RepositoryKey[] = "builder/publish/repository";

QString nativePath(const QString &path)
{
    return QDir::toNativeSeparators(path);
}

} // namespace

/// What a run ended with, handed from the worker thread to the GUI thread.
struct PackageController::Outcome
{
    bool ok = false;
    QString message;
    QString debFile;
    QStringList lines; ///< for the output panel
    QStringList warnings;
};

PackageController::PackageController(BuildOutputPanel *panel, std::function<QString()> projectFolder,
                                     QObject *parent)
    : QObject(parent)
    , m_panel(panel)
    , m_projectFolder(std::move(projectFolder))
    , m_package(new QAction(tr("&Package"), this))
    , m_publish(new QAction(tr("P&ublish…"), this))
{
    m_package->setObjectName(QStringLiteral("actionPackage"));
    m_package->setToolTip(tr("Make the Debian package (.deb) of the built component"));
    m_publish->setObjectName(QStringLiteral("actionPublish"));
    m_publish->setToolTip(tr("Make the package and add it to a component repository"));
    connect(m_package, &QAction::triggered, this, &PackageController::package);
    connect(m_publish, &QAction::triggered, this,
            [this] { choosePublishRepository(m_panel ? m_panel->window() : nullptr); });
    m_prompt = [](QWidget *parent, const QString &current) {
        return QFileDialog::getExistingDirectory(parent, tr("Publish into Repository"), current);
    };
    updateActions();
}

PackageController::~PackageController()
{
    // The tools it runs have timeouts of their own, so this wait ends.
    if (m_worker)
        m_worker->wait();
}

QString PackageController::outputFolder() const
{
    const QString folder = m_projectFolder ? m_projectFolder() : QString();
    return folder.isEmpty() ? QString() : QDir(folder).absoluteFilePath(QStringLiteral("packages"));
}

bool PackageController::canPackage() const
{
    const QString folder = m_projectFolder ? m_projectFolder() : QString();
    return !isRunning() && !folder.isEmpty()
        && QFileInfo::exists(QDir(folder).filePath(QStringLiteral("build/CMakeCache.txt")));
}

QString PackageController::repositoryFolder()
{
    return QSettings().value(QLatin1String(RepositoryKey)).toString();
}

void PackageController::setRepositoryFolder(const QString &folder)
{
    QSettings().setValue(QLatin1String(RepositoryKey), folder);
}

bool PackageController::package()
{
    return start(QString());
}

bool PackageController::publish(const QString &repository)
{
    if (repository.isEmpty())
        return false;
    return start(repository);
}

void PackageController::choosePublishRepository(QWidget *parent)
{
    if (isRunning())
        return;
    const QString repository = m_prompt ? m_prompt(parent, repositoryFolder()) : QString();
    if (repository.isEmpty())
        return;
    setRepositoryFolder(repository);
    publish(repository);
}

void PackageController::updateActions()
{
    const bool enabled = canPackage();
    m_package->setEnabled(enabled);
    m_publish->setEnabled(enabled);
}

bool PackageController::start(const QString &repository)
{
    if (isRunning())
        return false;
    const QString project = m_projectFolder ? m_projectFolder() : QString();
    if (!canPackage()) {
        Outcome outcome;
        outcome.message = project.isEmpty()
            ? tr("Nothing to package: generate and build the component's project first.")
            : tr("Nothing to package: build %1 first.").arg(nativePath(project));
        done(outcome);
        return false;
    }
    if (m_panel) {
        m_panel->show();
        m_panel->startBuild(repository.isEmpty()
                                ? tr("Packaging %1…").arg(nativePath(project))
                                : tr("Packaging %1 for %2…").arg(nativePath(project), nativePath(repository)));
    }
    const QString output = outputFolder();
    auto *outcome = new Outcome;
    m_worker = QThread::create([project, output, repository, outcome] {
        makeAndPublish(project, output, repository, outcome);
    });
    connect(m_worker, &QThread::finished, this, [this, outcome] {
        m_worker->deleteLater();
        m_worker = nullptr;
        const Outcome result = *outcome;
        delete outcome;
        done(result);
    });
    m_worker->start();
    updateActions();
    return true;
}

// Runs on the worker thread: nothing in here touches the controller or a widget.
void PackageController::makeAndPublish(const QString &project, const QString &output,
                                       const QString &repository, Outcome *outcome)
{
    if (!QDir().mkpath(output)) {
        outcome->message = tr("Cannot create the folder %1.").arg(nativePath(output));
        return;
    }
    Packages::PackageOptions options;
    options.projectDir = project;
    options.output = output;
    QString error;
    const std::optional<Packages::PackageResult> made
        = Packages::ComponentPackager(options).build(&error);
    if (!made) {
        outcome->message = tr("Packaging failed: %1").arg(error);
        return;
    }
    outcome->debFile = made->debFile;
    outcome->warnings = made->warnings;
    outcome->lines << tr("Made %1").arg(nativePath(made->debFile));
    outcome->lines += QString::fromUtf8(made->control.toText()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    if (repository.isEmpty()) {
        outcome->ok = true;
        outcome->message = tr("Made %1.").arg(nativePath(made->debFile));
        return;
    }
    Packages::Repository target(repository);
    if (!target.open(&error) || !target.publish({made->debFile}, false, &error)) {
        outcome->message = tr("Cannot publish %1 into %2: %3")
                               .arg(QFileInfo(made->debFile).fileName(), nativePath(repository), error);
        return;
    }
    outcome->ok = true;
    outcome->message = tr("Published %1 into %2.").arg(QFileInfo(made->debFile).fileName(), nativePath(repository));
}

void PackageController::done(const Outcome &outcome)
{
    if (outcome.ok)
        m_lastPackage = outcome.debFile;
    if (m_panel) {
        for (const QString &line : outcome.lines)
            m_panel->appendLine(line);
        for (const QString &warning : outcome.warnings)
            m_panel->appendLine(tr("warning: %1").arg(warning));
        m_panel->finishBuild(outcome.ok, outcome.message);
    }
    GenerateOutcome report;
    report.succeeded = outcome.ok;
    report.summary = outcome.message;
    for (const QString &warning : outcome.warnings)
        report.diagnostics << Diagnostic::warning(outcome.debFile, 0, 0, warning);
    if (!outcome.ok)
        report.diagnostics << Diagnostic::error(m_projectFolder ? m_projectFolder() : QString(), 0, 0,
                                                outcome.message);
    updateActions();
    emit finished(outcome.ok, outcome.message);
    emit reported(report);
}

PackageController *installPackageController(ComponentEditor *editor, GenerateController *generate,
                                            BuildController *build)
{
    const QPointer<GenerateController> source(generate);
    auto *controller = new PackageController(
        editor->buildOutputPanel(), [source] { return source ? source->outputFolder() : QString(); },
        editor);
    QToolBar *bar = editor->toolBar();
    bar->insertAction(build->cancelAction(), controller->packageAction());
    bar->insertAction(build->cancelAction(), controller->publishAction());
    QObject::connect(controller, &PackageController::reported, editor,
                     &ComponentEditor::reportGeneration);
    QObject::connect(build, &BuildController::reported, controller,
                     &PackageController::updateActions);
    QObject::connect(build, &BuildController::buildStarted, controller,
                     &PackageController::updateActions);
    QObject::connect(generate, &GenerateController::generated, controller,
                     &PackageController::updateActions);
    if (ComponentModel *model = editor->model())
        QObject::connect(model, &ComponentModel::profileReset, controller,
                         &PackageController::updateActions);
    return controller;
}

} // namespace Builder
