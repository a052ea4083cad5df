// SPDX-License-Identifier: MIT
#include "dependencycheck.h"

#include "packagestore.h"

#include <debnames.h>
#include <packagetool.h>

#include <QHash>
#include <QRegularExpression>

namespace Packages {

namespace {

/// One alternative of a dependency: `name[:arch] [(relation version)]`.
struct Requirement
{
    QString name;
    QString relation;
    QString version;
};

Requirement parseRequirement(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral(
        "^\\s*([^\\s:(]+)(?::\\S+)?\\s*(?:\\(\\s*(<<|<=|=|>=|>>|<|>)\\s*([^\\s)]+)\\s*\\))?"));
    const QRegularExpressionMatch match = pattern.match(text);
    return {match.captured(1), match.captured(2), match.captured(3)};
}

/// The versions of @p names installed on the node (dpkg-query, one run for all).
QHash<QString, QString> installedVersions(const QStringList &names)
{
    QHash<QString, QString> versions;
    if (names.isEmpty())
        return versions;
    // A name dpkg does not know makes dpkg-query fail, yet it still prints the others.
    const ToolResult result
        = runTool(QStringLiteral("dpkg-query"),
                  QStringList {QStringLiteral("-W"), QStringLiteral("-f"),
                               QStringLiteral("${Package} ${Status} ${Version}\\n")}
                      + names);
    for (const QString &line : QString::fromUtf8(result.out).split(QLatin1Char('\n'))) {
        const QStringList parts = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        // "<name> install ok installed <version>"
        if (parts.size() == 5 && parts.at(3) == QLatin1String("installed"))
            versions.insert(parts.at(0), parts.at(4));
    }
    return versions;
}

bool satisfiedBy(const Requirement &requirement, const PackageStore &store,
                 const QHash<QString, QString> &system)
{
    for (const InstalledPackage &package : store.versions(requirement.name)) {
        if (versionSatisfies(package.version, requirement.relation, requirement.version))
            return true;
    }
    const auto it = system.constFind(requirement.name);
    return it != system.cend() && versionSatisfies(*it, requirement.relation, requirement.version);
}

} // namespace

bool versionSatisfies(const QString &version, const QString &relation, const QString &wanted)
{
    if (relation.isEmpty())
        return true;
    const int order = compareVersions(version, wanted);
    if (relation == QLatin1String("<<") || relation == QLatin1String("<"))
        return order < 0;
    if (relation == QLatin1String("<="))
        return order <= 0;
    if (relation == QLatin1String("="))
        return order == 0;
    if (relation == QLatin1String(">="))
        return order >= 0;
    return order > 0;
}

QStringList unmetDependencies(const QString &depends, const PackageStore &store)
{
    QList<QList<Requirement>> groups;
    QStringList texts;
    QStringList names;
    for (const QString &entry : depends.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        QList<Requirement> alternatives;
        for (const QString &alternative : entry.split(QLatin1Char('|'))) {
            alternatives << parseRequirement(alternative);
            names << alternatives.last().name;
        }
        groups << alternatives;
        texts << entry.simplified();
    }
    names.removeDuplicates();
    names.removeAll(QString());
    const QHash<QString, QString> system = installedVersions(names);
    QStringList unmet;
    for (qsizetype i = 0; i < groups.size(); ++i) {
        const QList<Requirement> &alternatives = groups.at(i);
        const bool met
            = std::any_of(alternatives.cbegin(), alternatives.cend(),
                          [&](const Requirement &r) { return satisfiedBy(r, store, system); });
        if (!met)
            unmet << texts.at(i);
    }
    return unmet;
}

} // namespace Packages
