// SPDX-License-Identifier: MIT
#include "restoredialog.h"

#include "deployer.h"
#include "onlinesession.h"
#include "restorer.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

Q_DECLARE_METATYPE(Deploy::RestorePlan)
Q_DECLARE_METATYPE(Deploy::DeployPlan)
Q_DECLARE_METATYPE(Deploy::DeployReport)

namespace SystemEditor {

namespace {

QTableWidgetItem *checkItem(bool checked)
{
    auto *item = new QTableWidgetItem;
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
    item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
    return item;
}

/// The mapping in the UI's language (rtctl prints the engine's English names).
QString mappingText(Deploy::MappingKind kind)
{
    switch (kind) {
    case Deploy::MappingKind::Existing:
        return RestoreDialog::tr("existing");
    case Deploy::MappingKind::Create:
        return RestoreDialog::tr("create");
    case Deploy::MappingKind::Missing:
        break;
    }
    return RestoreDialog::tr("missing");
}

QTableWidgetItem *textItem(const QString &text)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled);
    item->setToolTip(text);
    return item;
}

const QString ManagerAddressKey = QStringLiteral("manager_address=");

// `Type?instance_name=X&manager_address=host:port` → `host:port`.
QString managerAddress(const QString &createArgument)
{
    for (const QString &option :
         createArgument.section(QLatin1Char('?'), 1).split(QLatin1Char('&')))
        if (option.startsWith(ManagerAddressKey))
            return option.mid(ManagerAddressKey.size());
    return {};
}

// The create argument with its `manager_address` option replaced (removed when `address` is
// empty): the master manager creates the component in the manager at that address.
QString withManagerAddress(const QString &createArgument, const QString &address)
{
    const QString type = createArgument.section(QLatin1Char('?'), 0, 0);
    QStringList options;
    for (const QString &option :
         createArgument.section(QLatin1Char('?'), 1).split(QLatin1Char('&'), Qt::SkipEmptyParts))
        if (!option.startsWith(ManagerAddressKey))
            options.append(option);
    if (!address.trimmed().isEmpty())
        options.append(ManagerAddressKey + address.trimmed());
    return options.isEmpty() ? type : type + QLatin1Char('?') + options.join(QLatin1Char('&'));
}

} // namespace

RestoreDialog::RestoreDialog(OnlineSession *session, Profile::RtsProfile profile,
                             Deploy::TargetOptions options, QWidget *parent)
    : QDialog(parent)
    , m_session(session)
    , m_profile(std::move(profile))
    , m_options(std::move(options))
    , m_cancel(std::make_shared<std::atomic_bool>(false))
{
    setWindowTitle(tr("Restore System"));
    buildUi();
}

RestoreDialog::~RestoreDialog()
{
    // A restore still running stops at its next remote call and rolls back.
    m_cancel->store(true);
}

