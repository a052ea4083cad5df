// SPDX-License-Identifier: MIT
#pragma once

#include "componentmapper.h"
#include "drift.h"
#include "rtsprofile.h"

#include <QDialog>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace SystemEditor {

class OnlineSession;

/**
 * Compare with File: what differs between a saved system and the live one, as the deployment
 * engine's drift (missing components and ports, missing and extra connectors, changed
 * configuration values and active sets, components in error or not answering), grouped by kind.
 * Each refresh maps the live system and compares off the GUI thread.
 */
class DriftView : public QDialog
{
    Q_OBJECT

public:
    /// `fileName` names the saved system in the title and the summary.
    DriftView(OnlineSession *session, Profile::RtsProfile profile, Deploy::TargetOptions options,
              const QString &fileName, QWidget *parent = nullptr);

    /// Compares again (asynchronously; refreshed() follows).
    void refresh();
    QList<Deploy::DriftItem> items() const { return m_items; }
    QTreeWidget *tree() const { return m_tree; }
    QString summary() const;

signals:
    void refreshed();

private:
    void buildUi();
    void showItems();

    OnlineSession *m_session;
    Profile::RtsProfile m_profile;
    Deploy::TargetOptions m_options;
    QString m_fileName;
    QList<Deploy::DriftItem> m_items;
    QTreeWidget *m_tree = nullptr;
    QLabel *m_summary = nullptr;
    QPushButton *m_refresh = nullptr;
    bool m_running = false;
};

} // namespace SystemEditor
