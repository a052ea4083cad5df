// SPDX-License-Identifier: MIT
#include "debcontrol.h"

#include <QStringList>

namespace Packages {

std::optional<DebControl> DebControl::parse(const QByteArray &text, QString *error)
{
    DebControl control;
    const QList<QByteArray> lines = text.split('\n');
    int lineNumber = 0;
    for (const QByteArray &raw : lines) {
        ++lineNumber;
        const QString line = QString::fromUtf8(raw).remove(QLatin1Char('\r'));
        if (line.trimmed().isEmpty()) {
            if (!control.isEmpty())
                break; // the end of the paragraph
            continue;
        }
        if (line.startsWith(QLatin1Char('#')))
            continue;
        if (line.startsWith(QLatin1Char(' ')) || line.startsWith(QLatin1Char('\t'))) {
            if (control.isEmpty()) {
                if (error)
                    *error
                        = QStringLiteral("line %1: continuation before any field").arg(lineNumber);
                return std::nullopt;
            }
            control.m_fields.last().second += QLatin1Char('\n') + line;
            continue;
        }
        const int colon = line.indexOf(QLatin1Char(':'));
        if (colon <= 0) {
            if (error)
                *error = QStringLiteral("line %1: not a 'Name: value' field").arg(lineNumber);
            return std::nullopt;
        }
        control.m_fields.append({line.left(colon).trimmed(), line.mid(colon + 1).trimmed()});
    }
    return control;
}

std::optional<QList<DebControl>> DebControl::parseAll(const QByteArray &text, QString *error)
{
    QList<DebControl> paragraphs;
    QByteArray normalized = text;
    normalized.replace("\r\n", "\n");
    // Paragraphs are separated by blank lines (lines of only spaces count as blank).
    QByteArray current;
    auto flush = [&]() -> bool {
        if (current.trimmed().isEmpty())
            return true;
        std::optional<DebControl> paragraph = parse(current, error);
        if (!paragraph)
            return false;
        paragraphs << *paragraph;
        current.clear();
        return true;
    };
    for (const QByteArray &line : normalized.split('\n')) {
        if (line.trimmed().isEmpty()) {
            if (!flush())
                return std::nullopt;
            current.clear();
        } else {
            current += line + '\n';
        }
    }
    if (!flush())
        return std::nullopt;
    return paragraphs;
}

int DebControl::indexOf(const QString &name) const
{
    for (int i = 0; i < m_fields.size(); ++i) {
        if (m_fields.at(i).first.compare(name, Qt::CaseInsensitive) == 0)
            return i;
    }
    return -1;
}

QString DebControl::value(const QString &name) const
{
    const int i = indexOf(name);
    return i < 0 ? QString() : m_fields.at(i).second;
}

bool DebControl::contains(const QString &name) const
{
    return indexOf(name) >= 0;
}

void DebControl::set(const QString &name, const QString &value)
{
    const int i = indexOf(name);
    if (i < 0)
        m_fields.append({name, value});
    else
        m_fields[i].second = value;
}

void DebControl::remove(const QString &name)
{
    const int i = indexOf(name);
    if (i >= 0)
        m_fields.removeAt(i);
}

QStringList DebControl::names() const
{
    QStringList result;
    for (const auto &field : m_fields)
        result << field.first;
    return result;
}

QByteArray DebControl::toText() const
{
    QByteArray text;
    for (const auto &field : m_fields) {
        // A value that starts on the next line (Release's checksum lists) has no space after ':'.
        const QString &value = field.second;
        const bool startsOnNextLine = value.startsWith(QLatin1Char('\n'));
        text += field.first.toUtf8() + (startsOnNextLine ? ":" : ": ") + value.toUtf8() + '\n';
    }
    return text;
}

} // namespace Packages
