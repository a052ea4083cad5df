// SPDX-License-Identifier: MIT
#include "parametereditor.h"

#include <QAbstractButton>
#include <QButtonGroup>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QRadioButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace SystemEditor {

using Widget = ParameterRule::Widget;

ParameterEditor::ParameterEditor(const QString &name, const ParameterRule &rule, QWidget *parent)
    : QWidget(parent)
    , m_name(name)
    , m_rule(rule)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(1);
    switch (rule.widget) {
    case Widget::Text:
        buildText();
        break;
    case Widget::Slider:
        buildSlider();
        break;
    case Widget::Spin:
        buildSpin();
        break;
    case Widget::Radio:
        buildChoices(true);
        break;
    case Widget::CheckBox:
        buildChoices(false);
        break;
    case Widget::OrderedList:
        buildOrderedList();
        break;
    }
    m_input->setObjectName(QStringLiteral("editor_") + name);
    if (!rule.constraintText.isEmpty())
        m_input->setToolTip(tr("Constraint: %1").arg(rule.constraintText));
    m_error = new QLabel(this);
    m_error->setObjectName(QStringLiteral("error_") + name);
    m_error->setStyleSheet(QStringLiteral("color: #c00000;"));
    m_error->setWordWrap(true); // the reason quotes the constraint; a narrow panel must show it all
    m_error->hide();
    layout->addWidget(m_error);
}

void ParameterEditor::buildText()
{
    auto *edit = new QLineEdit(this);
    layout()->addWidget(edit);
    m_input = edit;
    m_get = [edit] { return edit->text(); };
    m_set = [edit](const QString &v) { edit->setText(v); };
    connect(edit, &QLineEdit::textChanged, this, &ParameterEditor::userChanged);
}

void ParameterEditor::buildSlider()
{
    // QSlider counts integers: position n stands for minimum + n * step.
    auto *row = new QWidget(this);
    auto *rowLayout = new QHBoxLayout(row);
    rowLayout->setContentsMargins(0, 0, 0, 0);
    auto *slider = new QSlider(Qt::Horizontal, row);
    const double minimum = *m_rule.minimum;
    const double step = m_rule.step;
    slider->setRange(0, int(std::floor((*m_rule.maximum - minimum) / step + 1e-9)));
    m_sliderValue = new QLabel(row);
    m_sliderValue->setMinimumWidth(60);
    rowLayout->addWidget(slider, 1);
    rowLayout->addWidget(m_sliderValue);
    layout()->addWidget(row);
    m_input = slider;
    const bool integral = m_rule.isIntegral();
    m_get = [slider, minimum, step, integral] {
        const double v = minimum + slider->value() * step;
        return integral ? QString::number(qint64(std::llround(v))) : QString::number(v, 'g', 12);
    };
    m_set = [slider, minimum, step](const QString &v) {
        slider->setValue(int(std::lround((v.toDouble() - minimum) / step)));
    };
    connect(slider, &QSlider::valueChanged, this, &ParameterEditor::userChanged);
}

void ParameterEditor::buildSpin()
{
    if (m_rule.isIntegral()) {
        auto *spin = new QSpinBox(this);
        spin->setRange(int(*m_rule.minimum), int(*m_rule.maximum));
        spin->setSingleStep(int(m_rule.step));
        m_input = spin;
        m_get = [spin] { return QString::number(spin->value()); };
        m_set = [spin](const QString &v) { spin->setValue(v.toInt()); };
        connect(spin, &QSpinBox::valueChanged, this, &ParameterEditor::userChanged);
    } else {
        auto *spin = new QDoubleSpinBox(this);
        spin->setDecimals(6);
        spin->setRange(*m_rule.minimum, *m_rule.maximum);
        spin->setSingleStep(m_rule.step);
        m_input = spin;
        m_get = [spin] { return QString::number(spin->value(), 'g', 12); };
        m_set = [spin](const QString &v) { spin->setValue(v.toDouble()); };
        connect(spin, &QDoubleSpinBox::valueChanged, this, &ParameterEditor::userChanged);
    }
    layout()->addWidget(m_input);
}

