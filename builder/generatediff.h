// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QString>
#include <QStringList>

namespace Builder {

/// One line of a line diff.
struct DiffLine
{
    enum class Kind { Same, Removed, Added };

    Kind kind = Kind::Same;
    QString text;
    int oldLine = 0; ///< 1-based line in the old text; 0 for added lines
    int newLine = 0; ///< 1-based line in the new text; 0 for removed lines

    bool operator==(const DiffLine &other) const
    {
        return kind == other.kind && text == other.text && oldLine == other.oldLine
            && newLine == other.newLine;
    }
    bool operator!=(const DiffLine &other) const { return !(*this == other); }
};

/// The lines of a text (`\n`, `\r\n` or `\r` separated); a final line break adds no empty line.
QStringList diffLines(const QString &text);

/**
 * The line diff of `oldLines` → `newLines` along a longest common subsequence: every line of
 * both once, in order, removed lines of a change before the added ones. Common leading and
 * trailing lines are matched first; a middle too large for the LCS table is shown as all
 * removed, then all added.
 */
QList<DiffLine> lineDiff(const QStringList &oldLines, const QStringList &newLines);

/**
 * A unified diff (`--- old`, `+++ new`, `@@ -a,b +c,d @@` hunks with `context` lines around each
 * change) of two texts; empty when they have the same lines.
 */
QString unifiedDiff(const QString &oldText, const QString &newText, const QString &oldName,
                    const QString &newName, int context = 3);

} // namespace Builder
