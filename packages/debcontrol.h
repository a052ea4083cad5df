// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>

#include <optional>

namespace Packages {

/**
 * One paragraph of Debian control data (deb822): fields in their order, names matched without
 * regard to case as dpkg does. A value keeps its continuation lines ("\n" + " text"); the first
 * line is what follows "Name: ". Used for a package's DEBIAN/control, a repository's Packages
 * entries and its Release file.
 */
class DebControl
{
public:
    /// Parses the first paragraph of @p text; nothing, with the reason in @p error, when a line is
    /// neither a field nor a continuation.
    static std::optional<DebControl> parse(const QByteArray &text, QString *error = nullptr);
    /// Every paragraph of @p text (a Packages file); nothing when one is malformed.
    static std::optional<QList<DebControl>> parseAll(const QByteArray &text,
                                                     QString *error = nullptr);

    /// The value of @p name, or an empty string when absent.
    QString value(const QString &name) const;
    bool contains(const QString &name) const;
    /// Sets @p name, keeping its place when present, appending otherwise.
    void set(const QString &name, const QString &value);
    void remove(const QString &name);
    /// The field names in order.
    QStringList names() const;
    bool isEmpty() const { return m_fields.isEmpty(); }

    /// The paragraph as text, one "Name: value" per field, ending with a newline.
    QByteArray toText() const;

private:
    int indexOf(const QString &name) const;

    QList<QPair<QString, QString>> m_fields;
};

} // namespace Packages
