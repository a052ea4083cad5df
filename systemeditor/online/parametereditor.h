// SPDX-License-Identifier: MIT
#pragma once

#include "parameterrule.h"

#include <QWidget>

#include <functional>
#include <optional>

class QLabel;

namespace SystemEditor {

/**
 * The editor of one configuration parameter: the widget its ParameterRule names, plus a line that
 * shows why the current value breaks the constraint. value()/setValue() use the parameter's text
 * form (comma-separated for checkbox and ordered_list).
 */
class ParameterEditor : public QWidget
{
    Q_OBJECT

public:
    ParameterEditor(const QString &name, const ParameterRule &rule, QWidget *parent = nullptr);

    QString name() const { return m_name; }
    const ParameterRule &rule() const { return m_rule; }
    QString value() const;
    void setValue(const QString &value);
    /// Empty when the value satisfies the constraint.
    QString error() const;
    /// The widget that edits the value (QLineEdit, QSlider, QSpinBox/QDoubleSpinBox, a radio group,
    /// checkboxes or a QListWidget), with object name `editor_<name>`.
    QWidget *input() const { return m_input; }

signals:
    void valueChanged(const QString &value);

private:
    void buildText();
    void buildSlider();
    void buildSpin();
    void buildChoices(bool exclusive);
    void buildOrderedList();
    void userChanged();
    void changed();

    QString m_name;
    ParameterRule m_rule;
    QWidget *m_input = nullptr;
    QLabel *m_sliderValue = nullptr;
    QLabel *m_error = nullptr;
    std::optional<QString> m_unshown; ///< a value the widget cannot represent, kept verbatim
    bool m_settingValue = false;
    std::function<QString()> m_get;
    std::function<void(const QString &)> m_set;
};

} // namespace SystemEditor
