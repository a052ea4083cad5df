// SPDX-License-Identifier: MIT
#pragma once

#include "builderfieldrules.h"

#include <QString>

namespace Studio::FieldRules {

/**
 * Checks of single form fields, shown inline next to the field. Each returns an empty string
 * when the text is acceptable, else a short sentence saying what is wrong. The document keeps any
 * text regardless (a bad value is never lost); these only tell the user.
 *
 * The rules the Builder defines (names, required fields, numbers, enumerations) are used as they
 * are; the system id rule is the application's own.
 */
using Builder::FieldRules::componentNameProblem;
using Builder::FieldRules::enumerationProblem;
using Builder::FieldRules::nonNegativeIntegerProblem;
using Builder::FieldRules::nonNegativeNumberProblem;
using Builder::FieldRules::requiredProblem;

/// A part of a system id (vendor, name, version): required and free of ':'.
QString systemIdPartProblem(const QString &text);

} // namespace Studio::FieldRules