void RestoreDialog::buildUi()
{
    m_components = new QTableWidget(0, 8, this);
    m_components->setObjectName(QStringLiteral("componentTable"));
    m_components->setHorizontalHeaderLabels({tr("Component"), tr("Type"), tr("Mapping"),
                                             tr("Live path / note"), tr("Target manager"),
                                             tr("Restore"), tr("Activate"), tr("Install")});
    m_connectors = new QTableWidget(0, 4, this);
    m_connectors->setObjectName(QStringLiteral("connectorTable"));
    m_connectors->setHorizontalHeaderLabels({tr("Connector"), tr("From"), tr("To"), tr("Connect")});
    for (QTableWidget *table : {m_components, m_connectors}) {
        table->verticalHeader()->hide();
        table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
        table->horizontalHeader()->setStretchLastSection(true);
    }
    // The live path is the long text; the check boxes keep their width.
    m_components->horizontalHeader()->setStretchLastSection(false);
    m_components->horizontalHeader()->setSectionResizeMode(PathColumn, QHeaderView::Stretch);
    m_progress = new QListWidget(this);
    m_progress->setObjectName(QStringLiteral("progressList"));
    m_summary = new QLabel(tr("Mapping the live system…"), this);
    m_summary->setObjectName(QStringLiteral("summaryLabel"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_dryRun = buttons->addButton(tr("Dry Run"), QDialogButtonBox::ActionRole);
    m_dryRun->setObjectName(QStringLiteral("dryRunButton"));
    m_dryRun->setEnabled(false);
    connect(m_dryRun, &QPushButton::clicked, this, &RestoreDialog::dryRun);
    m_restore = buttons->addButton(tr("Restore"), QDialogButtonBox::AcceptRole);
    m_restore->setObjectName(QStringLiteral("restoreButton"));
    m_restore->setEnabled(false);
    connect(m_restore, &QPushButton::clicked, this, &RestoreDialog::restore);
    // While a restore runs: a busy bar, the step under way, and Cancel (which rolls back).
    m_busy = new QProgressBar(this);
    m_busy->setObjectName(QStringLiteral("restoreBusy"));
    m_busy->setRange(0, 0);
    m_busy->setTextVisible(false);
    m_busy->hide();
    m_stop = buttons->addButton(tr("Cancel Restore"), QDialogButtonBox::ActionRole);
    m_stop->setObjectName(QStringLiteral("cancelRestoreButton"));
    m_stop->hide();
    connect(m_stop, &QPushButton::clicked, this, [this] {
        cancelRestore();
        m_stop->setEnabled(false);
        m_summary->setText(tr("Cancelling: undoing what was done…"));
    });
    connect(buttons, &QDialogButtonBox::rejected, this, [this] {
        cancelRestore();
        reject();
    });

    m_create = new QCheckBox(tr("Create missing components through a manager:"), this);
    m_create->setObjectName(QStringLiteral("createCheck"));
    m_create->setChecked(m_options.create);
    m_manager = new QComboBox(this);
    m_manager->setObjectName(QStringLiteral("managerCombo"));
    m_manager->setEditable(true);
    m_manager->setMinimumContentsLength(40);
    m_manager->setEditText(m_options.manager);
    m_manager->setToolTip(tr("An rtshell path (/host:2809/host.host_cxt/manager.mgr) or a "
                             "corbaloc (corbaloc::host:2810)"));
    connect(m_create, &QCheckBox::toggled, this, &RestoreDialog::createChanged);
    connect(m_manager->lineEdit(), &QLineEdit::editingFinished, this, [this] {
        if (m_create->isChecked())
            createChanged();
    });
    connect(m_manager, &QComboBox::activated, this, [this] {
        if (m_create->isChecked())
            createChanged();
    });
    auto *createRow = new QHBoxLayout;
    createRow->addWidget(m_create);
    createRow->addWidget(m_manager, 1);
    m_install = new QCheckBox(tr("Install missing component types from repository:"), this);
    m_install->setObjectName(QStringLiteral("installCheck"));
    m_repository = new QLineEdit(this);
    m_repository->setObjectName(QStringLiteral("repositoryEdit"));
    m_repository->setPlaceholderText(tr("http://host/repo/, file:///path or a folder"));
    m_repository->setText(QSettings().value(RepositorySettingKey).toString());
    m_repository->setToolTip(tr("A component repository made with rtctl repo. Each manager that "
                                "creates components installs the packages of the types it cannot "
                                "load, verified with its own keyring."));
    // Installing is for components to be created, so it asks for creating too.
    connect(m_install, &QCheckBox::toggled, this, [this](bool on) {
        if (on && !m_create->isChecked())
            m_create->setChecked(true);
        else
            createChanged();
    });
    connect(m_repository, &QLineEdit::editingFinished, this, [this] {
        if (m_install->isChecked())
            createChanged();
    });
    auto *installRow = new QHBoxLayout;
    installRow->addWidget(m_install);
    installRow->addWidget(m_repository, 1);

    auto *splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_components);
    splitter->addWidget(m_connectors);
    splitter->addWidget(m_progress);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(createRow);
    layout->addLayout(installRow);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_busy);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    resize(980, 620);
}

