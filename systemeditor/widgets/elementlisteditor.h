// SPDX-License-Identifier: MIT
#pragma once

#include "parameterrule.h"

#include <QWidget>

class QPushButton;
class QVBoxLayout;

namespace Profile {
struct RtcConfiguration;
}

namespace SystemEditor {

class ParameterEditor;

/**
 * The rules of a configuration parameter whose value is an array (`vector<T>`, written as
 * comma-separated elements): each element is edited with the parameter's widget and checked on
 * its own, against the constraint's i-th member for a list constraint (`c0,c1,…`; elements past
 * the last member have none) or against the whole constraint otherwise.
 */
struct ElementRules
{
    QString widgetSpec;
    QString constraintText; ///< the whole constraint (not a list)
    QStringList memberTexts; ///< a list constraint's members

    /// Whether `configuration` is edited per element (a vector type or a list constraint).
    static bool appliesTo(const Profile::RtcConfiguration &configuration);
    static ElementRules of(const Profile::RtcConfiguration &configuration);
    ParameterRule ruleAt(int index) const;
    /// Empty when every element of `value` satisfies its constraint, else the first reason.
    QString check(const QString &value) const;
    static QStringList split(const QString &value);
};

/**
 * Editor of an array parameter: one ParameterEditor per element (object name `<name>[i]`), each
 * with its remove button, plus "Add element" (a new element repeats the last one). value() is the
 * elements joined by commas. valueChanged() tells whether elements were added or removed, so that
 * such an edit becomes its own undo step.
 */
class ElementListEditor : public QWidget
{
    Q_OBJECT

public:
    ElementListEditor(const QString &name, const ElementRules &rules, QWidget *parent = nullptr);

    QString name() const { return m_name; }
    QString value() const;
    void setValue(const QString &value);
    QString error() const { return m_rules.check(value()); }
    int count() const { return int(m_elements.size()); }
    ParameterEditor *element(int index) const { return m_elements.value(index); }

    void addElement();
    void removeElement(int index);

signals:
    void valueChanged(const QString &value, bool structural);

private:
    void rebuild(const QStringList &values);

    QString m_name;
    ElementRules m_rules;
    QVBoxLayout *m_rows;
    QPushButton *m_add;
    QList<ParameterEditor *> m_elements;
    bool m_settingValue = false;
};

} // namespace SystemEditor
