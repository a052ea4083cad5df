// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

namespace Builder::FieldRules {

/**
 * Checks of single form fields, shown inline next to the field. Each returns an empty string
 * when the text is acceptable, else a short sentence saying what is wrong. The model keeps any
 * text regardless (a bad value is never lost); these only tell the user.
 */

/// A name (component, port, parameter, interface): required, `[0-9A-Za-z_\-:]` only.
QString componentNameProblem(const QString &text);
/// A required text field.
QString requiredProblem(const QString &text);
/// Empty (absent) or an integer ≥ 0.
QString nonNegativeIntegerProblem(const QString &text);
/// Empty (absent) or a number ≥ 0.
QString nonNegativeNumberProblem(const QString &text);
/// One of `allowed` (exact spelling).
QString enumerationProblem(const QString &text, const QStringList &allowed);
/// Empty or a C++ identifier (variable names).
QString identifierProblem(const QString &text);

} // namespace Builder::FieldRules
