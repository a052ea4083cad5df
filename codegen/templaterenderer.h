// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QVariantMap>

#include <optional>

namespace Codegen {

/**
 * Renders a mustache template (kainjow mustache) with a context built from Qt values:
 * QVariantMap → object, QVariantList / QStringList → list, bool → section flag, anything else
 * → its text. Values are inserted verbatim (no HTML escaping: the output is source code).
 *
 * Returns nothing and sets `error` (with the template's own message) when the template text is
 * not valid mustache.
 */
std::optional<QString> renderTemplate(const QString &templateText, const QVariantMap &context,
                                      QString *error);

} // namespace Codegen
