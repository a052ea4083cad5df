// SPDX-License-Identifier: MIT
#include "onlinedocks.h"

#include "configurationview.h"
#include "executioncontextview.h"
#include "managerview.h"
#include "nameservicemodel.h"
#include "nameserviceview.h"
#include "onlinediagram.h"
#include "onlinesession.h"
#include "restoredialog.h"
#include "systemmodel.h"

#include <QAction>
#include <QDockWidget>
#include <QItemSelectionModel>
#include <QMainWindow>
#include <QSortFilterProxyModel>
#include <QTreeView>

namespace Studio {

using SystemEditor::NameServiceModel;

OnlineDocks::OnlineDocks(QMainWindow *window, QSettings *settings)
    : QObject(window)
    , m_session(new SystemEditor::OnlineSession(this))
    , m_nameService(new SystemEditor::NameServiceView(m_session, settings))
    , m_configuration(new SystemEditor::ConfigurationView(m_session))
    , m_contexts(new SystemEditor::ExecutionContextView(m_session))
    , m_manager(new SystemEditor::ManagerView(m_session))
    , m_diagram(new SystemEditor::OnlineDiagram(m_session))
{
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
    addDock(window, m_diagram, tr("Online Diagram"), QStringLiteral("onlineDiagramDock"),
            Qt::RightDockWidgetArea);
    window->tabifyDockWidget(configuration, contexts);
    window->tabifyDockWidget(contexts, manager);
    configuration->raise();
    connect(m_nameService->treeView()->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &current) {
                showItem(m_nameService->filterModel()->mapToSource(current));
            });
    connect(m_nameService->treeView(), &QTreeView::doubleClicked, this,
            [this](const QModelIndex &index) {
                addToDiagram(m_nameService->filterModel()->mapToSource(index));
            });
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

SystemEditor::RestoreDialog *OnlineDocks::openRestore(const Profile::RtsProfile &profile)
{
    Deploy::TargetOptions options;
    options.nameServers = m_nameService->model()->servers();
    auto *dialog
        = new SystemEditor::RestoreDialog(m_session, profile, options, m_nameService->window());
    dialog->setObjectName(QStringLiteral("restoreDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    dialog->plan();
    return dialog;
}

void OnlineDocks::addToDiagram(const QModelIndex &index)
{
    const auto type = Corba::NodeType(index.data(NameServiceModel::TypeRole).toInt());
    const QString ior = index.data(NameServiceModel::IorRole).toString();
    if (type != Corba::NodeType::Component || ior.isEmpty())
        return;
    // New components go below each other, left of the data flow they will join.
    const int count = int(m_diagram->model()->componentIds().size());
    m_diagram->addComponent(index.data(NameServiceModel::PathRole).toString(), ior,
                            QPointF(40 + 260 * (count % 3), 40 + 180 * (count / 3)));
    m_docks.at(4)->show();
}

} // namespace Studio
