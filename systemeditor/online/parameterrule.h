// SPDX-License-Identifier: MIT
#pragma once

#include "rtcconstraint.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace SystemEditor {

/**
 * How the Configuration view edits one parameter: the widget named by the component's hidden
 * `__widget__` set (`text`, `slider.STEP`, `spin`, `radio`, `checkbox`, `ordered_list`) and the
 * check from its `__constraints__` set (the constraint string syntax of RTC Builder).
 */
struct ParameterRule
{
    enum class Widget { Text, Slider, Spin, Radio, CheckBox, OrderedList };

    Widget widget = Widget::Text;
    double step = 1; ///< slider/spin step (`slider.0.1` → 0.1)
    std::optional<double> minimum; ///< lower bound read from the constraint
    std::optional<double> maximum; ///< upper bound read from the constraint
    QStringList choices; ///< enumeration values for radio, checkbox and ordered_list
    std::optional<Profile::RtcConstraint> constraint;
    QString constraintText;
    QString constraintError; ///< why the constraint string could not be read

    /// Builds the rule from the `__widget__` and `__constraints__` values of a parameter. A widget
    /// that needs choices or bounds the constraint does not give falls back to text.
    static ParameterRule from(const QString &widgetSpec, const QString &constraintText);

    /// Empty when `value` satisfies the constraint, else a short reason.
    QString check(const QString &value) const;
    /// True when the values are whole numbers (step and bounds integral).
    bool isIntegral() const;
};

} // namespace SystemEditor
