// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QMetaType>
#include <QWidget>

#include <vector>

class QCheckBox;
class QFormLayout;
class QLabel;
class QListWidget;
class QPushButton;

namespace SystemEditor {

class OnlineSession;
class ParameterEditor;

/// A component's configuration as the worker read it.
struct ConfigurationSnapshot
{
    std::vector<Corba::ConfigurationSet> sets;
    QString active;
};

/**
 * The Configuration view of one live component: its configuration sets with the active one
 * marked, add/copy/delete/activate, and the parameters of the selected set edited with the widgets
 * of `__widget__` and checked with `__constraints__`. Hidden sets (`__…__`) show in detail mode.
 * Apply writes the changed values through the worker layer and reads the sets back.
 */
class ConfigurationView : public QWidget
{
    Q_OBJECT

public:
    explicit ConfigurationView(OnlineSession *session, QWidget *parent = nullptr);

    /// Shows the component at `path` (with reference `ior`) and reads its configuration.
    void setComponent(const QString &path, const QString &ior);
    QString componentPath() const { return m_path; }
    void reload();

    void setDetailMode(bool on);
    bool detailMode() const;
    /// Set ids in the list, in order (hidden ones only in detail mode).
    QStringList shownSets() const;
    QString activeSet() const { return m_snapshot.active; }
    QString currentSet() const { return m_current; }
    void selectSet(const QString &id);

    /// The editor of parameter `name` in the selected set, or null.
    ParameterEditor *editor(const QString &name) const;
    /// True when a value differs from what was read and none breaks its constraint.
    bool canApply() const;

    /// Writes the changed values of the selected set; false (nothing sent) while a value is
    /// invalid.
    bool apply();
    /// Adds set `id` with the parameters of the selected set; `copyValues` keeps their values,
    /// otherwise the values of the `default` set are used.
    void addSet(const QString &id, bool copyValues);
    void deleteSet(const QString &id);
    void activateSet(const QString &id);

signals:
    /// The configuration was read (after setComponent, reload or an edit).
    void loaded();
    /// A remote edit finished; `error` is empty on success.
    void editFinished(const QString &error);

private:
    void buildUi();
    void showSnapshot(const ConfigurationSnapshot &snapshot);
    void fillSetList();
    void fillParameters();
    void updateButtons();
    const Corba::ConfigurationSet *set(const QString &id) const;
    void submitEdit(const std::function<void()> &edit);
    void askNewSet(bool copyValues);

    OnlineSession *m_session;
    QString m_path;
    QString m_ior;
    ConfigurationSnapshot m_snapshot;
    QString m_current;
    std::vector<ParameterEditor *> m_editors;

    QLabel *m_title = nullptr;
    QListWidget *m_sets = nullptr;
    QCheckBox *m_detail = nullptr;
    QWidget *m_parameterArea = nullptr;
    QFormLayout *m_form = nullptr;
    QPushButton *m_apply = nullptr;
    QPushButton *m_activate = nullptr;
    QPushButton *m_delete = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::ConfigurationSnapshot)
