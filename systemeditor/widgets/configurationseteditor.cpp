// SPDX-License-Identifier: MIT
#include "configurationseteditor.h"

#include "configurationcommands.h"
#include "constraintsyntax.h"
#include "elementlisteditor.h"
#include "instancecommands.h"
#include "parametereditor.h"
#include "systemmodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

namespace SystemEditor {

using namespace Profile;

namespace {

const QString WidgetSet = QStringLiteral("__widget__");
const QString ConstraintsSet = QStringLiteral("__constraints__");
constexpr int MinimumEditorWidth = 170;

QString valueIn(const RtsComponent &c, const QString &setId, const QString &parameter)
{
    for (const RtsConfigurationSet &set : c.configurationSets) {
        if (set.id != setId)
            continue;
        for (const RtsConfigurationData &data : set.data) {
            if (data.name == parameter)
                return data.data.value_or(QString());
        }
    }
    return {};
}

QPushButton *button(const QString &text, const QString &objectName)
{
    auto *b = new QPushButton(text);
    b->setObjectName(objectName);
    return b;
}

} // namespace

ConfigurationSetEditor::ConfigurationSetEditor(SystemModel *model, QUndoStack *undoStack,
                                               QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_sets(new QComboBox)
    , m_showHidden(new QCheckBox(tr("Show hidden sets")))
    , m_activate(button(tr("Activate"), QStringLiteral("activateSet")))
    , m_delete(button(tr("Delete"), QStringLiteral("deleteSet")))
    , m_valuesArea(new QWidget)
    , m_valuesForm(new QFormLayout)
{
    m_sets->setObjectName(QStringLiteral("configurationSet"));
    m_showHidden->setObjectName(QStringLiteral("showHiddenSets"));
    QPushButton *add = button(tr("Add"), QStringLiteral("addSet"));
    QPushButton *copy = button(tr("Copy"), QStringLiteral("copySet"));
    connect(m_sets, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_filling)
            fillValues();
    });
    connect(m_showHidden, &QCheckBox::toggled, this, &ConfigurationSetEditor::refresh);
    connect(m_activate, &QPushButton::clicked, this, &ConfigurationSetEditor::activateShownSet);
    connect(add, &QPushButton::clicked, this, &ConfigurationSetEditor::addSet);
    connect(copy, &QPushButton::clicked, this, &ConfigurationSetEditor::addSetCopy);
    connect(m_delete, &QPushButton::clicked, this, &ConfigurationSetEditor::deleteShownSet);
    // Two rows keep the panel usable in a narrow dock (one row needed ~480 px).
    auto *setRow = new QHBoxLayout;
    setRow->addWidget(m_sets, 1);
    setRow->addWidget(m_showHidden);
    auto *buttonRow = new QHBoxLayout;
    for (QPushButton *b : {m_activate, add, copy, m_delete})
        buttonRow->addWidget(b);
    buttonRow->addStretch(1);
    m_valuesForm->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_valuesForm->setLabelAlignment(Qt::AlignLeft | Qt::AlignTop);
    // A long name (with its unit) puts its widget on the next line rather than squeezing it.
    m_valuesForm->setRowWrapPolicy(QFormLayout::WrapLongRows);
    // Spare height goes below the rows, not into tall widgets (an ordered list floated in it).
    auto *valuesLayout = new QVBoxLayout(m_valuesArea);
    valuesLayout->addLayout(m_valuesForm);
    valuesLayout->addStretch(1);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setWidget(m_valuesArea);
    scroll->setFrameShape(QFrame::StyledPanel);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(setRow);
    layout->addLayout(buttonRow);
    layout->addWidget(scroll, 1);
    connect(model, &SystemModel::componentChanged, this, [this](const QString &name) {
        if (name == m_component)
            refresh();
    });
}

const RtsComponent *ConfigurationSetEditor::current() const
{
    return m_model ? m_model->component(m_component) : nullptr;
}

bool ConfigurationSetEditor::isHidden(const QString &setId)
{
    return setId.startsWith(QLatin1String("__")) && setId.endsWith(QLatin1String("__"));
}

void ConfigurationSetEditor::setComponent(const QString &instanceName)
{
    if (instanceName != m_component) {
        m_component = instanceName;
        m_sets->clear();
        m_editorsSet.clear();
    }
    refresh();
}

void ConfigurationSetEditor::setShowHidden(bool show)
{
    m_showHidden->setChecked(show);
}

void ConfigurationSetEditor::refresh()
{
    fillSets();
    fillValues();
}

void ConfigurationSetEditor::fillSets()
{
    const RtsComponent *c = current();
    m_filling = true;
    const QString shown = !shownSet().isEmpty()
        ? shownSet()
        : (c ? c->activeConfigurationSet.value_or(QString()) : QString());
    m_sets->clear();
    if (c) {
        for (const RtsConfigurationSet &set : c->configurationSets) {
            if (isHidden(set.id) && !m_showHidden->isChecked())
                continue;
            const bool active = set.id == c->activeConfigurationSet;
            m_sets->addItem(active ? tr("%1 (active)").arg(set.id) : set.id, set.id);
        }
    }
    m_sets->setCurrentIndex(std::max(0, m_sets->findData(shown)));
    m_filling = false;
}

