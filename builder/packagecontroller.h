// SPDX-License-Identifier: MIT
#pragma once

#include "generateoutcome.h"

#include <QObject>
#include <QPointer>

#include <functional>

class QAction;
class QThread;
class QWidget;

namespace Builder {

class BuildController;
class BuildOutputPanel;
class ComponentEditor;
class GenerateController;

/**
 * The Builder's Package and Publish: turns the built project (`<project>/build`) into a Debian
 * package in `<project>/packages/` with Packages::ComponentPackager (what `rtctl package` does),
 * and adds it to a Debian repository made by `rtctl repo init` (what `rtctl repo publish` does),
 * which signs its index again with the repository's key.
 *
 * The work runs on a thread of its own, its steps and result in the build output panel and, in
 * the Builder's reporting format, as reported(). A version already in the repository is refused
 * with a message saying so: a published version never changes under the machines that installed it.
 */
class PackageController : public QObject
{
    Q_OBJECT

public:
    /// Asks for the repository folder to publish into (given the last one); empty: cancelled.
    using RepositoryPrompt = std::function<QString(QWidget *parent, const QString &current)>;

    PackageController(BuildOutputPanel *panel, std::function<QString()> projectFolder,
                      QObject *parent = nullptr);
    ~PackageController() override;

    /// Package: enabled when the project was built and nothing runs.
    QAction *packageAction() const { return m_package; }
    /// Publish…: the same, then the repository it goes into.
    QAction *publishAction() const { return m_publish; }

    /// `<project>/packages`; empty without a project folder.
    QString outputFolder() const;
    bool canPackage() const;
    bool isRunning() const { return m_worker != nullptr; }
    /// The .deb the last successful run made.
    QString lastPackage() const { return m_lastPackage; }

    /// The repository folder offered first (the last one published into).
    static QString repositoryFolder();
    static void setRepositoryFolder(const QString &folder);
    /// Replaces the folder dialog of Publish… (tests answer without a modal dialog).
    void setRepositoryPrompt(RepositoryPrompt prompt) { m_prompt = std::move(prompt); }

public slots:
    /// Makes the package; false when a run is in progress or nothing was built (reported).
    bool package();
    /// Makes the package and publishes it into the repository at @p repository.
    bool publish(const QString &repository);
    /// Asks for the repository (over @p parent), then publish().
    void choosePublishRepository(QWidget *parent);
    void updateActions();

signals:
    /// A run ended: what it made and where it went, or why not.
    void finished(bool ok, const QString &message);
    void reported(const Builder::GenerateOutcome &outcome);

private:
    struct Outcome;
    bool start(const QString &repository);
    static void makeAndPublish(const QString &project, const QString &output, const QString &repository,
                               Outcome *outcome);
    void done(const Outcome &outcome);

    QPointer<BuildOutputPanel> m_panel;
    std::function<QString()> m_projectFolder;
    RepositoryPrompt m_prompt;
    QAction *m_package;
    QAction *m_publish;
    QThread *m_worker = nullptr;
    QString m_lastPackage;
};

/// Gives @p editor Package and Publish… after @p build's actions on its tool bar, enabled once a
/// build succeeded, reporting through ComponentEditor::reportGeneration().
PackageController *installPackageController(ComponentEditor *editor, GenerateController *generate,
                                            BuildController *build);

} // namespace Builder
