// SPDX-License-Identifier: MIT
#include "driftview.h"

#include "onlinesession.h"

#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QMap>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

struct DriftResult
{
    QList<Deploy::DriftItem> items;
};

} // namespace

} // namespace SystemEditor

Q_DECLARE_METATYPE(SystemEditor::DriftResult)

namespace SystemEditor {

DriftView::DriftView(OnlineSession *session, Profile::RtsProfile profile,
                     Deploy::TargetOptions options, const QString &fileName, QWidget *parent)
    : QDialog(parent)
    , m_session(session)
    , m_profile(std::move(profile))
    , m_options(std::move(options))
    , m_fileName(fileName)
{
    setWindowTitle(tr("Compare %1 with the Live System").arg(fileName));
    buildUi();
}

void DriftView::buildUi()
{
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("driftTree"));
    m_tree->setHeaderLabels({tr("Difference"), tr("In the file"), tr("Live")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->setRootIsDecorated(true);
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("driftSummary"));
    m_summary->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_refresh = buttons->addButton(tr("Refresh"), QDialogButtonBox::ActionRole);
    m_refresh->setObjectName(QStringLiteral("refreshButton"));
    connect(m_refresh, &QPushButton::clicked, this, &DriftView::refresh);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_tree, 1);
    layout->addWidget(m_summary);
    layout->addWidget(buttons);
    resize(760, 480);
}

void DriftView::refresh()
{
    if (m_running)
        return;
    m_running = true;
    m_refresh->setEnabled(false);
    m_summary->setText(tr("Comparing with the live system…"));
    const Profile::RtsProfile profile = m_profile;
    const Deploy::TargetOptions options = m_options;
    m_session->submit(
        OnlineSession::deploymentHost(),
        [profile, options] {
            DriftResult result;
            result.items = Deploy::diffSystem(profile, Deploy::planRestore(profile, options));
            return QVariant::fromValue(result);
        },
        this,
        [this](const OnlineResult &result) {
            m_running = false;
            m_refresh->setEnabled(true);
            m_items
                = result.ok ? result.value.value<DriftResult>().items : QList<Deploy::DriftItem>();
            showItems();
            if (!result.ok)
                m_summary->setText(result.error);
            emit refreshed();
        });
}

void DriftView::showItems()
{
    m_tree->clear();
    // One branch per kind, in the order the engine defines the kinds.
    QMap<int, QTreeWidgetItem *> groups;
    for (const Deploy::DriftItem &item : std::as_const(m_items)) {
        QTreeWidgetItem *&group = groups[int(item.kind)];
        if (!group) {
            group = new QTreeWidgetItem({Deploy::DriftItem::kindName(item.kind)});
            QFont bold = group->font(0);
            bold.setBold(true);
            group->setFont(0, bold);
        }
        auto *row = new QTreeWidgetItem(group, {item.subject, item.saved, item.live});
        row->setToolTip(0, item.toString());
    }
    for (QTreeWidgetItem *group : std::as_const(groups)) {
        group->setText(0, QStringLiteral("%1 (%2)").arg(group->text(0)).arg(group->childCount()));
        m_tree->addTopLevelItem(group);
        group->setExpanded(true);
    }
    m_summary->setText(summary());
}

QString DriftView::summary() const
{
    if (m_items.isEmpty())
        return tr("The live system matches %1.").arg(m_fileName);
    return tr("%n difference(s) between %1 and the live system.", nullptr, int(m_items.size()))
        .arg(m_fileName);
}

} // namespace SystemEditor