QString ConfigurationSetEditor::shownSet() const
{
    return m_sets->currentData().toString();
}

void ConfigurationSetEditor::setShownSet(const QString &setId)
{
    m_sets->setCurrentIndex(m_sets->findData(setId));
}

ParameterRule ConfigurationSetEditor::ruleFor(const QString &parameter) const
{
    const RtsComponent *c = current();
    if (!c || isHidden(shownSet()))
        return {}; // hidden sets are metadata, edited as text
    if (const RtcConfiguration *configuration = profileConfiguration(parameter))
        return ParameterRule::from(configuration->widget().value_or(QString()),
                                   constraintToString(configuration->constraint));
    // Without a profile, a system saved online may still carry the hidden sets.
    return ParameterRule::from(valueIn(*c, WidgetSet, parameter),
                               valueIn(*c, ConstraintsSet, parameter));
}

QLabel *ConfigurationSetEditor::parameterLabel(const QString &parameter) const
{
    // The unit belongs next to the name (the widgets show bare numbers); the description and the
    // type go to the tooltip.
    const RtcConfiguration *configuration = profileConfiguration(parameter);
    QString unit;
    QStringList tip;
    if (configuration) {
        const std::optional<RtcConfigurationDoc> &doc = configuration->doc;
        unit = configuration->unit.value_or(doc ? doc->unit.value_or(QString()) : QString());
        tip << tr("Type: %1").arg(configuration->type);
        if (doc && doc->description && !doc->description->isEmpty())
            tip << *doc->description;
    }
    auto *label = new QLabel(unit.isEmpty() ? tr("%1:").arg(parameter)
                                            : tr("%1 (%2):").arg(parameter, unit));
    label->setObjectName(QStringLiteral("label_") + parameter);
    label->setToolTip(tip.join(QLatin1Char('\n')));
    return label;
}

const RtcConfiguration *ConfigurationSetEditor::profileConfiguration(const QString &parameter) const
{
    const RtcProfile *rtc = m_model ? m_model->rtcProfile(m_component) : nullptr;
    if (!rtc)
        return nullptr;
    for (const RtcConfiguration &configuration : rtc->configurations) {
        if (configuration.name == parameter)
            return &configuration;
    }
    return nullptr;
}

std::optional<ElementRules> ConfigurationSetEditor::elementRulesFor(const QString &parameter) const
{
    const RtcConfiguration *configuration = profileConfiguration(parameter);
    if (isHidden(shownSet()) || !configuration || !ElementRules::appliesTo(*configuration))
        return std::nullopt;
    return ElementRules::of(*configuration);
}

ElementListEditor *ConfigurationSetEditor::elementEditor(const QString &parameter) const
{
    for (ElementListEditor *editor : m_lists) {
        if (editor->name() == parameter)
            return editor;
    }
    return nullptr;
}

ParameterEditor *ConfigurationSetEditor::parameterEditor(const QString &parameter) const
{
    for (ParameterEditor *editor : m_editors) {
        if (editor->name() == parameter)
            return editor;
    }
    return nullptr;
}

void ConfigurationSetEditor::fillValues()
{
    const RtsComponent *c = current();
    const QString setId = shownSet();
    const RtsConfigurationSet *set = nullptr;
    if (c) {
        for (const RtsConfigurationSet &s : c->configurationSets) {
            if (s.id == setId)
                set = &s;
        }
    }
    m_activate->setEnabled(c && set && c->activeConfigurationSet != setId);
    m_delete->setEnabled(set != nullptr);
    QStringList names;
    if (set) {
        for (const RtsConfigurationData &data : set->data)
            names << data.name;
    }
    // The same parameters of the same set: only values change, so that an editor the user is
    // typing in is kept.
    if (set && setId == m_editorsSet && names == m_shownNames) {
        updateValues(*set);
        return;
    }
    while (m_valuesForm->rowCount() > 0)
        m_valuesForm->removeRow(0);
    m_editors.clear();
    m_lists.clear();
    m_shownNames = names;
    m_editorsSet = setId;
    if (!set)
        return;
    for (const RtsConfigurationData &data : set->data) {
        if (const std::optional<ElementRules> rules = elementRulesFor(data.name)) {
            addElementList(data.name, *rules, data.data.value_or(QString()));
            continue;
        }
        auto *editor = new ParameterEditor(data.name, ruleFor(data.name));
        // Wide enough for a usable slider; a long label then wraps its widget below it.
        editor->setMinimumWidth(MinimumEditorWidth);
        m_filling = true;
        editor->setValue(data.data.value_or(QString()));
        m_filling = false;
        connect(editor, &ParameterEditor::valueChanged, this, [this, editor] { onEdited(editor); });
        m_editors << editor;
        m_valuesForm->addRow(parameterLabel(data.name), editor);
    }
}

