// SPDX-License-Identifier: MIT
#pragma once

#include "rtsprofile.h"

#include <functional>

#include <QWidget>

namespace Planner {
struct Plan;
}

class QAction;
class QLabel;
class QSplitter;
class QTabWidget;
class QTreeView;

namespace SystemEditor {
class PlanView;
class PropertiesPanel;
class RepositoryView;
class RtcRepository;
class SystemCanvas;
} // namespace SystemEditor

namespace Studio {

class RtsDocument;
class SystemInfoForm;
class SystemOutlineModel;

/**
 * The System Editor's editor of one system: the canvas takes most of the width; one column on
 * the right holds the repository of RTC profiles (drag one onto the canvas to add an instance)
 * and the outline above the properties of the selection and the system info, their tab bars
 * showing whole titles. The Plan view (where the planner puts each component) opens below the
 * canvas from the tool bar's Plan button. Everything listens to the document's SystemModel; edits
 * go through the document's undo stack.
 */
class RtsEditor : public QWidget
{
    Q_OBJECT

public:
    explicit RtsEditor(RtsDocument *document, QWidget *parent = nullptr);
    ~RtsEditor() override;

    RtsDocument *document() const { return m_document; }
    SystemOutlineModel *outlineModel() const { return m_outlineModel; }
    QTreeView *outlineView() const { return m_outlineView; }
    SystemInfoForm *systemInfoForm() const { return m_systemInfo; }
    SystemEditor::SystemCanvas *canvas() const { return m_canvas; }
    SystemEditor::PropertiesPanel *propertiesPanel() const { return m_properties; }
    SystemEditor::RepositoryView *repositoryView() const { return m_repositoryView; }
    SystemEditor::PlanView *planView() const { return m_planView; }
    /// Shows or hides the Plan view below the canvas (the tool bar's Plan button).
    void showPlanView(bool show);
    /// The last message the canvas gave (why a connection was refused, …).
    QString statusText() const;

    /**
     * The repository all system editors share. Its sources are remembered in the settings; the
     * first time, it holds the RTC profiles of the bundled examples when they can be found.
     */
    static SystemEditor::RtcRepository *sharedRepository();

    /// Deploys a system whose components are pinned where the plan puts them, from a repository
    /// (empty: none); set by the main window, which owns the online tools.
    using DeployHandler = std::function<void(const Profile::RtsProfile &system, const QString &repository)>;
    /// Makes every Plan view's Deploy call @p handler (and enables it).
    static void setDeployHandler(DeployHandler handler);

private:
    void deployPlan(const Planner::Plan &plan);

    QWidget *buildToolBar();
    QWidget *buildBrowserTabs();
    QWidget *buildDetailTabs();

    RtsDocument *m_document;
    SystemOutlineModel *m_outlineModel;
    QTreeView *m_outlineView;
    SystemInfoForm *m_systemInfo;
    SystemEditor::SystemCanvas *m_canvas;
    SystemEditor::PropertiesPanel *m_properties;
    SystemEditor::RepositoryView *m_repositoryView;
    SystemEditor::PlanView *m_planView;
    QAction *m_planAction = nullptr;
    QLabel *m_status;
    QSplitter *m_centre; ///< the canvas above the Plan view
    QSplitter *m_splitter;
};

} // namespace Studio
