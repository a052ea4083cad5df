// SPDX-License-Identifier: MIT
#include "fieldrules.h"

#include <QCoreApplication>

namespace Studio::FieldRules {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Studio::FieldRules)
};

} // namespace

QString systemIdPartProblem(const QString &text)
{
    if (text.trimmed().isEmpty())
        return Text::tr("This field is required (it is part of the system id).");
    if (text.contains(QLatin1Char(':')))
        return Text::tr("':' separates the parts of the system id and cannot be used here.");
    return {};
}

} // namespace Studio::FieldRules
