// SPDX-License-Identifier: MIT
#include "executioncontextview.h"

#include "componentproxy.h"
#include "executioncontextmodel.h"
#include "iorendpoint.h"
#include "nameservicemodel.h"
#include "onlinecalls.h"
#include "onlinesession.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSet>
#include <QTableView>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

// Components listed under a manager carry no reference; the same instance is also bound in the
// naming tree, where it is picked up once.
void collectComponents(const QAbstractItemModel *model, const QModelIndex &parent,
                       QList<Corba::ContextMember> &components, QSet<QString> &seen)
{
    for (int row = 0; row < model->rowCount(parent); ++row) {
        const QModelIndex index = model->index(row, 0, parent);
        const QString ior = index.data(NameServiceModel::IorRole).toString();
        if (index.data(NameServiceModel::TypeRole).toInt() == int(Corba::NodeType::Component)
            && !ior.isEmpty() && !seen.contains(ior)) {
            seen.insert(ior);
            components.append({index.data(NameServiceModel::PathRole).toString(), ior});
        }
        collectComponents(model, index, components, seen);
    }
}

// Calls about a component queue on the worker of the process serving it, so a hung process
// delays only its own calls.
QString hostOf(const QString &ior, const QString &path)
{
    const QString endpoint = Corba::iorEndpoint(ior);
    return endpoint.isEmpty() ? path : endpoint;
}

} // namespace

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
    m_table->setContextMenuPolicy(Qt::CustomContextMenu);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("statusLabel"));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_title);
    layout->addWidget(m_table, 1);
    layout->addLayout(buildButtons());
    layout->addWidget(m_status);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                if (current.isValid())
                    m_rate->setValue(m_model->contexts()[size_t(current.row())].rate);
            });
    connect(m_table, &QWidget::customContextMenuRequested, this, [this](const QPoint &pos) {
        const QModelIndex index = m_table->indexAt(pos);
        if (!index.isValid())
            return;
        QMenu *menu = createContextMenu(index.row());
        menu->setAttribute(Qt::WA_DeleteOnClose);
        menu->popup(m_table->viewport()->mapToGlobal(pos));
    });
}

