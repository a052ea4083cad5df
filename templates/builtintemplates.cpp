// SPDX-License-Identifier: MIT
#include "builtintemplates.h"

namespace Templates {

QString builtinRoot()
{
    return QStringLiteral(":/rtstudio/templates/");
}

} // namespace Templates
