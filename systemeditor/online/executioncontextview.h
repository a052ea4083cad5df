// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QList>
#include <QWidget>

#include <functional>

class QDoubleSpinBox;
class QLabel;
class QMenu;
class QTableView;

namespace SystemEditor {

class ExecutionContextModel;
class NameServiceModel;
class OnlineSession;

/**
 * The Execution Context view of one live component: its owned and participating contexts with
 * kind, running state, rate, the component's state in each, the owner and the other participants;
 * Start/Stop and rate of the selected context, Activate/Deactivate/Reset of the component in it,
 * and Attach/Detach of other live components to/from it. All calls go through the worker layer;
 * the table is read back after every action.
 */
class ExecutionContextView : public QWidget
{
    Q_OBJECT

public:
    explicit ExecutionContextView(OnlineSession *session, QWidget *parent = nullptr);

    void setComponent(const QString &path, const QString &ior);
    QString componentPath() const { return m_path; }
    void reload();
    /**
     * The live components the session knows (components with a reference in the Name Service
     * model), offered as attach targets and used to name participants by path.
     */
    void setComponentSource(const NameServiceModel *model) { m_components = model; }

    ExecutionContextModel *model() const { return m_model; }
    QTableView *tableView() const { return m_table; }
    /// The selected context index (0 when nothing is selected).
    int currentContext() const;

    enum class Action { Start, Stop, Activate, Deactivate, Reset };
    /// Runs `action` on context `ecIndex`, then reloads.
    void perform(Action action, int ecIndex);
    void setRate(double rate, int ecIndex);

    /// Live components that could join context `ecIndex` (`name` holds the path).
    QList<Corba::ContextMember> attachCandidates(int ecIndex) const;
    /// Components that could leave context `ecIndex`: its participants, never its owner.
    QList<Corba::ContextMember> detachCandidates(int ecIndex) const;
    /// Makes `target` (`name` = path) take part in context `ecIndex`, then reloads.
    void attach(int ecIndex, const Corba::ContextMember &target);
    /// Takes `target` (`name` = path) out of context `ecIndex`, then reloads.
    void detach(int ecIndex, const Corba::ContextMember &target);
    /// The menu of the table: the actions above for context `ecIndex`; caller owns it.
    QMenu *createContextMenu(int ecIndex);

signals:
    void loaded();
    /// An action finished; `error` is empty on success.
    void actionFinished(const QString &error);

private:
    void buildUi();
    QLayout *buildButtons();
    void fillMemberMenu(QMenu *menu, const QList<Corba::ContextMember> &members, int ecIndex,
                        bool attaching);
    void popupMemberMenu(QWidget *button, bool attaching);
    QList<Corba::ContextMember> liveComponents() const;
    QString pathOf(const Corba::ContextMember &member) const;
    void fail(const QString &error);
    void submit(const QString &ior, const QString &path, const std::function<void()> &call);

    OnlineSession *m_session;
    const NameServiceModel *m_components = nullptr;
    QString m_path;
    QString m_ior;
    ExecutionContextModel *m_model;
    QTableView *m_table = nullptr;
    QDoubleSpinBox *m_rate = nullptr;
    QLabel *m_title = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace SystemEditor