void ParameterEditor::buildChoices(bool exclusive)
{
    auto *box = new QWidget(this);
    auto *boxLayout = new QHBoxLayout(box);
    boxLayout->setContentsMargins(0, 0, 0, 0);
    auto *group = new QButtonGroup(box);
    group->setExclusive(exclusive);
    for (const QString &choice : m_rule.choices) {
        QAbstractButton *button = exclusive
            ? static_cast<QAbstractButton *>(new QRadioButton(choice, box))
            : new QCheckBox(choice, box);
        button->setObjectName(QStringLiteral("choice_") + choice);
        group->addButton(button);
        boxLayout->addWidget(button);
    }
    boxLayout->addStretch(1);
    layout()->addWidget(box);
    m_input = box;
    m_get = [group] {
        QStringList checked;
        for (QAbstractButton *button : group->buttons()) {
            if (button->isChecked())
                checked.append(button->text());
        }
        return checked.join(QLatin1Char(','));
    };
    m_set = [group](const QString &v) {
        QStringList values;
        for (const QString &part : v.split(QLatin1Char(','), Qt::SkipEmptyParts))
            values.append(part.trimmed());
        const bool exclusive = group->exclusive();
        group->setExclusive(false); // an exclusive group cannot be cleared otherwise
        for (QAbstractButton *button : group->buttons())
            button->setChecked(values.contains(button->text()));
        group->setExclusive(exclusive);
    };
    connect(group, &QButtonGroup::buttonToggled, this, &ParameterEditor::userChanged);
}

void ParameterEditor::buildOrderedList()
{
    // Checked items in list order form the value; dragging reorders them.
    auto *list = new QListWidget(this);
    list->setDragDropMode(QAbstractItemView::InternalMove);
    list->setMaximumHeight(int(m_rule.choices.size()) * 20 + 8);
    for (const QString &choice : m_rule.choices) {
        auto *item = new QListWidgetItem(choice, list);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable | Qt::ItemIsDragEnabled);
        item->setCheckState(Qt::Unchecked);
    }
    layout()->addWidget(list);
    m_input = list;
    m_get = [list] {
        QStringList checked;
        for (int i = 0; i < list->count(); ++i) {
            if (list->item(i)->checkState() == Qt::Checked)
                checked.append(list->item(i)->text());
        }
        return checked.join(QLatin1Char(','));
    };
    m_set = [list](const QString &v) {
        const QStringList values = v.split(QLatin1Char(','), Qt::SkipEmptyParts);
        // Chosen values first, in their order, then the others.
        for (int target = 0; target < values.size(); ++target) {
            const auto found = list->findItems(values.at(target).trimmed(), Qt::MatchExactly);
            if (found.isEmpty())
                continue;
            QListWidgetItem *item = list->takeItem(list->row(found.first()));
            list->insertItem(target, item);
        }
        for (int i = 0; i < list->count(); ++i) {
            const bool chosen = values.contains(list->item(i)->text());
            list->item(i)->setCheckState(chosen ? Qt::Checked : Qt::Unchecked);
        }
    };
    connect(list, &QListWidget::itemChanged, this, &ParameterEditor::userChanged);
    connect(list->model(), &QAbstractItemModel::rowsMoved, this, &ParameterEditor::userChanged);
}

QString ParameterEditor::value() const
{
    return m_unshown ? *m_unshown : m_get();
}

void ParameterEditor::setValue(const QString &value)
{
    m_settingValue = true;
    m_set(value);
    m_settingValue = false;
    // A slider or spin box cannot show a value outside its range or off its step; the text is kept
    // as it is (and checked) until the user moves the widget, so nothing changes silently.
    m_unshown.reset();
    if (m_get() != value)
        m_unshown = value;
    changed();
}

QString ParameterEditor::error() const
{
    return m_rule.check(value());
}

void ParameterEditor::userChanged()
{
    if (m_settingValue)
        return;
    m_unshown.reset(); // the user moved the widget: its value counts now
    changed();
}

void ParameterEditor::changed()
{
    const QString text = value();
    if (m_sliderValue)
        m_sliderValue->setText(text);
    const QString problem = m_rule.check(text);
    m_error->setText(problem);
    m_error->setVisible(!problem.isEmpty());
    emit valueChanged(text);
}

} // namespace SystemEditor
