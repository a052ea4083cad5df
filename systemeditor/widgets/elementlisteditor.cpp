// SPDX-License-Identifier: MIT
#include "elementlisteditor.h"

#include "constraintsyntax.h"
#include "parametereditor.h"
#include "rtcprofile.h"

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QPushButton>
#include <QToolButton>
#include <QVBoxLayout>

namespace SystemEditor {

using namespace Profile;

bool ElementRules::appliesTo(const RtcConfiguration &configuration)
{
    const QString type = configuration.type.trimmed();
    const bool vector = type.startsWith(QLatin1String("vector<"))
        || type.startsWith(QLatin1String("std::vector<"));
    const bool list = configuration.constraint
        && configuration.constraint->kind == RtcConstraintKind::List;
    return vector || list;
}

ElementRules ElementRules::of(const RtcConfiguration &configuration)
{
    ElementRules rules;
    rules.widgetSpec = configuration.widget().value_or(QString());
    if (configuration.constraint && configuration.constraint->kind == RtcConstraintKind::List) {
        for (const RtcConstraint &member : configuration.constraint->members)
            rules.memberTexts << constraintToString(member);
    } else {
        rules.constraintText = constraintToString(configuration.constraint);
    }
    return rules;
}

ParameterRule ElementRules::ruleAt(int index) const
{
    if (memberTexts.isEmpty())
        return ParameterRule::from(widgetSpec, constraintText);
    return ParameterRule::from(widgetSpec, memberTexts.value(index));
}

QStringList ElementRules::split(const QString &value)
{
    if (value.trimmed().isEmpty())
        return {};
    QStringList parts = value.split(QLatin1Char(','));
    for (QString &part : parts)
        part = part.trimmed();
    return parts;
}

QString ElementRules::check(const QString &value) const
{
    const QStringList elements = split(value);
    for (int i = 0; i < elements.size(); ++i) {
        const QString problem = ruleAt(i).check(elements.at(i));
        if (!problem.isEmpty())
            return QCoreApplication::translate("SystemEditor::ElementRules", "Element %1: %2")
                .arg(i + 1)
                .arg(problem);
    }
    return {};
}

ElementListEditor::ElementListEditor(const QString &name, const ElementRules &rules,
                                     QWidget *parent)
    : QWidget(parent)
    , m_name(name)
    , m_rules(rules)
    , m_rows(new QVBoxLayout)
    , m_add(new QPushButton(tr("Add element")))
{
    setObjectName(QStringLiteral("elements_") + name);
    m_add->setObjectName(QStringLiteral("addElement_") + name);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_rows->setSpacing(2);
    layout->addLayout(m_rows);
    auto *addRow = new QHBoxLayout;
    addRow->addWidget(m_add);
    addRow->addStretch(1);
    layout->addLayout(addRow);
    connect(m_add, &QPushButton::clicked, this, &ElementListEditor::addElement);
}

QString ElementListEditor::value() const
{
    QStringList values;
    for (const ParameterEditor *element : m_elements)
        values << element->value();
    return values.join(QLatin1Char(','));
}

void ElementListEditor::setValue(const QString &value)
{
    const QStringList values = ElementRules::split(value);
    m_settingValue = true;
    if (values.size() == m_elements.size()) {
        // Same shape: the widgets stay (one being dragged or typed in keeps its focus).
        for (int i = 0; i < values.size(); ++i) {
            if (m_elements.at(i)->value() != values.at(i))
                m_elements.at(i)->setValue(values.at(i));
        }
    } else {
        rebuild(values);
    }
    m_settingValue = false;
}

void ElementListEditor::rebuild(const QStringList &values)
{
    // Later: the clicked remove button is one of these widgets.
    while (QLayoutItem *item = m_rows->takeAt(0)) {
        item->widget()->hide();
        item->widget()->deleteLater();
        delete item;
    }
    m_elements.clear();
    for (int i = 0; i < values.size(); ++i) {
        auto *row = new QWidget;
        auto *rowLayout = new QHBoxLayout(row);
        rowLayout->setContentsMargins(0, 0, 0, 0);
        auto *element = new ParameterEditor(QStringLiteral("%1[%2]").arg(m_name).arg(i),
                                            m_rules.ruleAt(i), row);
        element->setValue(values.at(i));
        auto *remove = new QToolButton(row);
        remove->setObjectName(QStringLiteral("removeElement_%1").arg(i));
        remove->setText(QStringLiteral("\u2212"));
        remove->setToolTip(tr("Remove element %1").arg(i + 1));
        rowLayout->addWidget(element, 1);
        rowLayout->addWidget(remove, 0, Qt::AlignTop);
        m_rows->addWidget(row);
        m_elements << element;
        connect(element, &ParameterEditor::valueChanged, this, [this] {
            if (!m_settingValue)
                emit valueChanged(value(), false);
        });
        connect(remove, &QToolButton::clicked, this, [this, i] { removeElement(i); });
    }
}

void ElementListEditor::addElement()
{
    QStringList values = ElementRules::split(value());
    // A new element repeats the last one (a valid value), or starts at the lower bound.
    const std::optional<double> minimum = m_rules.ruleAt(0).minimum;
    if (!values.isEmpty())
        values << values.last();
    else
        values << (minimum ? QString::number(*minimum) : QString());
    rebuild(values);
    emit valueChanged(value(), true);
}

void ElementListEditor::removeElement(int index)
{
    QStringList values = ElementRules::split(value());
    if (index < 0 || index >= values.size())
        return;
    values.removeAt(index);
    rebuild(values);
    emit valueChanged(value(), true);
}

} // namespace SystemEditor
