// SPDX-License-Identifier: MIT
#include "configurationview.h"

#include "componentproxy.h"
#include "iorendpoint.h"
#include "onlinesession.h"
#include "parametereditor.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QVBoxLayout>

namespace SystemEditor {

namespace {

const QString WidgetSet = QStringLiteral("__widget__");
const QString ConstraintSet = QStringLiteral("__constraints__");

bool isHiddenSet(const QString &id)
{
    return id.startsWith(QLatin1String("__"));
}

QPushButton *button(const QString &text, const QString &name, QWidget *parent)
{
    auto *b = new QPushButton(text, parent);
    b->setObjectName(name);
    return b;
}

} // namespace

ConfigurationView::ConfigurationView(OnlineSession *session, QWidget *parent)
    : QWidget(parent)
    , m_session(session)
{
    qRegisterMetaType<ConfigurationSnapshot>();
    buildUi();
    updateButtons();
}

void ConfigurationView::buildUi()
{
    m_title = new QLabel(tr("No component selected"), this);
    m_title->setObjectName(QStringLiteral("componentLabel"));
    m_sets = new QListWidget(this);
    m_sets->setObjectName(QStringLiteral("setList"));
    m_detail = new QCheckBox(tr("Detail (hidden sets)"), this);
    m_detail->setObjectName(QStringLiteral("detailCheck"));
    auto *add = button(tr("Add"), QStringLiteral("addSetButton"), this);
    auto *copy = button(tr("Copy"), QStringLiteral("copySetButton"), this);
    m_delete = button(tr("Delete"), QStringLiteral("deleteSetButton"), this);
    m_activate = button(tr("Activate"), QStringLiteral("activateSetButton"), this);
    m_apply = button(tr("Apply"), QStringLiteral("applyButton"), this);
    auto *reloadButton = button(tr("Reload"), QStringLiteral("reloadButton"), this);

    auto *left = new QWidget(this);
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(m_sets, 1);
    leftLayout->addWidget(m_detail);
    auto *setButtons = new QHBoxLayout;
    for (QPushButton *b : {add, copy, m_delete, m_activate})
        setButtons->addWidget(b);
    leftLayout->addLayout(setButtons);

    m_parameterArea = new QWidget;
    m_form = new QFormLayout(m_parameterArea);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setWidget(m_parameterArea);
    auto *right = new QWidget(this);
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->addWidget(scroll, 1);
    auto *applyRow = new QHBoxLayout;
    applyRow->addStretch(1);
    applyRow->addWidget(reloadButton);
    applyRow->addWidget(m_apply);
    rightLayout->addLayout(applyRow);

    auto *splitter = new QSplitter(this);
    splitter->addWidget(left);
    splitter->addWidget(right);
    splitter->setStretchFactor(1, 2);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("statusLabel"));
    m_status->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(m_title);
    layout->addWidget(splitter, 1);
    layout->addWidget(m_status);

    connect(m_sets, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row >= 0)
            selectSet(m_sets->item(row)->data(Qt::UserRole).toString());
    });
    connect(m_detail, &QCheckBox::toggled, this, &ConfigurationView::setDetailMode);
    connect(add, &QPushButton::clicked, this, [this] { askNewSet(false); });
    connect(copy, &QPushButton::clicked, this, [this] { askNewSet(true); });
    connect(m_delete, &QPushButton::clicked, this, [this] { deleteSet(m_current); });
    connect(m_activate, &QPushButton::clicked, this, [this] { activateSet(m_current); });
    connect(m_apply, &QPushButton::clicked, this, &ConfigurationView::apply);
    connect(reloadButton, &QPushButton::clicked, this, &ConfigurationView::reload);
}

void ConfigurationView::setComponent(const QString &path, const QString &ior)
{
    m_path = path;
    m_ior = ior;
    m_current.clear();
    m_title->setText(path);
    reload();
}

void ConfigurationView::reload()
{
    if (m_ior.isEmpty())
        return;
    const QString path = m_path;
    const QString ior = m_ior;
    const QString host = Corba::iorEndpoint(ior).isEmpty() ? path : Corba::iorEndpoint(ior);
    m_session->submit(
        host,
        [path, ior] {
            const Corba::ComponentProxy proxy(ior, path);
            ConfigurationSnapshot snapshot;
            snapshot.sets = proxy.configurationSets();
            snapshot.active = proxy.activeConfigurationSet();
            return QVariant::fromValue(snapshot);
        },
        this,
        [this, path](const OnlineResult &result) {
            if (path != m_path)
                return; // another component was chosen meanwhile
            if (!result.ok) {
                m_status->setText(result.error);
                return;
            }
            showSnapshot(result.value.value<ConfigurationSnapshot>());
            emit loaded();
        });
}

void ConfigurationView::showSnapshot(const ConfigurationSnapshot &snapshot)
{
    m_snapshot = snapshot;
    if (m_current.isEmpty() || !set(m_current))
        m_current = snapshot.active;
    fillSetList();
    fillParameters();
}

const Corba::ConfigurationSet *ConfigurationView::set(const QString &id) const
{
    for (const Corba::ConfigurationSet &s : m_snapshot.sets) {
        if (s.id == id)
            return &s;
    }
    return nullptr;
}

void ConfigurationView::fillSetList()
{
    const QSignalBlocker blocker(m_sets);
    m_sets->clear();
    for (const Corba::ConfigurationSet &s : m_snapshot.sets) {
        if (isHiddenSet(s.id) && !m_detail->isChecked())
            continue;
        const bool active = s.id == m_snapshot.active;
        auto *item = new QListWidgetItem(active ? tr("%1 (active)").arg(s.id) : s.id, m_sets);
        item->setData(Qt::UserRole, s.id);
        QFont font = item->font();
        font.setBold(active);
        item->setFont(font);
        if (s.id == m_current)
            m_sets->setCurrentItem(item);
    }
}

