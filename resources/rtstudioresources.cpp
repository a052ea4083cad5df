// SPDX-License-Identifier: MIT
#include "rtstudioresources.h"

namespace Resources {

QString iconPath(const QString &name)
{
    return QStringLiteral(":/icons/%1.svg").arg(name);
}

QString applicationIconPath()
{
    return iconPath(QStringLiteral("rtstudio"));
}

} // namespace Resources
