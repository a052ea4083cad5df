// SPDX-License-Identifier: MIT
#include "buildcontroller.h"

#include "buildoutputpanel.h"
#include "buildsettingsdialog.h"
#include "componenteditor.h"
#include "componentmodel.h"
#include "generatecontroller.h"
#include "packagecontroller.h"
#include "projectbuilder.h"
#include "pythonproject.h"
#include "runcontroller.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QToolBar>

using namespace Profile;

namespace Builder {

namespace {

const char SdkPrefixKey[] = "builder/build/sdkPrefix";
const char BuildTypeKey[] = "builder/build/buildType";

} // namespace

BuildController::BuildController(BuildOutputPanel *panel, std::function<QString()> projectFolder,
                                 QObject *parent)
    : QObject(parent)
    , m_panel(panel)
    , m_projectFolder(std::move(projectFolder))
    , m_builder(new Codegen::ProjectBuilder(this))
    , m_build(new QAction(tr("&Build"), this))
    , m_cancel(new QAction(tr("Cancel Build"), this))
    , m_settings(new QAction(tr("Build &Settings…"), this))
{
    m_build->setObjectName(QStringLiteral("actionBuild"));
    m_build->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_B));
    m_build->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_build->setToolTip(tr("Configure and build the generated C++ project with CMake, or check that the "
                           "Python component loads into a manager"));
    m_cancel->setObjectName(QStringLiteral("actionCancelBuild"));
    m_cancel->setToolTip(tr("Stop the running build"));
    m_settings->setObjectName(QStringLiteral("actionBuildSettings"));
    m_settings->setToolTip(tr("The SDK prefix (CMAKE_PREFIX_PATH) and the build type"));
    connect(m_build, &QAction::triggered, this, &BuildController::build);
    connect(m_cancel, &QAction::triggered, this, &BuildController::cancel);
    connect(m_settings, &QAction::triggered, this,
            [this] { editSettings(m_panel ? m_panel->window() : nullptr); });
    if (m_panel)
        connect(m_panel, &BuildOutputPanel::cancelRequested, this, &BuildController::cancel);
    connect(m_builder, &Codegen::ProjectBuilder::output, this, [this](const QString &line) {
        if (m_panel)
            m_panel->appendLine(line);
    });
    connect(m_builder, &Codegen::ProjectBuilder::progress, this, [this](int done, int total) {
        if (m_panel)
            m_panel->setProgress(done, total);
    });
    connect(m_builder, &Codegen::ProjectBuilder::finished, this, &BuildController::buildFinished);
    updateActions();
}

BuildController::~BuildController() = default;

QString BuildController::sdkPrefix()
{
    const QSettings settings;
    return settings.contains(QLatin1String(SdkPrefixKey))
        ? settings.value(QLatin1String(SdkPrefixKey)).toString()
        : Codegen::ProjectBuilder::defaultSdkPrefix();
}

void BuildController::setSdkPrefix(const QString &prefix)
{
    QSettings().setValue(QLatin1String(SdkPrefixKey), prefix);
}

void BuildController::resetSdkPrefix()
{
    QSettings().remove(QLatin1String(SdkPrefixKey));
}

QString BuildController::buildType()
{
    const QString type = QSettings().value(QLatin1String(BuildTypeKey)).toString();
    return type == QLatin1String("Debug") ? type : QStringLiteral("Release");
}

void BuildController::setBuildType(const QString &type)
{
    QSettings().setValue(QLatin1String(BuildTypeKey), type);
}

QString BuildController::projectFolder() const
{
    return m_projectFolder ? m_projectFolder() : QString();
}

bool BuildController::canBuild() const
{
    const QString folder = projectFolder();
    return !isRunning() && !folder.isEmpty()
        && (QFileInfo::exists(QDir(folder).filePath(QStringLiteral("CMakeLists.txt")))
            || Codegen::PythonProject::inFolder(folder));
}

bool BuildController::isRunning() const
{
    return m_builder->isRunning();
}

bool BuildController::build()
{
    if (isRunning())
        return false;
    const QString folder = projectFolder();
    if (folder.isEmpty()) {
        const QString message = tr("Nothing to build: generate the component's project first.");
        if (m_panel)
            m_panel->finishBuild(false, message);
        GenerateOutcome outcome;
        outcome.summary = message;
        outcome.diagnostics << Diagnostic::error(QString(), 0, 0, message);
        emit reported(outcome);
        return false;
    }
    Codegen::BuildOptions options;
    options.projectDir = folder;
    options.prefixPath = sdkPrefix();
    options.configuration = buildType();
    if (m_panel) {
        m_panel->show();
        m_panel->startBuild(tr("Building %1…").arg(QDir::toNativeSeparators(folder)));
    }
    emit buildStarted();
    // One that cannot start has reported why (finished()) before start() returns.
    const bool started = m_builder->start(options);
    updateActions();
    return started;
}

void BuildController::cancel()
{
    m_builder->cancel();
}

void BuildController::updateActions()
{
    m_build->setEnabled(canBuild());
    m_cancel->setEnabled(isRunning());
}

void BuildController::editSettings(QWidget *parent)
{
    BuildSettingsDialog dialog(sdkPrefix(), Codegen::ProjectBuilder::defaultSdkPrefix(),
                               buildType(), parent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    setSdkPrefix(dialog.sdkPrefix());
    setBuildType(dialog.buildType());
}

void BuildController::buildFinished(bool ok, const QString &message)
{
    if (m_panel)
        m_panel->finishBuild(ok, message);
    GenerateOutcome outcome;
    outcome.succeeded = ok;
    outcome.summary = message;
    outcome.diagnostics = m_builder->problems();
    // A failure the parser recognised nothing in still gets a row, naming the folder.
    if (!ok && !hasErrors(outcome.diagnostics) && !m_builder->wasCancelled())
        outcome.diagnostics << Diagnostic::error(projectFolder(), 0, 0, message);
    updateActions();
    emit reported(outcome);
}

BuildController *installBuildController(ComponentEditor *editor, GenerateController *generate)
{
    const QPointer<GenerateController> source(generate);
    auto *controller = new BuildController(
        editor->buildOutputPanel(),
        [source] { return source ? source->outputFolder() : QString(); }, editor);
    QToolBar *bar = editor->toolBar();
    bar->addAction(controller->buildAction());
    bar->addAction(controller->cancelAction());
    bar->addAction(controller->settingsAction());
    bar->show();
    // The shortcut works anywhere in the editor, not only on the tool bar.
    editor->addAction(controller->buildAction());
    QObject::connect(controller, &BuildController::reported, editor,
                     &ComponentEditor::reportGeneration);
    // Build becomes possible once Generate wrote a project, or the component names another one.
    QObject::connect(generate, &GenerateController::generated, controller,
                     &BuildController::updateActions);
    if (ComponentModel *model = editor->model()) {
        QObject::connect(model, &ComponentModel::componentIdChanged, controller,
                         &BuildController::updateActions);
        QObject::connect(model, &ComponentModel::profileReset, controller,
                         &BuildController::updateActions);
    }
    installRunController(editor, generate, controller);
    installPackageController(editor, generate, controller);
    return controller;
}

} // namespace Builder
