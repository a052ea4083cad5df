// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QTableView;

namespace SystemEditor {

class ExecutionContextModel;
class OnlineSession;

/**
 * The Execution Context view of one live component: its owned and participating contexts with
 * kind, running state, rate and the component's state in each; Start/Stop and rate of the selected
 * context and Activate/Deactivate/Reset of the component in it. All calls go through the worker
 * layer; the table is read back after every action.
 */
class ExecutionContextView : public QWidget
{
    Q_OBJECT

public:
    explicit ExecutionContextView(OnlineSession *session, QWidget *parent = nullptr);

    void setComponent(const QString &path, const QString &ior);
    QString componentPath() const { return m_path; }
    void reload();

    ExecutionContextModel *model() const { return m_model; }
    QTableView *tableView() const { return m_table; }
    /// The selected context index (0 when nothing is selected).
    int currentContext() const;

    enum class Action { Start, Stop, Activate, Deactivate, Reset };
    /// Runs `action` on context `ecIndex`, then reloads.
    void perform(Action action, int ecIndex);
    void setRate(double rate, int ecIndex);

signals:
    void loaded();
    /// An action finished; `error` is empty on success.
    void actionFinished(const QString &error);

private:
    void buildUi();
    void submit(const std::function<void()> &call);

    OnlineSession *m_session;
    QString m_path;
    QString m_ior;
    ExecutionContextModel *m_model;
    QTableView *m_table = nullptr;
    QDoubleSpinBox *m_rate = nullptr;
    QLabel *m_title = nullptr;
    QLabel *m_status = nullptr;
};

} // namespace SystemEditor