void RestoreDialog::setManagers(const QStringList &managers)
{
    const QString current = m_manager->currentText();
    m_manager->clear();
    m_manager->addItems(managers);
    m_manager->setEditText(current.isEmpty() ? managers.value(0) : current);
}

void RestoreDialog::setCreateMissing(bool create, const QString &manager)
{
    const QSignalBlocker blocker(m_create);
    m_create->setChecked(create);
    m_manager->setEditText(manager);
    createChanged();
}

void RestoreDialog::setInstallFrom(const QString &repository)
{
    const QSignalBlocker blockInstall(m_install);
    const QSignalBlocker blockCreate(m_create);
    m_install->setChecked(!repository.isEmpty());
    m_repository->setText(repository);
    if (!repository.isEmpty())
        m_create->setChecked(true);
    createChanged();
}

bool RestoreDialog::installing() const
{
    return m_install->isChecked() && !m_repository->text().trimmed().isEmpty();
}

void RestoreDialog::createChanged()
{
    m_options.create = m_create->isChecked();
    m_options.manager = m_manager->currentText().trimmed();
    m_restore->setEnabled(false);
    m_dryRun->setEnabled(false);
    m_summary->setText(tr("Mapping the live system…"));
    plan();
}

void RestoreDialog::plan()
{
    const Profile::RtsProfile profile = m_profile;
    const Deploy::TargetOptions options = m_options;
    const QString repository = installing() ? m_repository->text().trimmed() : QString();
    const bool deploying = !repository.isEmpty() || hasPins();
    m_session->submit(
        OnlineSession::deploymentHost(),
        [profile, options, repository, deploying] {
            if (!deploying)
                return QVariant::fromValue(Deploy::planRestore(profile, options));
            Deploy::DeployOptions deploy;
            deploy.target = options;
            deploy.repository = repository;
            return QVariant::fromValue(Deploy::planDeploy(profile, deploy));
        },
        this,
        [this](const OnlineResult &result) {
            if (!result.ok) {
                m_summary->setText(result.error);
                return;
            }
            takePlan(result.value);
            showPlan();
            emit planned();
        });
}

void RestoreDialog::takePlan(const QVariant &value)
{
    m_deploying = value.canConvert<Deploy::DeployPlan>();
    if (m_deploying) {
        m_deployPlan = value.value<Deploy::DeployPlan>();
        m_plan = m_deployPlan.restore;
    } else {
        m_deployPlan = {};
        m_plan = value.value<Deploy::RestorePlan>();
    }
}

bool RestoreDialog::hasPins() const
{
    return std::any_of(m_profile.components.cbegin(), m_profile.components.cend(),
                       [](const Profile::RtsComponent &c) { return !Deploy::pinOf(c).isEmpty(); });
}

QString RestoreDialog::installFor(const Deploy::ComponentMapping &mapping) const
{
    if (mapping.kind != Deploy::MappingKind::Create)
        return {};
    for (const Deploy::PackageInstall &install : m_deployPlan.installs) {
        if (install.node == mapping.manager && install.types.contains(mapping.typeName))
            return QStringLiteral("%1 %2").arg(install.package, install.version);
    }
    return {};
}

