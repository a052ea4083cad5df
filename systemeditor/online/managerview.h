// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"
#include "packageinstallerproxy.h"

#include <QMetaType>
#include <QWidget>

#include <optional>

#include <vector>

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace SystemEditor {

class OnlineSession;

/// One manager as the worker read it, with the names and references of its slaves.
struct ManagerSnapshot
{
    QString name; ///< the manager's `instance_name`
    bool master = false;
    QList<QPair<QString, QString>> slaves; ///< (instance name, IOR)
    std::vector<Corba::Properties> loadable;
    std::vector<Corba::Properties> loaded;
    std::vector<Corba::Properties> factories;
    std::vector<Corba::ComponentInfo> components;
    /// The component packages installed (rtmanager's install service); nothing when the manager
    /// has no install service (OpenRTM-aist's).
    std::optional<QList<Corba::InstalledPackageInfo>> packages;
};

/**
 * The Manager view of one live RTM::Manager: its slaves, loadable and loaded modules, factories
 * and component instances; create a component (type, target manager, parameter table with
 * `instance_name`), delete one, load/unload a module and shut the manager down; on a manager
 * with an install service, its installed component packages, install one by URL and uninstall
 * (what `rtctl node` does). Every call goes through the worker layer and the view is read back
 * after each action.
 */
class ManagerView : public QWidget
{
    Q_OBJECT

public:
    explicit ManagerView(OnlineSession *session, QWidget *parent = nullptr);

    void setManager(const QString &path, const QString &ior);
    void reload();
    const ManagerSnapshot &snapshot() const { return m_snapshot; }
    QTreeWidget *tree() const { return m_tree; }

    /// Component types the factories offer (their `type_name` or `implementation_id`).
    QStringList types() const;
    /// Target managers: this one first, then its slaves (names as shown in the combo box).
    QStringList targets() const;
    /// Sets the create form: type, target (index into targets()) and parameters (`instance_name`
    /// first when given).
    void setCreateForm(const QString &type, int target, const Corba::Properties &parameters);
    /// The `create_component` argument the form describes (`Type?k=v&…`).
    QString createArgument() const;
    void create();
    void deleteComponent(const QString &instanceName);
    void loadModule(const QString &path, const QString &initFunction);
    void unloadModule(const QString &path);
    void shutdown();
    /// Installs the package at @p url (`…/pool/…/NAME_VERSION_ARCH.deb[#SUITE]`).
    void installPackage(const QString &url);
    /// Uninstalls @p package (every version when @p version is empty).
    void uninstallPackage(const QString &package, const QString &version);

signals:
    void loaded();
    /// An action finished; `error` is empty on success.
    void actionFinished(const QString &error);

private:
    void buildUi();
    QWidget *buildCreateForm();
    void showSnapshot(const ManagerSnapshot &snapshot);
    QTreeWidgetItem *section(const QString &title, const QString &name);
    void submit(const QString &ior, const std::function<void()> &call);
    QString targetIor(int target) const;

    OnlineSession *m_session;
    QString m_path;
    QString m_ior;
    ManagerSnapshot m_snapshot;
    QLabel *m_title = nullptr;
    QTreeWidget *m_tree = nullptr;
    QComboBox *m_type = nullptr;
    QComboBox *m_target = nullptr;
    QTableWidget *m_parameters = nullptr;
    QLabel *m_status = nullptr;
    QPushButton *m_install = nullptr;
    QPushButton *m_uninstall = nullptr;
};

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::ManagerSnapshot)
