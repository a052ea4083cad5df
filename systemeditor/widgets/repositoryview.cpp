// SPDX-License-Identifier: MIT
#include "repositoryview.h"

#include "rtcrepository.h"

#include <QAction>
#include <QFileDialog>
#include <QHeaderView>
#include <QInputDialog>
#include <QToolBar>
#include <QTreeView>
#include <QVBoxLayout>

namespace SystemEditor {

RepositoryView::RepositoryView(RtcRepository *repository, QWidget *parent)
    : QWidget(parent)
    , m_repository(repository)
    , m_tree(new QTreeView)
{
    m_tree->setObjectName(QStringLiteral("repositoryTree"));
    m_tree->setModel(repository);
    m_tree->setDragEnabled(true);
    m_tree->setDragDropMode(QAbstractItemView::DragOnly);
    m_tree->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_tree->setUniformRowHeights(true);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->expandAll();
    // New categories arrive expanded, so that their components can be dragged at once.
    connect(repository, &QAbstractItemModel::modelReset, m_tree, &QTreeView::expandAll);
    connect(repository, &QAbstractItemModel::rowsInserted, m_tree, &QTreeView::expandAll);

    auto *toolBar = new QToolBar;
    toolBar->setIconSize(QSize(16, 16));
    m_addFiles = toolBar->addAction(tr("Add Files…"), this, &RepositoryView::chooseFiles);
    m_addFolder = toolBar->addAction(tr("Add Folder…"), this, &RepositoryView::chooseFolder);
    m_addUrl = toolBar->addAction(tr("Add Repository URL…"), this, &RepositoryView::chooseUrl);
    m_addUrl->setObjectName(QStringLiteral("actionRepositoryAddUrl"));
    m_addUrl->setToolTip(tr("Add a component repository served over http or https (rtctl repo)"));
    m_reload = toolBar->addAction(tr("Reload"), repository, &RtcRepository::reload);
    m_addFiles->setObjectName(QStringLiteral("actionRepositoryAddFiles"));
    m_addFolder->setObjectName(QStringLiteral("actionRepositoryAddFolder"));
    m_reload->setObjectName(QStringLiteral("actionRepositoryReload"));
    m_addFolder->setToolTip(tr("Add a folder of RTC profiles, or a component repository folder"));

    connect(repository, &RtcRepository::repositoryRead, this, [this](const QString &source) {
        emit statusMessage(tr("Component repository %1 read.").arg(source));
    });
    // A package of a repository folder can be removed from it (rtctl repo remove).
    m_tree->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_removePackage = new QAction(tr("Remove Package from Repository"), m_tree);
    m_removePackage->setObjectName(QStringLiteral("actionRepositoryRemovePackage"));
    m_tree->addAction(m_removePackage);
    connect(m_removePackage, &QAction::triggered, this, [this] {
        if (!m_repository->removePackage(m_tree->currentIndex()))
            emit statusMessage(tr("Only a package of a component repository folder can be removed."));
    });
    connect(repository, &RtcRepository::packageRemoved, this, [this](const QString &package, const QString &error) {
        emit statusMessage(error.isEmpty() ? tr("Package %1 removed from its repository.").arg(package)
                                           : tr("Package %1 was not removed: %2").arg(package, error));
    });

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(toolBar);
    layout->addWidget(m_tree, 1);
}

void RepositoryView::addSources(const QStringList &paths)
{
    for (const QString &path : paths) {
        if (!m_repository->addSource(path))
            emit statusMessage(tr("\"%1\" does not exist.").arg(path));
    }
    m_tree->expandAll();
}

void RepositoryView::chooseFiles()
{
    addSources(QFileDialog::getOpenFileNames(this, tr("Add RTC Profiles"), QString(),
                                             tr("RTC profiles (*.xml *.yaml *.yml)")));
}

void RepositoryView::chooseFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Add Folder of RTC Profiles"));
    if (!folder.isEmpty())
        addSources({folder});
}

void RepositoryView::chooseUrl()
{
    const QString url = QInputDialog::getText(this, tr("Add Component Repository"),
                                              tr("Repository URL (http, https or file):"))
                            .trimmed();
    if (url.isEmpty())
        return;
    addSources({url});
    emit statusMessage(tr("Reading component repository %1…").arg(url));
}

} // namespace SystemEditor
