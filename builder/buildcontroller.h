// SPDX-License-Identifier: MIT
#pragma once

#include "generateoutcome.h"

#include <QObject>
#include <QPointer>

#include <functional>

class QAction;
class QWidget;

namespace Codegen {
class ProjectBuilder;
}

namespace Builder {

class BuildOutputPanel;
class ComponentEditor;
class GenerateController;

/**
 * The Builder's Build: configures and builds the project Generate wrote (the folder given by
 * `projectFolder`, normally GenerateController::outputFolder()) with Codegen::ProjectBuilder,
 * in the background. Output and progress go to a BuildOutputPanel; what the build ended with
 * (its summary, and the compiler and CMake errors and warnings with file and line) is announced
 * as reported(), which the application lists in its Problems panel like Generate's outcome.
 *
 * The SDK prefix (CMAKE_PREFIX_PATH) and the build type are settings shared by all components;
 * the prefix defaults to ProjectBuilder::defaultSdkPrefix(). Nothing here opens a dialog except
 * Build Settings, which the user asks for.
 */
class BuildController : public QObject
{
    Q_OBJECT

public:
    BuildController(BuildOutputPanel *panel, std::function<QString()> projectFolder,
                    QObject *parent = nullptr);
    ~BuildController() override;

    /// Build (Ctrl+B): enabled when the project folder holds a generated CMake or Python project
    /// and no build runs.
    QAction *buildAction() const { return m_build; }
    /// Cancel Build: enabled while a build runs.
    QAction *cancelAction() const { return m_cancel; }
    /// Build Settings…: the SDK prefix and the build type.
    QAction *settingsAction() const { return m_settings; }
    Codegen::ProjectBuilder *projectBuilder() const { return m_builder; }

    /// CMAKE_PREFIX_PATH for builds; empty: none is passed.
    static QString sdkPrefix();
    static void setSdkPrefix(const QString &prefix);
    /// Forgets the chosen prefix, so that the default applies again.
    static void resetSdkPrefix();
    /// `Release` (default) or `Debug`.
    static QString buildType();
    static void setBuildType(const QString &type);

    /// The folder Build would build; empty when nothing was generated yet.
    QString projectFolder() const;
    bool canBuild() const;
    bool isRunning() const;

public slots:
    /// Starts a build of the project folder; false when one runs already or it cannot start
    /// (the reason is reported).
    bool build();
    void cancel();
    /// Re-evaluates which actions are enabled (after a Generate, a change of component id …).
    void updateActions();
    /// Asks for the SDK prefix and build type (a dialog over `parent`).
    void editSettings(QWidget *parent);

signals:
    void buildStarted();
    /// What the build ended with.
    void reported(const Builder::GenerateOutcome &outcome);

private:
    void buildFinished(bool ok, const QString &message);

    QPointer<BuildOutputPanel> m_panel;
    std::function<QString()> m_projectFolder;
    Codegen::ProjectBuilder *m_builder;
    QAction *m_build;
    QAction *m_cancel;
    QAction *m_settings;
};

/**
 * Gives `editor` its Build: a BuildController (a child of the editor) over the folder
 * `generate` writes into, its actions on the editor's tool bar, its output in the editor's
 * build output panel and its outcome through ComponentEditor::reportGeneration(). Run in
 * Manager… (installRunController()), Package and Publish… (installPackageController()) come
 * with it.
 */
BuildController *installBuildController(ComponentEditor *editor, GenerateController *generate);

} // namespace Builder