void ConfigurationView::fillParameters()
{
    while (m_form->rowCount() > 0)
        m_form->removeRow(0);
    m_editors.clear();
    const Corba::ConfigurationSet *current = set(m_current);
    const Corba::ConfigurationSet *widgets = set(WidgetSet);
    const Corba::ConfigurationSet *constraints = set(ConstraintSet);
    if (current) {
        for (const auto &[name, value] : current->data) {
            // Hidden sets are metadata: their values are edited as plain text.
            const ParameterRule rule = isHiddenSet(m_current)
                ? ParameterRule()
                : ParameterRule::from(
                    widgets ? Corba::propertyValue(widgets->data, name) : QString(),
                    constraints ? Corba::propertyValue(constraints->data, name) : QString());
            auto *editor = new ParameterEditor(name, rule, m_parameterArea);
            editor->setValue(value);
            connect(editor, &ParameterEditor::valueChanged, this,
                    &ConfigurationView::updateButtons);
            m_form->addRow(name, editor);
            m_editors.push_back(editor);
        }
    }
    updateButtons();
}

void ConfigurationView::setDetailMode(bool on)
{
    if (m_detail->isChecked() != on)
        m_detail->setChecked(on); // comes back here through toggled()
    if (!on && isHiddenSet(m_current))
        m_current = m_snapshot.active;
    fillSetList();
    fillParameters();
}

bool ConfigurationView::detailMode() const
{
    return m_detail->isChecked();
}

QStringList ConfigurationView::shownSets() const
{
    QStringList ids;
    for (int i = 0; i < m_sets->count(); ++i)
        ids.append(m_sets->item(i)->data(Qt::UserRole).toString());
    return ids;
}

void ConfigurationView::selectSet(const QString &id)
{
    if (id == m_current || !set(id))
        return;
    m_current = id;
    fillSetList();
    fillParameters();
}

ParameterEditor *ConfigurationView::editor(const QString &name) const
{
    for (ParameterEditor *e : m_editors) {
        if (e->name() == name)
            return e;
    }
    return nullptr;
}

bool ConfigurationView::canApply() const
{
    const Corba::ConfigurationSet *current = set(m_current);
    if (!current)
        return false;
    // Only edited values must satisfy their constraints: a live value that already breaks one is
    // shown with its reason but does not block applying other edits.
    bool changed = false;
    for (const ParameterEditor *e : m_editors) {
        if (e->value() == Corba::propertyValue(current->data, e->name()))
            continue;
        if (!e->error().isEmpty())
            return false;
        changed = true;
    }
    return changed;
}

void ConfigurationView::updateButtons()
{
    m_apply->setEnabled(canApply());
    const bool has = set(m_current) != nullptr;
    m_activate->setEnabled(has && m_current != m_snapshot.active && !isHiddenSet(m_current));
    m_delete->setEnabled(has && m_current != m_snapshot.active);
}

void ConfigurationView::submitEdit(const std::function<void()> &edit)
{
    const QString host = Corba::iorEndpoint(m_ior).isEmpty() ? m_path : Corba::iorEndpoint(m_ior);
    m_session->submit(
        host,
        [edit] {
            edit();
            return QVariant();
        },
        this,
        [this](const OnlineResult &result) {
            m_status->setText(result.ok ? tr("Done") : result.error);
            emit editFinished(result.ok ? QString() : result.error);
            reload();
        });
}

bool ConfigurationView::apply()
{
    if (!canApply())
        return false;
    const Corba::ConfigurationSet *current = set(m_current);
    QList<QPair<QString, QString>> changes;
    for (const ParameterEditor *e : m_editors) {
        if (e->value() != Corba::propertyValue(current->data, e->name()))
            changes.append({e->name(), e->value()});
    }
    const Corba::ComponentProxy proxy(m_ior, m_path);
    const QString setId = m_current;
    submitEdit([proxy, setId, changes] {
        for (const auto &[name, value] : changes)
            proxy.setParameter(setId, name, value);
    });
    return true;
}

void ConfigurationView::addSet(const QString &id, bool copyValues)
{
    const Corba::ConfigurationSet *source = set(copyValues ? m_current : QStringLiteral("default"));
    if (id.isEmpty() || set(id) || !source)
        return;
    Corba::ConfigurationSet added = *source;
    added.id = id;
    const Corba::ComponentProxy proxy(m_ior, m_path);
    m_current = id;
    submitEdit([proxy, added] { proxy.addConfigurationSet(added); });
}

void ConfigurationView::deleteSet(const QString &id)
{
    if (!set(id) || id == m_snapshot.active)
        return;
    const Corba::ComponentProxy proxy(m_ior, m_path);
    m_current = m_snapshot.active;
    submitEdit([proxy, id] { proxy.removeConfigurationSet(id); });
}

void ConfigurationView::activateSet(const QString &id)
{
    if (!set(id))
        return;
    const Corba::ComponentProxy proxy(m_ior, m_path);
    submitEdit([proxy, id] { proxy.activateConfigurationSet(id); });
}

void ConfigurationView::askNewSet(bool copyValues)
{
    bool ok = false;
    const QString id = QInputDialog::getText(this, copyValues ? tr("Copy Set") : tr("Add Set"),
                                             tr("Id of the new configuration set:"),
                                             QLineEdit::Normal, QString(), &ok);
    if (ok)
        addSet(id.trimmed(), copyValues);
}

} // namespace SystemEditor
