// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "diagnostic.h"

#include <QHash>

namespace Builder {

/// Problems of one element, keyed by the model field they are about ("name", "type",
/// "variableName", "position", "defaultValue", "widget" …); the value says what is wrong.
using FieldProblems = QHash<QString, QString>;

/**
 * The editor's rules for one data port, service port or configuration parameter: name charset,
 * names unique across all ports (data and service share one name space), variable names unique
 * across the component, required type and default, known position, a known widget with a
 * numeric step, and a radio widget only with an enumeration constraint.
 */
FieldProblems itemProblems(const Profile::RtcProfile &profile, Part part, int index);

/// The rules for one interface of a service port (name, uniqueness in the port, direction,
/// type, variable name).
FieldProblems interfaceProblems(const Profile::RtcProfile &profile, int portIndex,
                                int interfaceIndex);

/// Non-empty when the category is `composite.…` but the component has ports.
QString compositePortsProblem(const Profile::RtcProfile &profile);

/// The configuration widgets RTC Builder offers.
const QStringList &configurationWidgets();

/**
 * Everything that refuses code generation: the errors of validateRtcProfile() plus the editor's
 * rules above (one diagnostic per problem, `object` naming the element).
 */
Profile::Diagnostics generationProblems(const Profile::RtcProfile &profile);

} // namespace Builder
