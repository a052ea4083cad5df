// SPDX-License-Identifier: MIT
#include "executioncontextview.h"

#include "componentproxy.h"
#include "executioncontextmodel.h"
#include "iorendpoint.h"
#include "onlinesession.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

Q_DECLARE_METATYPE(std::vector<Corba::ExecutionContextInfo>)

namespace SystemEditor {

ExecutionContextView::ExecutionContextView(OnlineSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
    , m_model(new ExecutionContextModel(this))
{
    buildUi();
}

void ExecutionContextView::buildUi()
{
    m_title = new QLabel(tr("No component selected"), this);
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("contextTable"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_rate = new QDoubleSpinBox(this);
    m_rate->setObjectName(QStringLiteral("rateSpin"));
    m_rate->setRange(0.001, 1e6);
    m_rate->setDecimals(3);
    m_rate->setSuffix(tr(" Hz"));
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("statusLabel"));

    auto *buttons = new QHBoxLayout;
    const std::pair<const char *, Action> actions[]
        = {{QT_TR_NOOP("Start"), Action::Start},
           {QT_TR_NOOP("Stop"), Action::Stop},
           {QT_TR_NOOP("Activate"), Action::Activate},
           {QT_TR_NOOP("Deactivate"), Action::Deactivate},
           {QT_TR_NOOP("Reset"), Action::Reset}};
    for (const auto &[text, action] : actions) {
        auto *button = new QPushButton(tr(text), this);
        button->setObjectName(QStringLiteral("%1Button").arg(QString::fromLatin1(text).toLower()));
        const Action what = action;
        connect(button, &QPushButton::clicked, this,
                [this, what] { perform(what, currentContext()); });
        buttons->addWidget(button);
    }
    buttons->addStretch(1);
    buttons->addWidget(m_rate);
    auto *rateButton = new QPushButton(tr("Set Rate"), this);
    rateButton->setObjectName(QStringLiteral("setRateButton"));
    connect(rateButton, &QPushButton::clicked, this,
            [this] { setRate(m_rate->value(), currentContext()); });
    buttons->addWidget(rateButton);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_title);
    layout->addWidget(m_table, 1);
    layout->addLayout(buttons);
    layout->addWidget(m_status);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                if (current.isValid())
                    m_rate->setValue(m_model->contexts()[size_t(current.row())].rate);
            });
}

void ExecutionContextView::setComponent(const QString &path, const QString &ior)
{
    m_path = path;
    m_ior = ior;
    m_title->setText(path);
    m_model->setContexts({});
    reload();
}

void ExecutionContextView::reload()
{
    if (m_ior.isEmpty())
        return;
    const Corba::ComponentProxy proxy(m_ior, m_path);
    const QString path = m_path;
    const QString host = iorEndpoint(m_ior).isEmpty() ? m_path : iorEndpoint(m_ior);
    m_session->submit(
        host, [proxy] { return QVariant::fromValue(proxy.executionContexts()); }, this,
        [this, path](const OnlineResult &result) {
            if (path != m_path)
                return;
            if (!result.ok) {
                m_status->setText(result.error);
                return;
            }
            m_model->setContexts(result.value.value<std::vector<Corba::ExecutionContextInfo>>());
            if (!m_table->currentIndex().isValid() && m_model->rowCount() > 0)
                m_table->selectRow(0);
            emit loaded();
        });
}

int ExecutionContextView::currentContext() const
{
    const QModelIndex current = m_table->currentIndex();
    return current.isValid() ? current.row() : 0;
}

void ExecutionContextView::submit(const std::function<void()> &call)
{
    const QString host = iorEndpoint(m_ior).isEmpty() ? m_path : iorEndpoint(m_ior);
    m_session->submit(
        host,
        [call] {
            call();
            return QVariant();
        },
        this,
        [this](const OnlineResult &result) {
            m_status->setText(result.ok ? tr("Done") : result.error);
            emit actionFinished(result.ok ? QString() : result.error);
            reload();
        });
}

void ExecutionContextView::perform(Action action, int ecIndex)
{
    if (m_ior.isEmpty())
        return;
    const Corba::ComponentProxy proxy(m_ior, m_path);
    submit([proxy, action, ecIndex] {
        switch (action) {
        case Action::Start:
            return proxy.startContext(ecIndex);
        case Action::Stop:
            return proxy.stopContext(ecIndex);
        case Action::Activate:
            return proxy.activate(ecIndex);
        case Action::Deactivate:
            return proxy.deactivate(ecIndex);
        case Action::Reset:
            return proxy.reset(ecIndex);
        }
    });
}

void ExecutionContextView::setRate(double rate, int ecIndex)
{
    if (m_ior.isEmpty())
        return;
    const Corba::ComponentProxy proxy(m_ior, m_path);
    submit([proxy, rate, ecIndex] { proxy.setRate(rate, ecIndex); });
}

} // namespace SystemEditor
