// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QAction;
class QTreeView;

namespace SystemEditor {

class RtcRepository;

/**
 * The Repository view of the offline System Editor: the RTC profiles of the repository as a
 * tree (category → component), with actions to add files, folders and component repositories
 * by URL, reload and remove a source. Components are dragged from it onto a system's canvas, which creates an instance.
 */
class RepositoryView : public QWidget
{
    Q_OBJECT

public:
    explicit RepositoryView(RtcRepository *repository, QWidget *parent = nullptr);

    RtcRepository *repository() const { return m_repository; }
    QTreeView *treeView() const { return m_tree; }
    QAction *addFilesAction() const { return m_addFiles; }
    QAction *addFolderAction() const { return m_addFolder; }
    QAction *reloadAction() const { return m_reload; }
    QAction *addUrlAction() const { return m_addUrl; }
    QAction *removePackageAction() const { return m_removePackage; }

    /// Adds sources and reports those that do not exist through statusMessage().
    void addSources(const QStringList &paths);

signals:
    void statusMessage(const QString &message);

private:
    void chooseFiles();
    void chooseFolder();
    void chooseUrl();

    RtcRepository *m_repository;
    QTreeView *m_tree;
    QAction *m_addFiles;
    QAction *m_addFolder;
    QAction *m_reload;
    QAction *m_addUrl;
    QAction *m_removePackage;
};

} // namespace SystemEditor
