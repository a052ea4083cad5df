// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "diagnostic.h"
#include "generateoutcome.h"

#include <QPointer>
#include <QWidget>

class QLabel;
class QTabWidget;
class QToolBar;
class QUndoStack;

namespace Builder {

class BasicPage;
class BuildOutputPanel;
class ComponentPreview;
class TypeCatalog;

/**
 * RTC Builder's editor of one component: the pages (Basic, Activity, Data Ports, Service Ports,
 * Configuration, Documentation, Language/Environment, RTC.xml) as tabs along the bottom, with the
 * live preview beside them. Every page works on the same model and undo stack, so undo and redo
 * reach across pages.
 *
 * Generate asks generationProblems() first: with errors left, the editor lists them on the Basic
 * page and refuses (generateRefused()); otherwise it emits generateRequested(). Every outcome of
 * Generate (refused, failed, written) is announced as generationReported(), so that the
 * application can list it (the editor itself never depends on the application). Build (see
 * BuildController) reports the same way, and prints into buildOutputPanel().
 */
class ComponentEditor : public QWidget
{
    Q_OBJECT

public:
    /// `types` null: a catalog shared by all editors, loaded on first use.
    ComponentEditor(ComponentModel *model, QUndoStack *undoStack, TypeCatalog *types = nullptr,
                    QWidget *parent = nullptr);

    ComponentModel *model() const { return m_model; }
    QUndoStack *undoStack() const { return m_undoStack; }
    QTabWidget *pages() const { return m_pages; }
    BasicPage *basicPage() const { return m_basicPage; }
    ComponentPreview *preview() const { return m_preview; }
    /// The editor's own tool bar (Build and its settings); hidden while it has no actions.
    QToolBar *toolBar() const { return m_toolBar; }
    /// Where Build prints; below the pages, hidden until the first build.
    BuildOutputPanel *buildOutputPanel() const { return m_buildOutput; }
    TypeCatalog *typeCatalog() const { return m_types; }
    /// The page with the given tab title (e.g. "Data Ports"); null when there is none.
    QWidget *page(const QString &title) const;
    /// The user guide's section about the page in front ("Data Ports page"…), for F1.
    QString helpSection() const;

    /// True when something listens to generationReported() (then no summary dialog is needed).
    bool reportsGeneration() const;

    /// The shared catalog of IDL types (bundled IDL plus the user's folders).
    static TypeCatalog *sharedTypeCatalog();

public slots:
    /// Checks the component and emits generateRequested() or generateRefused().
    void requestGenerate();
    /// Announces an outcome of Generate (called by the GenerateController of this editor).
    void reportGeneration(const Builder::GenerateOutcome &outcome);

signals:
    /// Generation was asked for and the component has no errors.
    void generateRequested();
    /// Generation was asked for but these errors remain.
    void generateRefused(const Profile::Diagnostics &problems);
    /// What a Generate ended with: refused, failed, or the files written.
    void generationReported(const Builder::GenerateOutcome &outcome);
    void codeRestoreRequested();
    void clearBackupsRequested();

private:
    void addPages();

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    TypeCatalog *m_types;
    QTabWidget *m_pages;
    BasicPage *m_basicPage;
    ComponentPreview *m_preview;
    QToolBar *m_toolBar;
    BuildOutputPanel *m_buildOutput;
};

} // namespace Builder
