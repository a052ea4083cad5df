// SPDX-License-Identifier: MIT
#include "rtsdocument.h"

#include <QCoreApplication>

namespace Studio {

namespace {

/// Vendor, name and version of an id. Unlike RtsSystemId::parse() this accepts empty parts, so
/// that clearing a field while typing does not make the other two disappear; a name holding ':'
/// is tolerated by taking vendor and version from both ends.
std::optional<QStringList> idParts(const QString &id)
{
    QStringList parts = id.split(QLatin1Char(':'));
    if (parts.size() < 4 || parts.first() != QLatin1String("RTSystem"))
        return std::nullopt;
    const QString vendor = parts.at(1);
    const QString version = parts.last();
    const QString name = parts.mid(2, parts.size() - 3).join(QLatin1Char(':'));
    return QStringList {vendor, name, version};
}

int partIndex(RtsDocument::SystemField field)
{
    switch (field) {
    case RtsDocument::SystemField::Vendor:
        return 0;
    case RtsDocument::SystemField::Name:
        return 1;
    case RtsDocument::SystemField::Version:
        return 2;
    case RtsDocument::SystemField::Abstract:
        break;
    }
    return -1;
}

} // namespace

RtsDocument::RtsDocument(Profile::RtsProfile profile, QObject *parent)
    : Document(parent)
    , m_profile(std::move(profile))
{ }

QByteArray RtsDocument::serialize(Profile::FileFormat format) const
{
    return Profile::serializeRtsProfile(m_profile, format);
}

void RtsDocument::setSystemId(const QString &id)
{
    if (m_profile.id == id)
        return;
    m_profile.id = id;
    emit systemInfoChanged();
}

void RtsDocument::setAbstract(const std::optional<QString> &abstract)
{
    if (m_profile.abstract == abstract)
        return;
    m_profile.abstract = abstract;
    emit systemInfoChanged();
}

QString RtsDocument::systemField(SystemField field) const
{
    if (field == SystemField::Abstract)
        return m_profile.abstract.value_or(QString());
    const std::optional<QStringList> parts = idParts(m_profile.id);
    return parts ? parts->at(partIndex(field)) : QString();
}

bool RtsDocument::hasWellFormedId() const
{
    return idParts(m_profile.id).has_value();
}

QString RtsDocument::idWithField(const QString &id, SystemField field, const QString &value)
{
    const int index = partIndex(field);
    if (index < 0)
        return id;
    QStringList parts = idParts(id).value_or(QStringList {QString(), QString(), QString()});
    parts[index] = value;
    return QStringLiteral("RTSystem:%1:%2:%3").arg(parts.at(0), parts.at(1), parts.at(2));
}

QString RtsDocument::fieldLabel(SystemField field)
{
    switch (field) {
    case SystemField::Vendor:
        return tr("vendor");
    case SystemField::Name:
        return tr("system name");
    case SystemField::Version:
        return tr("version");
    case SystemField::Abstract:
        break;
    }
    return tr("abstract");
}

} // namespace Studio
