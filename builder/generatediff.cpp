// SPDX-License-Identifier: MIT
#include "generatediff.h"

#include <QRegularExpression>

#include <algorithm>
#include <vector>

namespace Builder {

namespace {

/// Above this many cells the LCS table would cost too much memory for a dialog's diff.
constexpr qsizetype MaxTableCells = 16 * 1000 * 1000;

using Kind = DiffLine::Kind;

void appendRange(QList<DiffLine> *out, Kind kind, const QStringList &lines, int from, int to)
{
    for (int i = from; i < to; ++i) {
        DiffLine line {kind, lines.at(i), 0, 0};
        if (kind == Kind::Removed)
            line.oldLine = i + 1;
        else
            line.newLine = i + 1;
        out->append(line);
    }
}

/// LCS of old[a0, a1) and new[b0, b1) by dynamic programming, walked forward from the start.
void diffMiddle(const QStringList &a, int a0, int a1, const QStringList &b, int b0, int b1,
                QList<DiffLine> *out)
{
    const int n = a1 - a0;
    const int m = b1 - b0;
    if (qsizetype(n + 1) * qsizetype(m + 1) > MaxTableCells) {
        appendRange(out, Kind::Removed, a, a0, a1);
        appendRange(out, Kind::Added, b, b0, b1);
        return;
    }
    // table[i][j]: LCS length of the suffixes a[a0+i..] and b[b0+j..].
    std::vector<int> table(size_t(n + 1) * size_t(m + 1), 0);
    auto at = [&](int i, int j) -> int & { return table[size_t(i) * size_t(m + 1) + size_t(j)]; };
    for (int i = n - 1; i >= 0; --i) {
        for (int j = m - 1; j >= 0; --j)
            at(i, j) = a.at(a0 + i) == b.at(b0 + j) ? at(i + 1, j + 1) + 1
                                                    : std::max(at(i + 1, j), at(i, j + 1));
    }
    int i = 0;
    int j = 0;
    QList<DiffLine> added; // held back so that a change reads removed-then-added
    auto flushAdded = [&] {
        out->append(added);
        added.clear();
    };
    while (i < n || j < m) {
        if (i < n && j < m && a.at(a0 + i) == b.at(b0 + j)) {
            flushAdded();
            out->append({Kind::Same, a.at(a0 + i), a0 + i + 1, b0 + j + 1});
            ++i;
            ++j;
        } else if (j < m && (i == n || at(i, j + 1) >= at(i + 1, j))) {
            added.append({Kind::Added, b.at(b0 + j), 0, b0 + j + 1});
            ++j;
        } else {
            out->append({Kind::Removed, a.at(a0 + i), a0 + i + 1, 0});
            ++i;
        }
    }
    flushAdded();
}

QString hunkRange(int start, int count)
{
    // Unified diff convention: an empty range names the line before it.
    if (count == 0)
        return QStringLiteral("%1,0").arg(start - 1);
    if (count == 1)
        return QString::number(start);
    return QStringLiteral("%1,%2").arg(start).arg(count);
}

QString hunk(const QList<DiffLine> &lines, int from, int to)
{
    int oldStart = 0, newStart = 0, oldCount = 0, newCount = 0;
    QString body;
    for (int k = from; k < to; ++k) {
        const DiffLine &line = lines.at(k);
        if (line.kind != Kind::Added) {
            oldStart = oldStart ? oldStart : line.oldLine;
            ++oldCount;
        }
        if (line.kind != Kind::Removed) {
            newStart = newStart ? newStart : line.newLine;
            ++newCount;
        }
        const QChar sign = line.kind == Kind::Same ? QLatin1Char(' ')
            : line.kind == Kind::Removed           ? QLatin1Char('-')
                                                   : QLatin1Char('+');
        body += sign + line.text + QLatin1Char('\n');
    }
    // A hunk without old (or new) lines starts after the line before it.
    if (!oldStart) {
        oldStart = 1;
        for (int k = from; k >= 0; --k) {
            if (lines.at(k).oldLine) {
                oldStart = lines.at(k).oldLine + 1;
                break;
            }
        }
    }
    if (!newStart) {
        newStart = 1;
        for (int k = from; k >= 0; --k) {
            if (lines.at(k).newLine) {
                newStart = lines.at(k).newLine + 1;
                break;
            }
        }
    }
    return QStringLiteral("@@ -%1 +%2 @@\n")
               .arg(hunkRange(oldStart, oldCount), hunkRange(newStart, newCount))
        + body;
}

} // namespace

QStringList diffLines(const QString &text)
{
    static const QRegularExpression breaks(QStringLiteral("\r\n|\r|\n"));
    QStringList lines = text.split(breaks);
    if (!lines.isEmpty() && lines.constLast().isEmpty())
        lines.removeLast();
    return lines;
}

QList<DiffLine> lineDiff(const QStringList &oldLines, const QStringList &newLines)
{
    QList<DiffLine> out;
    int head = 0;
    const int common = int(std::min(oldLines.size(), newLines.size()));
    while (head < common && oldLines.at(head) == newLines.at(head)) {
        out.append({Kind::Same, oldLines.at(head), head + 1, head + 1});
        ++head;
    }
    int oldEnd = int(oldLines.size());
    int newEnd = int(newLines.size());
    while (oldEnd > head && newEnd > head && oldLines.at(oldEnd - 1) == newLines.at(newEnd - 1)) {
        --oldEnd;
        --newEnd;
    }
    diffMiddle(oldLines, head, oldEnd, newLines, head, newEnd, &out);
    for (int k = 0; oldEnd + k < oldLines.size(); ++k)
        out.append({Kind::Same, oldLines.at(oldEnd + k), oldEnd + k + 1, newEnd + k + 1});
    return out;
}

QString unifiedDiff(const QString &oldText, const QString &newText, const QString &oldName,
                    const QString &newName, int context)
{
    const QList<DiffLine> lines = lineDiff(diffLines(oldText), diffLines(newText));
    context = std::max(context, 0);
    QString result;
    int k = 0;
    const int count = int(lines.size());
    while (k < count) {
        while (k < count && lines.at(k).kind == Kind::Same)
            ++k;
        if (k == count)
            break;
        const int from = std::max(k - context, 0);
        // Extend the hunk while the next change is close enough for the contexts to touch.
        int end = k;
        for (;;) {
            while (end < count && lines.at(end).kind != Kind::Same)
                ++end;
            int same = end;
            while (same < count && lines.at(same).kind == Kind::Same)
                ++same;
            if (same < count && same - end <= 2 * context) {
                end = same;
                continue;
            }
            end = std::min(end + context, count);
            break;
        }
        result += hunk(lines, from, end);
        k = end;
    }
    if (result.isEmpty())
        return result;
    return QStringLiteral("--- %1\n+++ %2\n").arg(oldName, newName) + result;
}

} // namespace Builder
