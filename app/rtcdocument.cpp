// SPDX-License-Identifier: MIT
#include "rtcdocument.h"

namespace Studio {

namespace {

using Field = RtcDocument::BasicField;

/// The model member behind a required field; null for the optional ones.
QString *requiredMember(Profile::RtcBasicInfo &info, Field field)
{
    switch (field) {
    case Field::Name:
        return &info.name;
    case Field::Version:
        return &info.version;
    case Field::Vendor:
        return &info.vendor;
    case Field::Category:
        return &info.category;
    case Field::ComponentType:
        return &info.componentType;
    case Field::ActivityType:
        return &info.activityType;
    case Field::ExecutionType:
        return &info.executionType;
    case Field::Description:
    case Field::MaxInstances:
    case Field::ExecutionRate:
        break;
    }
    return nullptr;
}

std::optional<QString> *optionalMember(Profile::RtcBasicInfo &info, Field field)
{
    switch (field) {
    case Field::Description:
        return &info.description;
    case Field::MaxInstances:
        return &info.maxInstances;
    case Field::ExecutionRate:
        return &info.executionRate;
    default:
        break;
    }
    return nullptr;
}

} // namespace

RtcDocument::RtcDocument(Profile::RtcProfile profile, QObject *parent)
    : Document(parent)
    , m_profile(std::move(profile))
{ }

QByteArray RtcDocument::serialize(Profile::FileFormat format) const
{
    return Profile::serializeRtcProfile(m_profile, format);
}

std::optional<QString> RtcDocument::basicField(BasicField field) const
{
    // The member lookups need a mutable object; reading through them changes nothing.
    auto &info = const_cast<Profile::RtcBasicInfo &>(m_profile.basicInfo);
    if (QString *member = requiredMember(info, field))
        return *member;
    return *optionalMember(info, field);
}

void RtcDocument::setBasicField(BasicField field, const std::optional<QString> &value)
{
    if (basicField(field) == value)
        return;
    if (QString *member = requiredMember(m_profile.basicInfo, field))
        *member = value.value_or(QString());
    else
        *optionalMember(m_profile.basicInfo, field) = value;
    emit basicFieldChanged(field);
}

void RtcDocument::setComponentId(const QString &id)
{
    if (m_profile.id == id)
        return;
    m_profile.id = id;
    emit componentIdChanged(id);
}

bool RtcDocument::isOptional(BasicField field)
{
    return field == Field::Description || field == Field::MaxInstances
        || field == Field::ExecutionRate;
}

bool RtcDocument::isIdPart(BasicField field)
{
    return field == Field::Name || field == Field::Vendor || field == Field::Category
        || field == Field::Version;
}

QString RtcDocument::fieldLabel(BasicField field)
{
    switch (field) {
    case Field::Name:
        return tr("component name");
    case Field::Description:
        return tr("description");
    case Field::Version:
        return tr("version");
    case Field::Vendor:
        return tr("vendor");
    case Field::Category:
        return tr("category");
    case Field::ComponentType:
        return tr("component type");
    case Field::ActivityType:
        return tr("activity type");
    case Field::MaxInstances:
        return tr("max instances");
    case Field::ExecutionType:
        return tr("execution type");
    case Field::ExecutionRate:
        break;
    }
    return tr("execution rate");
}

QString RtcDocument::idAfterEdit(const Profile::RtcProfile &profile, BasicField field,
                                 const QString &value)
{
    if (!isIdPart(field) || profile.id != profile.idFromBasicInfo())
        return profile.id;
    const Profile::RtcBasicInfo &info = profile.basicInfo;
    Profile::RtcComponentId parts {info.vendor, info.category, info.name, info.version};
    QString *part = field == Field::Name ? &parts.name
        : field == Field::Vendor         ? &parts.vendor
        : field == Field::Category       ? &parts.category
                                         : &parts.version;
    *part = value;
    return parts.toString();
}

} // namespace Studio