void ConfigurationSetEditor::addElementList(const QString &parameter, const ElementRules &rules,
                                            const QString &value)
{
    auto *editor = new ElementListEditor(parameter, rules);
    editor->setMinimumWidth(MinimumEditorWidth);
    editor->setValue(value);
    connect(editor, &ElementListEditor::valueChanged, this,
            [this, editor](const QString &text, bool structural) {
                if (!m_filling)
                    setValue(editor->name(), text, structural);
            });
    m_lists << editor;
    m_valuesForm->addRow(parameterLabel(parameter), editor);
}

void ConfigurationSetEditor::updateValues(const RtsConfigurationSet &set)
{
    m_filling = true;
    for (const RtsConfigurationData &data : set.data) {
        const QString value = data.data.value_or(QString());
        ParameterEditor *editor = parameterEditor(data.name);
        if (editor && editor->value() != value)
            editor->setValue(value);
        if (ElementListEditor *list = elementEditor(data.name); list && list->value() != value)
            list->setValue(value);
    }
    m_filling = false;
}

void ConfigurationSetEditor::onEdited(ParameterEditor *editor)
{
    if (m_filling)
        return;
    setValue(editor->name(), editor->value());
}

bool ConfigurationSetEditor::setValue(const QString &parameter, const QString &value,
                                      bool structural)
{
    const RtsComponent *c = current();
    const std::optional<ElementRules> elements = elementRulesFor(parameter);
    const QString problem = elements ? elements->check(value) : ruleFor(parameter).check(value);
    if (!c || !problem.isEmpty())
        return false;
    if (valueIn(*c, shownSet(), parameter) == value)
        return true;
    auto *command
        = new SetConfigurationValueCommand(m_model, m_component, shownSet(), parameter, value);
    // Adding or removing an element is a step of its own, not merged with typing.
    command->setMergeable(!structural);
    if (m_undoStack) {
        m_undoStack->push(command);
    } else {
        command->redo();
        delete command;
    }
    return true;
}

void ConfigurationSetEditor::activateShownSet()
{
    if (const RtsComponent *c = current())
        pushSets(c->configurationSets, shownSet());
}

void ConfigurationSetEditor::addSet()
{
    const RtsComponent *c = current();
    if (!c)
        return;
    QList<RtsConfigurationSet> sets = c->configurationSets;
    RtsConfigurationSet set;
    set.id = uniqueSetId(sets, QStringLiteral("new_set"));
    // A new set starts from the profile's defaults; without a profile, from the shown set's names.
    if (const RtcProfile *rtc = m_model->rtcProfile(m_component)) {
        for (const RtcConfiguration &configuration : rtc->configurations) {
            RtsConfigurationData data;
            data.name = configuration.name;
            data.data = configuration.defaultValue;
            set.data << data;
        }
    } else {
        for (ParameterEditor *editor : m_editors) {
            RtsConfigurationData data;
            data.name = editor->name();
            data.data = QString();
            set.data << data;
        }
    }
    sets.append(set);
    pushSets(sets, c->activeConfigurationSet.value_or(QString()).isEmpty()
                 ? std::optional<QString>(set.id)
                 : c->activeConfigurationSet);
    setShownSet(set.id);
}

void ConfigurationSetEditor::addSetCopy()
{
    const RtsComponent *c = current();
    if (!c)
        return;
    QList<RtsConfigurationSet> sets = c->configurationSets;
    RtsConfigurationSet copy;
    for (const RtsConfigurationSet &set : sets) {
        if (set.id == shownSet())
            copy = set;
    }
    copy.id = uniqueSetId(sets, copy.id.isEmpty() ? QStringLiteral("set")
                                                  : copy.id + QStringLiteral("_copy"));
    sets.append(copy);
    pushSets(sets, c->activeConfigurationSet);
    setShownSet(copy.id);
}

void ConfigurationSetEditor::deleteShownSet()
{
    const RtsComponent *c = current();
    if (!c)
        return;
    QList<RtsConfigurationSet> sets = c->configurationSets;
    const QString removed = shownSet();
    sets.removeIf([&](const RtsConfigurationSet &s) { return s.id == removed; });
    // The active set moves to the first one left when it was the deleted one.
    std::optional<QString> active = c->activeConfigurationSet;
    if (active == removed)
        active = sets.isEmpty() ? std::nullopt : std::optional(sets.first().id);
    m_sets->setCurrentIndex(-1);
    pushSets(sets, active);
}

void ConfigurationSetEditor::pushSets(const QList<RtsConfigurationSet> &sets,
                                      const std::optional<QString> &active)
{
    const RtsComponent *c = current();
    if (!c || (c->configurationSets == sets && c->activeConfigurationSet == active))
        return;
    auto *command = new SetConfigurationSetsCommand(m_model, m_component, sets, active);
    if (m_undoStack) {
        m_undoStack->push(command);
    } else {
        command->redo();
        delete command;
    }
}

} // namespace SystemEditor