QLayout *ExecutionContextView::buildButtons()
{
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
    for (const bool attaching : {true, false}) {
        auto *button = new QPushButton(attaching ? tr("Attach...") : tr("Detach..."), this);
        button->setObjectName(attaching ? QStringLiteral("attachButton")
                                        : QStringLiteral("detachButton"));
        button->setToolTip(attaching ? tr("Make another live component take part in this context")
                                     : tr("Take a participant out of this context"));
        connect(button, &QPushButton::clicked, this,
                [this, button, attaching] { popupMemberMenu(button, attaching); });
        buttons->addWidget(button);
    }
    buttons->addStretch(1);
    m_rate = new QDoubleSpinBox(this);
    m_rate->setObjectName(QStringLiteral("rateSpin"));
    m_rate->setRange(0.001, 1e6);
    m_rate->setDecimals(3);
    m_rate->setSuffix(tr(" Hz"));
    buttons->addWidget(m_rate);
    auto *rateButton = new QPushButton(tr("Set Rate"), this);
    rateButton->setObjectName(QStringLiteral("setRateButton"));
    connect(rateButton, &QPushButton::clicked, this,
            [this] { setRate(m_rate->value(), currentContext()); });
    buttons->addWidget(rateButton);
    return buttons;
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
    const QString path = m_path;
    const QString ior = m_ior;
    m_session->submit(
        hostOf(m_ior, m_path),
        [path, ior] { return QVariant::fromValue(OnlineCalls::fetchContexts(path, ior)); }, this,
        [this, path](const OnlineResult &result) {
            if (path != m_path)
                return;
            if (!result.ok) {
                m_status->setText(result.error);
                return;
            }
            m_model->setContexts(result.value.value<ExecutionContexts>());
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

void ExecutionContextView::fail(const QString &error)
{
    m_status->setText(error);
    emit actionFinished(error);
}

void ExecutionContextView::submit(const QString &ior, const QString &path,
                                  const std::function<void()> &call)
{
    m_session->submit(
        hostOf(ior, path),
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
    submit(m_ior, m_path, [proxy, action, ecIndex] {
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
    submit(m_ior, m_path, [proxy, rate, ecIndex] { proxy.setRate(rate, ecIndex); });
}

QList<Corba::ContextMember> ExecutionContextView::liveComponents() const
{
    QList<Corba::ContextMember> components;
    QSet<QString> seen;
    if (m_components)
        collectComponents(m_components, QModelIndex(), components, seen);
    return components;
}

QString ExecutionContextView::pathOf(const Corba::ContextMember &member) const
{
    if (member.ior == m_ior)
        return m_path;
    for (const Corba::ContextMember &live : liveComponents()) {
        if (live.ior == member.ior)
            return live.name;
    }
    return ExecutionContextModel::memberName(member);
}

QList<Corba::ContextMember> ExecutionContextView::attachCandidates(int ecIndex) const
{
    const auto &contexts = m_model->contexts();
    if (ecIndex < 0 || size_t(ecIndex) >= contexts.size())
        return {};
    const Corba::ExecutionContextInfo &ec = contexts[size_t(ecIndex)];
    QSet<QString> members {m_ior, ec.owner.ior};
    for (const Corba::ContextMember &participant : ec.participants)
        members.insert(participant.ior);
    QList<Corba::ContextMember> candidates;
    for (const Corba::ContextMember &live : liveComponents()) {
        if (!members.contains(live.ior))
            candidates.append(live);
    }
    return candidates;
}

QList<Corba::ContextMember> ExecutionContextView::detachCandidates(int ecIndex) const
{
    const auto &contexts = m_model->contexts();
    if (ecIndex < 0 || size_t(ecIndex) >= contexts.size())
        return {};
    const Corba::ExecutionContextInfo &ec = contexts[size_t(ecIndex)];
    QList<Corba::ContextMember> candidates;
    bool selfListed = false;
    for (const Corba::ContextMember &participant : ec.participants) {
        selfListed = selfListed || participant.ior == m_ior;
        candidates.append({pathOf(participant), participant.ior});
    }
    // A context without a profile lists nobody, but the component itself can still leave it.
    if (!ec.owned && !selfListed)
        candidates.prepend({m_path, m_ior});
    return candidates;
}

void ExecutionContextView::attach(int ecIndex, const Corba::ContextMember &target)
{
    const auto &contexts = m_model->contexts();
    if (ecIndex < 0 || size_t(ecIndex) >= contexts.size())
        return fail(tr("%1: no execution context with index %2").arg(m_path).arg(ecIndex));
    const QString contextIor = contexts[size_t(ecIndex)].ior;
    submit(target.ior, target.name, [target, contextIor] {
        OnlineCalls::attachContext(target.name, target.ior, contextIor);
    });
}

void ExecutionContextView::detach(int ecIndex, const Corba::ContextMember &target)
{
    const auto &contexts = m_model->contexts();
    if (ecIndex < 0 || size_t(ecIndex) >= contexts.size())
        return fail(tr("%1: no execution context with index %2").arg(m_path).arg(ecIndex));
    const QString contextIor = contexts[size_t(ecIndex)].ior;
    submit(target.ior, target.name, [target, contextIor] {
        OnlineCalls::detachContext(target.name, target.ior, contextIor);
    });
}

void ExecutionContextView::fillMemberMenu(QMenu *menu, const QList<Corba::ContextMember> &members,
                                          int ecIndex, bool attaching)
{
    menu->setObjectName(attaching ? QStringLiteral("attachMenu") : QStringLiteral("detachMenu"));
    if (members.isEmpty()) {
        menu->addAction(attaching ? tr("No other live component") : tr("No participant"))
            ->setEnabled(false);
        return;
    }
    for (const Corba::ContextMember &member : members) {
        menu->addAction(member.name, this, [this, ecIndex, member, attaching] {
            attaching ? attach(ecIndex, member) : detach(ecIndex, member);
        });
    }
}

QMenu *ExecutionContextView::createContextMenu(int ecIndex)
{
    auto *menu = new QMenu(this);
    const std::pair<QString, Action> actions[] = {{tr("Start"), Action::Start},
                                                  {tr("Stop"), Action::Stop},
                                                  {tr("Activate"), Action::Activate},
                                                  {tr("Deactivate"), Action::Deactivate},
                                                  {tr("Reset"), Action::Reset}};
    for (const auto &[text, action] : actions) {
        const Action what = action;
        menu->addAction(text, this, [this, what, ecIndex] { perform(what, ecIndex); });
    }
    menu->addSeparator();
    fillMemberMenu(menu->addMenu(tr("Attach")), attachCandidates(ecIndex), ecIndex, true);
    fillMemberMenu(menu->addMenu(tr("Detach")), detachCandidates(ecIndex), ecIndex, false);
    return menu;
}

void ExecutionContextView::popupMemberMenu(QWidget *button, bool attaching)
{
    const int ecIndex = currentContext();
    auto *menu = new QMenu(this);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    fillMemberMenu(menu, attaching ? attachCandidates(ecIndex) : detachCandidates(ecIndex), ecIndex,
                   attaching);
    menu->popup(button->mapToGlobal(QPoint(0, button->height())));
}

} // namespace SystemEditor
