// SPDX-License-Identifier: MIT
#pragma once

#include "generateoutcome.h"
#include "modulerun.h"

#include <QObject>
#include <QPointer>

#include <functional>

class QAction;
class QThread;
class QWidget;

namespace Builder {

class BuildController;
class ComponentEditor;
class GenerateController;
class RunManagerDialog;

/**
 * The Builder's Run in Manager: loads the module Build produced (`<project>/build/src/<Name>.so`),
 * or a Python project's `<project>/<Name>.py` (which rtmanager runs in its own process), into a
 * running manager (rtmanager or OpenRTM-aist's rtcd) and creates the component from it,
 * so that it shows up in the System Editor's online views.
 *
 * The remote calls run one after the other on the controller's own worker thread, under one
 * overall timeout (timeout()); the GUI thread never waits for the manager. What the run ended
 * with is announced as runFinished() and, in the Builder's reporting format, as reported():
 * "Created Name0 in manager localhost:2810", or an error naming the manager and the module.
 *
 * The manager address is remembered in the settings together with the last few used ones.
 */
class RunController : public QObject
{
    Q_OBJECT

public:
    /// `projectFolder`: the folder Generate wrote into; `componentName`: the component's name.
    RunController(std::function<QString()> projectFolder, std::function<QString()> componentName,
                  QObject *parent = nullptr);
    ~RunController() override;

    /// Run in Manager…: enabled when the built module exists and nothing runs.
    QAction *runAction() const { return m_run; }

    /// The component's name; empty when it has none.
    QString componentName() const;
    /// The absolute path the built module has (whether or not it exists yet), or the Python
    /// project's module; empty when there is no project folder or name.
    QString modulePath() const;
    bool canRun() const;
    bool isRunning() const { return m_running; }

    /// The overall timeout of one run in milliseconds (default 10 s).
    int timeout() const { return m_timeout; }
    void setTimeout(int milliseconds) { m_timeout = milliseconds; }

    /// The manager address offered first (the last one used; default `localhost:2810`).
    static QString managerAddress();
    /// The addresses used before, most recent first (at most 10).
    static QStringList recentManagerAddresses();
    /// Remembers `address` as the most recent one.
    static void rememberManagerAddress(const QString &address);

    /// The dialog the Run in Manager… action opened, while it is open.
    RunManagerDialog *dialog() const;

public slots:
    /// Loads the built module into the manager at `address` (`host:port`) and creates the
    /// component; false when a run is in progress or there is no built module (reported).
    bool runInManager(const QString &address);
    /// Runs any module: what runInManager() does with the built one.
    bool runModule(const Builder::ModuleRunRequest &request);
    /// Opens the (non-modal) manager chooser over `parent`; its Run calls runInManager().
    void chooseManager(QWidget *parent);
    /// Re-evaluates whether Run in Manager… is enabled (after a build, a rename …).
    void updateActions();

signals:
    void runStarted(const Builder::ModuleRunRequest &request);
    void runFinished(const Builder::ModuleRunResult &result);
    /// What the run ended with, for the Problems panel and the status bar.
    void reported(const Builder::GenerateOutcome &outcome);

private:
    void finish(const ModuleRunResult &result);
    void reportFailure(const QString &message);

    std::function<QString()> m_projectFolder;
    std::function<QString()> m_componentName;
    QAction *m_run;
    QThread *m_thread;
    QObject *m_worker;
    QPointer<RunManagerDialog> m_dialog;
    int m_timeout = 10000;
    bool m_running = false;
};

/**
 * Gives `editor` its Run in Manager…: a RunController (a child of the editor) over the module
 * `build` produces from the folder `generate` writes into, its action on the editor's tool bar
 * after Build, and its outcome through ComponentEditor::reportGeneration().
 */
RunController *installRunController(ComponentEditor *editor, GenerateController *generate,
                                    BuildController *build);

} // namespace Builder
