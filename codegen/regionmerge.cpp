// SPDX-License-Identifier: MIT
#include "regionmerge.h"

#include <QMap>
#include <QRegularExpression>

namespace Codegen {

namespace {

// A marker counts only on a line of its own, optionally inside a comment (`//`, `#`, `<!-- -->`,
// `/* */` …): text that merely mentions a marker, such as the generated README explaining them,
// must not open a block.
QRegularExpression markerLine(const QString &marker)
{
    return QRegularExpression(QStringLiteral("^\\s*(?:(?://+|#+|<!--|/\\*+|\\*|--|;+|%+)\\s*)?")
                              + marker + QStringLiteral("\\s*(?:-->|\\*/)?\\s*$"));
}

const QRegularExpression &openMarker()
{
    static const QRegularExpression re
        = markerLine(QStringLiteral("<rtc-template\\s+block\\s*=\\s*\"([^\"]*)\"\\s*>"));
    return re;
}

bool isCloseMarker(const QString &line)
{
    static const QRegularExpression re = markerLine(QStringLiteral("</rtc-template>"));
    return re.match(line).hasMatch();
}

struct Block
{
    QString name;
    int openLine = 0; ///< index of the marker line
    int closeLine = 0;
};

/// The blocks of a text; nothing plus `error` when a block is not closed or nested.
std::optional<QList<Block>> findBlocks(const QStringList &lines, QString *error)
{
    QList<Block> blocks;
    std::optional<Block> open;
    for (int i = 0; i < lines.size(); ++i) {
        const QRegularExpressionMatch match = openMarker().match(lines.at(i));
        if (match.hasMatch()) {
            if (open) {
                *error = QStringLiteral("line %1: block \"%2\" starts inside block \"%3\"")
                             .arg(i + 1).arg(match.captured(1), open->name);
                return std::nullopt;
            }
            open = Block{match.captured(1), i, -1};
        } else if (isCloseMarker(lines.at(i))) {
            if (!open) {
                *error = QStringLiteral("line %1: </rtc-template> without a block").arg(i + 1);
                return std::nullopt;
            }
            open->closeLine = i;
            blocks << *open;
            open.reset();
        }
    }
    if (open) {
        *error = QStringLiteral("line %1: block \"%2\" is not closed")
                     .arg(open->openLine + 1).arg(open->name);
        return std::nullopt;
    }
    return blocks;
}

// Split keeping the text exact: joining with '\n' gives back the input, including a final
// newline (an empty last element) and any '\r' before it.
QStringList splitLines(const QString &text)
{
    return text.split(QLatin1Char('\n'));
}

} // namespace

QStringList templateRegionNames(const QString &text)
{
    QStringList names;
    const QStringList lines = splitLines(text);
    for (const QString &line : lines) {
        const QRegularExpressionMatch match = openMarker().match(line);
        if (match.hasMatch())
            names << match.captured(1);
    }
    return names;
}

RegionMergeResult mergeTemplateRegions(const QString &existing, const QString &fresh)
{
    RegionMergeResult result;
    const QStringList oldLines = splitLines(existing);
    const QStringList newLines = splitLines(fresh);
    QString error;
    const std::optional<QList<Block>> oldBlocks = findBlocks(oldLines, &error);
    if (!oldBlocks) {
        result.error = error;
        return result;
    }
    const std::optional<QList<Block>> newBlocks = findBlocks(newLines, &error);
    if (!newBlocks) {
        result.error = QStringLiteral("generated text: ") + error;
        return result;
    }
    // A name may stand for several blocks: the n-th of the user's takes the n-th fresh one.
    QMap<QString, QList<Block>> freshByName;
    for (const Block &block : *newBlocks)
        freshByName[block.name] << block;
    QMap<QString, int> taken;

    QStringList merged;
    int next = 0; // first old line not yet copied
    for (const Block &block : *oldBlocks) {
        const QList<Block> candidates = freshByName.value(block.name);
        const int index = taken[block.name]++;
        if (index >= candidates.size())
            continue;
        const Block &freshBlock = candidates.at(index);
        merged << oldLines.mid(next, block.openLine + 1 - next);
        merged << newLines.mid(freshBlock.openLine + 1, freshBlock.closeLine - freshBlock.openLine - 1);
        next = block.closeLine;
        result.refreshed << block.name;
    }
    merged << oldLines.mid(next);
    for (const Block &block : *newBlocks) {
        const bool present = std::any_of(oldBlocks->cbegin(), oldBlocks->cend(),
                                         [&](const Block &b) { return b.name == block.name; });
        if (!present && !result.notInExisting.contains(block.name))
            result.notInExisting << block.name;
    }
    result.text = merged.join(QLatin1Char('\n'));
    return result;
}

} // namespace Codegen
