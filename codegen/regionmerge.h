// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

#include <optional>

namespace Codegen {

/// The outcome of merging a fresh generated file into the user's edited one.
struct RegionMergeResult
{
    std::optional<QString> text; ///< nothing when the user's file has broken markers
    QStringList refreshed; ///< blocks whose bodies were replaced, in file order
    QStringList notInExisting; ///< fresh blocks the user's file no longer has (not added)
    QString error; ///< why `text` is empty: `line N: …`
};

/**
 * Generator-owned regions are wrapped in comment lines holding `<rtc-template block="NAME">`
 * and `</rtc-template>` (in any comment syntax: `// `, `# `, `<!-- -->`). Merging keeps the
 * user's file and replaces only the lines between each pair of markers with the fresh file's
 * lines of the block of the same name; everything outside the markers, and blocks the fresh
 * file does not have, stay as the user left them.
 */
RegionMergeResult mergeTemplateRegions(const QString &existing, const QString &fresh);

/// The names of the marked blocks of a text, in order (duplicates kept).
QStringList templateRegionNames(const QString &text);

} // namespace Codegen
