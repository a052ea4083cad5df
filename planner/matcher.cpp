// SPDX-License-Identifier: MIT
#include "matcher.h"

#include <QCoreApplication>
#include <QVersionNumber>

namespace Planner {

namespace {

/// What the planner says of a fact the node does not publish (translated when it is shown).
QString unknown()
{
    return QCoreApplication::translate("Planner", "unknown");
}

QString known(const std::optional<QString> &value)
{
    return value.value_or(unknown());
}

/// Language names as profiles and managers spell them (C++, cxx, Python3) folded onto one.
QString canonicalLanguage(const QString &name)
{
    QString lower = name.trimmed().toLower().remove(QLatin1Char(' '));
    if (lower == QLatin1String("cxx") || lower == QLatin1String("cpp"))
        return QStringLiteral("c++");
    if (lower.startsWith(QLatin1String("python")))
        return QStringLiteral("python");
    return lower;
}

bool startsWithAny(const std::optional<QString> &text, const QStringList &prefixes)
{
    if (!text)
        return false;
    for (const QString &prefix : prefixes) {
        if (text->startsWith(prefix, Qt::CaseInsensitive))
            return true;
    }
    return false;
}

bool hostsLanguage(const NodeFacts &node, const QString &language)
{
    if (!node.languages)
        return false;
    for (const QString &hosted : *node.languages) {
        if (canonicalLanguage(hosted) == canonicalLanguage(language))
            return true;
    }
    return false;
}

bool hasFact(const NodeFacts &node, const QString &fact, const QString &value)
{
    const auto it = node.userFacts.constFind(fact);
    return it != node.userFacts.constEnd() && (*it == value || splitFactList(*it).contains(value));
}

void checkPlatform(const ComponentRequirements &c, const NodeFacts &node, QList<Mismatch> *out)
{
    if (!c.oses.isEmpty() && !(node.os && c.oses.contains(*node.os, Qt::CaseInsensitive)))
        out->append(
            {QCoreApplication::translate("Planner", "OS %1").arg(c.oses.join(QStringLiteral(" or "))), known(node.os)});
    if (!c.osVersions.isEmpty() && !startsWithAny(node.distribution, c.osVersions)
        && !startsWithAny(node.osRelease, c.osVersions))
        out->append({QCoreApplication::translate("Planner", "OS version %1").arg(c.osVersions.join(QStringLiteral(" or "))),
                     node.distribution.value_or(known(node.osRelease))});
    bool archOk = c.architectures.isEmpty();
    for (const QString &arch : c.architectures)
        archOk = archOk
            || (node.architecture
                && canonicalArchitecture(arch) == canonicalArchitecture(*node.architecture));
    if (!archOk)
        out->append(
            {QCoreApplication::translate("Planner", "architecture %1").arg(c.architectures.join(QStringLiteral(" or "))),
             known(node.architecture)});
}

void checkUserFacts(const ComponentRequirements &c, const NodeFacts &node, QList<Mismatch> *out)
{
    const QStringList devices = node.devices();
    for (const QString &device : c.devices) {
        if (!devices.contains(device))
            out->append({QCoreApplication::translate("Planner", "device %1").arg(device),
                         devices.isEmpty() ? QCoreApplication::translate("Planner", "no devices listed")
                                           : devices.join(QLatin1Char(','))});
    }
    for (auto it = c.nodeFacts.constBegin(); it != c.nodeFacts.constEnd(); ++it) {
        if (!hasFact(node, it.key(), it.value()))
            out->append({QCoreApplication::translate("Planner", "node.%1 = %2").arg(it.key(), it.value()),
                         node.userFacts.value(it.key(), unknown())});
    }
}

void checkPlacement(const ComponentRequirements &c, const NodeFacts &node, QList<Mismatch> *out)
{
    if (!c.pinnedNode.isEmpty() && c.pinnedNode != node.name && c.pinnedNode != node.hostname)
        out->append({QCoreApplication::translate("Planner", "pinned to %1").arg(c.pinnedNode),
                     QCoreApplication::translate("Planner", "the name %1").arg(node.name)});
    if (c.cpuShare > 0) {
        const std::optional<double> free = node.freeCpus();
        if (!free || *free < c.cpuShare)
            out->append({QCoreApplication::translate("Planner", "CPU share %1").arg(c.cpuShare),
                         free ? QCoreApplication::translate("Planner", "%1 free").arg(*free) : unknown()});
    }
}

} // namespace

Matcher::Matcher(QList<RepositoryPackage> packages)
    : m_packages(std::move(packages))
{ }

bool Matcher::packageFits(const RepositoryPackage &package, const NodeFacts &node) const
{
    const bool archOk = package.architecture == QLatin1String("all")
        || (node.architecture
            && canonicalArchitecture(package.architecture)
                == canonicalArchitecture(*node.architecture));
    const bool abiOk = package.sdkAbi.isEmpty() || (node.sdkAbi && *node.sdkAbi == package.sdkAbi);
    return archOk && abiOk;
}

Matcher::TypeSource Matcher::typeSource(const QString &typeName, const NodeFacts &node) const
{
    TypeSource source;
    if (node.loadableTypes && node.loadableTypes->contains(typeName)) {
        source.loadable = true;
        return source;
    }
    for (const RepositoryPackage &package : m_packages) {
        if (!package.types.contains(typeName) || !packageFits(package, node))
            continue;
        if (!source.package
            || QVersionNumber::fromString(package.version)
                > QVersionNumber::fromString(source.package->version))
            source.package = &package;
    }
    return source;
}

QList<Mismatch> Matcher::mismatches(const ComponentRequirements &c, const NodeFacts &node) const
{
    QList<Mismatch> out;
    checkPlacement(c, node, &out);
    checkPlatform(c, node, &out);
    const TypeSource source = typeSource(c.typeName, node);
    // A node that loads the type already hosts its language, whatever it publishes.
    if (!c.language.isEmpty() && !source.loadable && !hostsLanguage(node, c.language))
        out.append({QCoreApplication::translate("Planner", "language %1").arg(c.language),
                    node.languages ? node.languages->join(QLatin1Char(',')) : unknown()});
    checkUserFacts(c, node, &out);
    if (!source.available())
        out.append({QCoreApplication::translate("Planner", "type %1 loadable or installable").arg(c.typeName),
                    QCoreApplication::translate("Planner", "no such type, no package for its architecture (%1) and SDK")
                        .arg(known(node.architecture))});
    return out;
}

} // namespace Planner