void RestoreDialog::showPlan()
{
    m_components->setRowCount(0);
    for (const Deploy::ComponentMapping &c : m_plan.components) {
        const int row = m_components->rowCount();
        m_components->insertRow(row);
        m_components->setItem(row, NameColumn, textItem(c.instanceName));
        m_components->setItem(row, TypeColumn, textItem(c.typeName));
        m_components->setItem(row, MappingColumn, textItem(mappingText(c.kind)));
        m_components->setItem(row, PathColumn, textItem(c.message.isEmpty() ? c.path : c.message));
        // Only a component still to be created has a manager to choose.
        QTableWidgetItem *manager = textItem(managerAddress(c.createArgument));
        if (c.kind == Deploy::MappingKind::Create) {
            manager->setFlags(Qt::ItemIsEnabled | Qt::ItemIsEditable);
            manager->setToolTip(
                tr("host:port of the manager that runs it; empty: %1").arg(m_options.manager));
        }
        m_components->setItem(row, ManagerColumn, manager);
        m_components->setItem(row, RestoreColumn,
                              checkItem(c.kind != Deploy::MappingKind::Missing || c.required));
        m_components->setItem(row, ActivateColumn, checkItem(c.activate));
        m_components->setItem(row, InstallColumn, textItem(installFor(c)));
    }
    m_connectors->setRowCount(0);
    for (const Deploy::ConnectorPlan &c : m_plan.connectors) {
        const int row = m_connectors->rowCount();
        m_connectors->insertRow(row);
        m_connectors->setItem(row, 0, textItem(c.name.isEmpty() ? c.connectorId : c.name));
        m_connectors->setItem(row, 1, textItem(c.sourcePort));
        m_connectors->setItem(row, 2, textItem(c.targetPort));
        m_connectors->setItem(row, 3, checkItem(c.connect));
    }
    QStringList notes = m_plan.problems;
    for (const QString &problem : m_deployPlan.problems) {
        if (!notes.contains(problem))
            notes.append(problem);
    }
    const auto missing = m_plan.missingRequired();
    for (const Deploy::ComponentMapping &c : missing)
        notes.append(tr("%1 is required but not found").arg(c.instanceName));
    if (!missing.isEmpty() && !m_create->isChecked())
        notes.append(tr("Tick \"Create missing components\" to create them through a manager."));
    // A component pinned to a node has its manager already.
    bool unplaced = false;
    for (const Deploy::ComponentMapping &c : std::as_const(m_plan.components))
        unplaced = unplaced || (c.kind == Deploy::MappingKind::Create && c.manager.isEmpty());
    const bool noManager = unplaced && m_options.manager.isEmpty();
    if (noManager)
        notes.append(tr("Choose the manager that creates the missing components."));
    m_summary->setText(notes.isEmpty() ? tr("Ready to restore.") : notes.join(QLatin1Char('\n')));
    m_restore->setEnabled(missing.isEmpty() && !noManager && m_deployPlan.problems.isEmpty());
    m_dryRun->setEnabled(true);
}

Deploy::RestorePlan RestoreDialog::chosenPlan() const
{
    Deploy::RestorePlan plan = m_plan;
    QStringList skipped;
    for (int row = 0; row < plan.components.size(); ++row) {
        Deploy::ComponentMapping &c = plan.components[row];
        c.activate = m_components->item(row, ActivateColumn)->checkState() == Qt::Checked;
        if (c.kind == Deploy::MappingKind::Create)
            c.createArgument = withManagerAddress(c.createArgument,
                                                  m_components->item(row, ManagerColumn)->text());
        if (m_components->item(row, RestoreColumn)->checkState() == Qt::Unchecked) {
            // Left out on purpose: neither created nor required, and nothing connects to it.
            c.kind = Deploy::MappingKind::Missing;
            c.required = false;
            c.message = tr("not selected");
            skipped.append(c.instanceName);
        }
    }
    for (int row = 0; row < plan.connectors.size(); ++row) {
        Deploy::ConnectorPlan &c = plan.connectors[row];
        c.connect = m_connectors->item(row, 3)->checkState() == Qt::Checked
            && !skipped.contains(c.sourceInstance) && !skipped.contains(c.targetInstance);
    }
    return plan;
}

