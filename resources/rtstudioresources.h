// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Resources {

/// Resource path of a bundled SVG icon, e.g. `iconPath(u"save")` → `:/icons/save.svg`.
QString iconPath(const QString &name);

/// Resource path of the application icon.
QString applicationIconPath();

} // namespace Resources
