// SPDX-License-Identifier: MIT
#include "restoredialog.h"

#include "onlinesession.h"
#include "restorer.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPointer>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

Q_DECLARE_METATYPE(Deploy::RestorePlan)
Q_DECLARE_METATYPE(Deploy::DeployReport)

namespace SystemEditor {

namespace {

// The deployment engine talks to many hosts; its calls share one worker of their own.
const QString DeployHost = QStringLiteral("deployment");

QTableWidgetItem *checkItem(bool checked)
{
    auto *item = new QTableWidgetItem;
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
    item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
    return item;
}

QTableWidgetItem *textItem(const QString &text)
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled);
    item->setToolTip(text);
    return item;
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
    m_components = new QTableWidget(0, 5, this);
    m_components->setObjectName(QStringLiteral("componentTable"));
    m_components->setHorizontalHeaderLabels(
        {tr("Component"), tr("Type"), tr("Mapping"), tr("Live path / note"), tr("Activate")});
    m_connectors = new QTableWidget(0, 4, this);
    m_connectors->setObjectName(QStringLiteral("connectorTable"));
    m_connectors->setHorizontalHeaderLabels({tr("Connector"), tr("From"), tr("To"), tr("Connect")});
    for (QTableWidget *table : {m_components, m_connectors}) {
        table->verticalHeader()->hide();
        table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
        table->horizontalHeader()->setStretchLastSection(true);
    }
    m_progress = new QListWidget(this);
    m_progress->setObjectName(QStringLiteral("progressList"));
    m_summary = new QLabel(tr("Mapping the live system…"), this);
    m_summary->setObjectName(QStringLiteral("summaryLabel"));
    m_summary->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_restore = buttons->addButton(tr("Restore"), QDialogButtonBox::AcceptRole);
    m_restore->setObjectName(QStringLiteral("restoreButton"));
    m_restore->setEnabled(false);
    connect(m_restore, &QPushButton::clicked, this, &RestoreDialog::restore);
    connect(buttons, &QDialogButtonBox::rejected, this, [this] {
        cancelRestore();
        reject();
    });

    auto *splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_components);
    splitter->addWidget(m_connectors);
    splitter->addWidget(m_progress);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    resize(820, 560);
}

void RestoreDialog::plan()
{
    const Profile::RtsProfile profile = m_profile;
    const Deploy::TargetOptions options = m_options;
    m_session->submit(
        DeployHost,
        [profile, options] { return QVariant::fromValue(Deploy::planRestore(profile, options)); },
        this,
        [this](const OnlineResult &result) {
            if (!result.ok) {
                m_summary->setText(result.error);
                return;
            }
            m_plan = result.value.value<Deploy::RestorePlan>();
            showPlan();
            emit planned();
        });
}

void RestoreDialog::showPlan()
{
    m_components->setRowCount(0);
    for (const Deploy::ComponentMapping &c : m_plan.components) {
        const int row = m_components->rowCount();
        m_components->insertRow(row);
        m_components->setItem(row, 0, textItem(c.instanceName));
        m_components->setItem(row, 1, textItem(c.typeName));
        m_components->setItem(row, 2, textItem(Deploy::mappingKindName(c.kind)));
        m_components->setItem(row, 3, textItem(c.message.isEmpty() ? c.path : c.message));
        m_components->setItem(row, 4, checkItem(c.activate));
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
    const auto missing = m_plan.missingRequired();
    for (const Deploy::ComponentMapping &c : missing)
        notes.append(tr("%1 is required but not found").arg(c.instanceName));
    m_summary->setText(notes.isEmpty() ? tr("Ready to restore.") : notes.join(QLatin1Char('\n')));
    m_restore->setEnabled(missing.isEmpty());
}

Deploy::RestorePlan RestoreDialog::chosenPlan() const
{
    Deploy::RestorePlan plan = m_plan;
    for (int row = 0; row < plan.components.size(); ++row)
        plan.components[row].activate = m_components->item(row, 4)->checkState() == Qt::Checked;
    for (int row = 0; row < plan.connectors.size(); ++row)
        plan.connectors[row].connect = m_connectors->item(row, 3)->checkState() == Qt::Checked;
    return plan;
}

void RestoreDialog::restore()
{
    m_restore->setEnabled(false);
    m_progress->clear();
    m_cancel->store(false);
    const Profile::RtsProfile profile = m_profile;
    const Deploy::RestorePlan plan = chosenPlan();
    const Deploy::TargetOptions options = m_options;
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
    m_session->submit(
        DeployHost,
        [profile, plan, options, control, cancel] {
            return QVariant::fromValue(Deploy::restoreSystem(profile, plan, options, control));
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
            m_summary->setText(
                m_report.ok ? tr("Restored.")
                            : tr("Restore failed and was rolled back: %1").arg(m_report.error));
            m_restore->setEnabled(true);
            emit restored(m_report.ok);
        });
}

void RestoreDialog::cancelRestore()
{
    m_cancel->store(true);
}

void RestoreDialog::addProgress(const Deploy::DeployStep &step)
{
    auto *item = new QListWidgetItem(step.toString(), m_progress);
    if (step.status == Deploy::StepStatus::Failed)
        item->setForeground(QColor(200, 0, 0));
    m_progress->scrollToItem(item);
}

} // namespace SystemEditor