void RestoreDialog::dryRun()
{
    m_progress->clear();
    const Deploy::RestorePlan plan = chosenPlan();
    for (const Deploy::PackageInstall &install : m_deployPlan.installs)
        new QListWidgetItem(tr("planned: install %1 %2 on %3 (%4)")
                                .arg(install.package, install.version, install.node,
                                     install.types.join(QLatin1Char(' '))),
                            m_progress);
    for (const QString &line : plan.toText().split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        new QListWidgetItem(tr("planned: %1").arg(line), m_progress);
    for (const Deploy::ConnectorPlan &c : plan.connectors) {
        if (!c.connect)
            new QListWidgetItem(tr("skipped: connect %1 (not selected)").arg(c.connectorId),
                                m_progress);
    }
    m_summary->setText(tr("Dry run: nothing was changed."));
}

void RestoreDialog::restore()
{
    m_restore->setEnabled(false);
    m_progress->clear();
    m_cancel->store(false);
    const Profile::RtsProfile profile = m_profile;
    const Deploy::RestorePlan plan = chosenPlan();
    const Deploy::TargetOptions options = m_options;
    Deploy::DeployPlan deployPlan = m_deployPlan;
    deployPlan.restore = plan;
    Deploy::DeployOptions deploy;
    deploy.target = options;
    deploy.repository = installing() ? m_repository->text().trimmed() : QString();
    if (!deploy.repository.isEmpty())
        QSettings().setValue(RepositorySettingKey, deploy.repository);
    // The dialog restores; starting stays with Start All.
    deploy.start = false;
    const std::shared_ptr<std::atomic_bool> cancel = m_cancel;
    // Progress is reported in the worker thread; it reaches the list through the event loop.
    const QPointer<RestoreDialog> self(this);
    Deploy::DeployControl control;
    control.cancel = cancel.get();
    control.progress = [self](const Deploy::DeployStep &step) {
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [self, step] {
                if (self)
                    self->addProgress(step);
            },
            Qt::QueuedConnection);
    };
    m_summary->setText(tr("Restoring…"));
    m_busy->show();
    m_stop->setEnabled(true);
    m_stop->show();
    m_session->submit(
        OnlineSession::deploymentHost(),
        [profile, plan, options, deployPlan, deploy, deploying = m_deploying, control, cancel] {
            if (!deploying)
                return QVariant::fromValue(Deploy::restoreSystem(profile, plan, options, control));
            return QVariant::fromValue(Deploy::deploySystem(profile, deployPlan, deploy, control));
        },
        this,
        [this](const OnlineResult &result) {
            if (!result.ok) {
                m_report = {};
                m_report.ok = false;
                m_report.error = result.error;
            } else {
                m_report = result.value.value<Deploy::DeployReport>();
            }
            m_busy->hide();
            m_stop->hide();
            showReport();
            m_restore->setEnabled(true);
            emit restored(m_report.ok);
        });
}

void RestoreDialog::showReport()
{
    if (m_report.ok) {
        m_summary->setText(tr("Restored."));
        return;
    }
    QStringList lines {tr("Restore failed: %1").arg(m_report.error)};
    for (const Deploy::DeployStep &step : m_report.stepsWith(Deploy::StepStatus::Failed))
        lines.append(tr("Failed: %1").arg(step.summary()));
    QStringList undone;
    for (const Deploy::DeployStep &step : m_report.stepsWith(Deploy::StepStatus::RolledBack))
        undone.append(step.heading());
    lines.append(undone.isEmpty() ? tr("Nothing had to be rolled back.")
                                  : tr("Rolled back: %1").arg(undone.join(QStringLiteral(", "))));
    m_summary->setText(lines.join(QLatin1Char('\n')));
}

void RestoreDialog::cancelRestore()
{
    m_cancel->store(true);
}

void RestoreDialog::addProgress(const Deploy::DeployStep &step)
{
    if (step.status == Deploy::StepStatus::Running) {
        // What is under way now; the list keeps what finished.
        if (m_stop->isEnabled())
            m_summary->setText(tr("Restoring: %1…").arg(step.heading()));
        return;
    }
    auto *item = new QListWidgetItem(step.toString(), m_progress);
    if (step.status == Deploy::StepStatus::Failed)
        item->setForeground(QColor(200, 0, 0));
    m_progress->scrollToItem(item);
}

} // namespace SystemEditor
