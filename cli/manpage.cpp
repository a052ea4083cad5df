// SPDX-License-Identifier: MIT
#include "manpage.h"

#include "commandline.h"

#include <QFile>

namespace Cli {

namespace {

const QString CommandsMarker = QStringLiteral(".\\\" @COMMANDS@\n");

QString escapeLine(const QString &line)
{
    QString out;
    // A line starting with . or ' would be a request, not text.
    if (line.startsWith(QLatin1Char('.')) || line.startsWith(QLatin1Char('\'')))
        out += QStringLiteral("\\&");
    for (const char32_t c : line.toUcs4()) {
        if (c == U'\\')
            out += QStringLiteral("\\e");
        else if (c == U'-')
            out += QStringLiteral("\\-"); // a minus, so that options copied from the page work
        else if (c > 0x7e)
            out += QStringLiteral("\\[u%1]").arg(
                QString::number(uint(c), 16).toUpper().rightJustified(4, QLatin1Char('0')));
        else
            out += QChar(char16_t(c));
    }
    return out;
}

} // namespace

QString ManPage::escape(const QString &text)
{
    QStringList lines = text.split(QLatin1Char('\n'));
    for (QString &line : lines)
        line = escapeLine(line);
    return lines.join(QLatin1Char('\n'));
}

QString ManPage::commandsSection(const CommandLine &commandLine)
{
    QString roff = QStringLiteral(
        ".SH COMMANDS\n"
        "Each command's usage, as\n.BI \"rtctl \" COMMAND \" \\-\\-help\"\nprints it.\n");
    for (const auto &command : commandLine.commands()) {
        roff += QStringLiteral(".SS \"rtctl %1\"\n%2\n.PP\n.RS 4\n.nf\n")
                    .arg(escape(command->name()), escape(command->summary()));
        // Blank lines inside the block would end it for some formatters: .sp keeps the gap.
        for (const QString &line : escape(command->usage().trimmed()).split(QLatin1Char('\n')))
            roff += line.trimmed().isEmpty() ? QStringLiteral(".sp\n") : line + QLatin1Char('\n');
        roff += QStringLiteral(".fi\n.RE\n");
    }
    return roff;
}

QString ManPage::roff(const CommandLine &commandLine, const QString &version)
{
    QFile file(QStringLiteral(":/man/rtctl.1.in"));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QString page = QString::fromUtf8(file.readAll());
    page.replace(QStringLiteral("@VERSION@"), version);
    page.replace(CommandsMarker, commandsSection(commandLine));
    return page;
}

} // namespace Cli
