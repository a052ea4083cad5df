// SPDX-License-Identifier: MIT
#include "debnames.h"

#include <QRegularExpression>
#include <QStringList>

namespace Packages {

bool isValidPackageName(const QString &name)
{
    static const QRegularExpression pattern(QStringLiteral("^[a-z0-9][a-z0-9+.-]+$"));
    return pattern.match(name).hasMatch();
}

bool isValidVersion(const QString &version)
{
    QString rest = version;
    static const QRegularExpression epoch(QStringLiteral("^[0-9]+:"));
    const QRegularExpressionMatch e = epoch.match(rest);
    if (e.hasMatch())
        rest = rest.mid(e.capturedLength());
    if (rest.contains(QLatin1Char(':')))
        return false;
    const int dash = rest.lastIndexOf(QLatin1Char('-'));
    QString upstream = rest;
    if (dash >= 0) {
        static const QRegularExpression revision(QStringLiteral("^[A-Za-z0-9+.~]+$"));
        if (!revision.match(rest.mid(dash + 1)).hasMatch())
            return false;
        upstream = rest.left(dash);
    }
    static const QRegularExpression upstreamPattern(QStringLiteral("^[0-9][A-Za-z0-9.+~-]*$"));
    return upstreamPattern.match(upstream).hasMatch();
}

namespace {

QString namePart(const QString &text)
{
    static const QRegularExpression notAllowed(QStringLiteral("[^a-z0-9+.]+"));
    QString part = text.toLower().replace(notAllowed, QStringLiteral("-"));
    while (part.startsWith(QLatin1Char('-')) || part.startsWith(QLatin1Char('.'))
           || part.startsWith(QLatin1Char('+')))
        part.remove(0, 1);
    while (part.endsWith(QLatin1Char('-')))
        part.chop(1);
    return part;
}

} // namespace

std::optional<QString> componentPackageName(const QString &vendor, const QString &category,
                                            const QString &name, QString *error)
{
    const QString component = namePart(name);
    if (component.isEmpty()) {
        *error = QStringLiteral(
                     "the component name '%1' gives no package name (it needs letters or digits)")
                     .arg(name);
        return std::nullopt;
    }
    QStringList parts {QStringLiteral("rtc")};
    for (const QString &part : {namePart(vendor), namePart(category), component}) {
        if (!part.isEmpty())
            parts << part;
    }
    const QString result = parts.join(QLatin1Char('-'));
    if (!isValidPackageName(result)) {
        *error = QStringLiteral("'%1' is not a valid Debian package name").arg(result);
        return std::nullopt;
    }
    return result;
}

std::optional<QString> debianVersion(const QString &profileVersion, QString *error)
{
    QString version = profileVersion.trimmed();
    if (version.size() > 1
        && (version.at(0) == QLatin1Char('v') || version.at(0) == QLatin1Char('V'))
        && version.at(1).isDigit())
        version.remove(0, 1);
    static const QRegularExpression separators(QStringLiteral("[\\s_]+"));
    version.replace(separators, QStringLiteral("."));
    if (version.isEmpty()) {
        *error = QStringLiteral("the profile has no version");
        return std::nullopt;
    }
    if (!isValidVersion(version)) {
        *error
            = QStringLiteral(
                  "the version '%1' is not a valid Debian version (it must start with a digit and "
                  "use only letters, digits and . + ~ -)")
                  .arg(profileVersion);
        return std::nullopt;
    }
    return version;
}

QString versionInFileName(const QString &version)
{
    const int colon = version.indexOf(QLatin1Char(':'));
    return colon < 0 ? version : version.mid(colon + 1);
}

namespace {

// dpkg's ordering of characters in the non-digit parts: '~' before everything, even the end;
// letters before other characters.
int order(QChar c)
{
    if (c.isDigit())
        return 0;
    if (c.isLetter())
        return c.unicode();
    if (c == QLatin1Char('~'))
        return -1;
    if (c.isNull())
        return 0;
    return c.unicode() + 256;
}

int compareFragment(const QString &a, const QString &b)
{
    int i = 0;
    int j = 0;
    while (i < a.size() || j < b.size()) {
        int firstDiff = 0;
        while ((i < a.size() && !a.at(i).isDigit()) || (j < b.size() && !b.at(j).isDigit())) {
            const int ac = i < a.size() ? order(a.at(i)) : 0;
            const int bc = j < b.size() ? order(b.at(j)) : 0;
            if (ac != bc)
                return ac - bc;
            ++i;
            ++j;
        }
        while (i < a.size() && a.at(i) == QLatin1Char('0'))
            ++i;
        while (j < b.size() && b.at(j) == QLatin1Char('0'))
            ++j;
        while (i < a.size() && a.at(i).isDigit() && j < b.size() && b.at(j).isDigit()) {
            if (!firstDiff)
                firstDiff = a.at(i).unicode() - b.at(j).unicode();
            ++i;
            ++j;
        }
        if (i < a.size() && a.at(i).isDigit())
            return 1;
        if (j < b.size() && b.at(j).isDigit())
            return -1;
        if (firstDiff)
            return firstDiff;
    }
    return 0;
}

struct Parts
{
    qint64 epoch = 0;
    QString upstream;
    QString revision;
};

Parts split(const QString &version)
{
    Parts parts;
    QString rest = version;
    const int colon = rest.indexOf(QLatin1Char(':'));
    if (colon >= 0) {
        parts.epoch = rest.left(colon).toLongLong();
        rest = rest.mid(colon + 1);
    }
    const int dash = rest.lastIndexOf(QLatin1Char('-'));
    parts.upstream = dash < 0 ? rest : rest.left(dash);
    parts.revision = dash < 0 ? QString() : rest.mid(dash + 1);
    return parts;
}

} // namespace

int compareVersions(const QString &a, const QString &b)
{
    const Parts pa = split(a);
    const Parts pb = split(b);
    if (pa.epoch != pb.epoch)
        return pa.epoch < pb.epoch ? -1 : 1;
    if (const int c = compareFragment(pa.upstream, pb.upstream))
        return c;
    return compareFragment(pa.revision, pb.revision);
}

} // namespace Packages
