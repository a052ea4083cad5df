// SPDX-License-Identifier: MIT
#include "fieldrules.h"

#include <QCoreApplication>

namespace Studio::FieldRules {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Studio::FieldRules", text);
}

} // namespace

QString systemIdPartProblem(const QString &text)
{
    if (text.trimmed().isEmpty())
        return tr("This field is required (it is part of the system id).");
    if (text.contains(QLatin1Char(':')))
        return tr("':' separates the parts of the system id and cannot be used here.");
    return {};
}

} // namespace Studio::FieldRules
