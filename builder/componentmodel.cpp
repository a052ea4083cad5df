// SPDX-License-Identifier: MIT
#include "componentmodel.h"

#include <QCoreApplication>

namespace Builder {

namespace {

using Profile::RtcBasicInfo;

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Builder::ComponentModel)
};

/// The model member behind a required field; null for the optional ones.
QString *requiredMember(RtcBasicInfo &info, BasicField field)
{
    switch (field) {
    case BasicField::Name:
        return &info.name;
    case BasicField::Version:
        return &info.version;
    case BasicField::Vendor:
        return &info.vendor;
    case BasicField::Category:
        return &info.category;
    case BasicField::ComponentType:
        return &info.componentType;
    case BasicField::ActivityType:
        return &info.activityType;
    case BasicField::ExecutionType:
        return &info.executionType;
    case BasicField::ComponentKind:
        return &info.componentKind;
    case BasicField::Description:
    case BasicField::MaxInstances:
    case BasicField::ExecutionRate:
    case BasicField::Abstract:
    case BasicField::RtcType:
        break;
    }
    return nullptr;
}

std::optional<QString> *optionalMember(RtcBasicInfo &info, BasicField field)
{
    switch (field) {
    case BasicField::Description:
        return &info.description;
    case BasicField::MaxInstances:
        return &info.maxInstances;
    case BasicField::ExecutionRate:
        return &info.executionRate;
    case BasicField::Abstract:
        return &info.abstractText;
    case BasicField::RtcType:
        return &info.rtcType;
    default:
        break;
    }
    return nullptr;
}

/// The profile's list behind a part, as the element type T.
template<typename T> QList<T> &listOf(Profile::RtcProfile &profile);
template<> QList<Profile::RtcDataPort> &listOf(Profile::RtcProfile &profile)
{
    return profile.dataPorts;
}
template<> QList<Profile::RtcServicePort> &listOf(Profile::RtcProfile &profile)
{
    return profile.servicePorts;
}
template<> QList<Profile::RtcConfiguration> &listOf(Profile::RtcProfile &profile)
{
    return profile.configurations;
}

/// Calls `f(list)` with the profile's list of `part`.
template<typename F> auto withList(Profile::RtcProfile &profile, Part part, F &&f)
{
    switch (part) {
    case Part::DataPort:
        return f(listOf<Profile::RtcDataPort>(profile));
    case Part::ServicePort:
        return f(listOf<Profile::RtcServicePort>(profile));
    case Part::Configuration:
        break;
    }
    return f(listOf<Profile::RtcConfiguration>(profile));
}

template<typename T> using Element = typename std::decay_t<T>::value_type;

} // namespace

ComponentModel::ComponentModel(Profile::RtcProfile profile, QObject *parent)
    : QObject(parent)
    , m_profile(std::move(profile))
{ }

void ComponentModel::setProfile(const Profile::RtcProfile &profile)
{
    if (m_profile == profile)
        return;
    emit profileAboutToBeReset();
    m_profile = profile;
    emit profileReset();
    emit changed();
}

std::optional<QString> ComponentModel::basicField(BasicField field) const
{
    // The member lookups need a mutable object; reading through them changes nothing.
    auto &info = const_cast<RtcBasicInfo &>(m_profile.basicInfo);
    if (QString *member = requiredMember(info, field))
        return *member;
    return *optionalMember(info, field);
}

void ComponentModel::setBasicField(BasicField field, const std::optional<QString> &value)
{
    if (basicField(field) == value)
        return;
    if (QString *member = requiredMember(m_profile.basicInfo, field))
        *member = value.value_or(QString());
    else
        *optionalMember(m_profile.basicInfo, field) = value;
    emit basicFieldChanged(field);
    emit changed();
}

void ComponentModel::setComponentId(const QString &id)
{
    if (m_profile.id == id)
        return;
    m_profile.id = id;
    emit componentIdChanged(id);
    emit changed();
}

bool ComponentModel::isOptional(BasicField field)
{
    return field == BasicField::Description || field == BasicField::MaxInstances
        || field == BasicField::ExecutionRate || field == BasicField::Abstract
        || field == BasicField::RtcType;
}

bool ComponentModel::isIdPart(BasicField field)
{
    return field == BasicField::Name || field == BasicField::Vendor || field == BasicField::Category
        || field == BasicField::Version;
}

QString ComponentModel::fieldLabel(BasicField field)
{
    switch (field) {
    case BasicField::Name:
        return Text::tr("component name");
    case BasicField::Description:
        return Text::tr("description");
    case BasicField::Version:
        return Text::tr("version");
    case BasicField::Vendor:
        return Text::tr("vendor");
    case BasicField::Category:
        return Text::tr("category");
    case BasicField::ComponentType:
        return Text::tr("component type");
    case BasicField::ActivityType:
        return Text::tr("activity type");
    case BasicField::MaxInstances:
        return Text::tr("max instances");
    case BasicField::ExecutionType:
        return Text::tr("execution type");
    case BasicField::ComponentKind:
        return Text::tr("component kind");
    case BasicField::Abstract:
        return Text::tr("abstract");
    case BasicField::RtcType:
        return Text::tr("RTC type");
    case BasicField::ExecutionRate:
        break;
    }
    return Text::tr("execution rate");
}

QString ComponentModel::idAfterEdit(const Profile::RtcProfile &profile, BasicField field,
                                    const QString &value)
{
    if (!isIdPart(field) || profile.id != profile.idFromBasicInfo())
        return profile.id;
    const RtcBasicInfo &info = profile.basicInfo;
    Profile::RtcComponentId parts {info.vendor, info.category, info.name, info.version};
    QString *part = field == BasicField::Name ? &parts.name
        : field == BasicField::Vendor         ? &parts.vendor
        : field == BasicField::Category       ? &parts.category
                                              : &parts.version;
    *part = value;
    return parts.toString();
}

std::optional<Profile::RtcActionStatus> ComponentModel::action(Profile::RtcAction action) const
{
    return m_profile.actions[action];
}

void ComponentModel::setAction(Profile::RtcAction action,
                               const std::optional<Profile::RtcActionStatus> &status)
{
    if (m_profile.actions[action] == status)
        return;
    m_profile.actions[action] = status;
    emit actionChanged(action);
    emit changed();
}

void ComponentModel::setComponentDoc(const std::optional<Profile::RtcBasicDoc> &doc)
{
    if (m_profile.basicInfo.doc == doc)
        return;
    m_profile.basicInfo.doc = doc;
    emit componentDocChanged();
    emit changed();
}

void ComponentModel::setLanguage(const std::optional<Profile::RtcLanguage> &language)
{
    if (m_profile.language == language)
        return;
    m_profile.language = language;
    emit languageChanged();
    emit changed();
}

int ComponentModel::itemCount(Part part) const
{
    auto &profile = const_cast<Profile::RtcProfile &>(m_profile);
    return withList(profile, part, [](auto &list) { return int(list.size()); });
}

PartItem ComponentModel::item(Part part, int index) const
{
    auto &profile = const_cast<Profile::RtcProfile &>(m_profile);
    return withList(profile, part, [index](auto &list) { return PartItem(list.at(index)); });
}

QString ComponentModel::itemName(Part part, int index) const
{
    auto &profile = const_cast<Profile::RtcProfile &>(m_profile);
    return withList(profile, part, [index](auto &list) {
        return index >= 0 && index < list.size() ? list.at(index).name : QString();
    });
}

int ComponentModel::indexOf(Part part, const QString &name) const
{
    for (int i = 0; i < itemCount(part); ++i) {
        if (itemName(part, i) == name)
            return i;
    }
    return -1;
}

void ComponentModel::insertItem(Part part, int index, const PartItem &item)
{
    const int at = qBound(0, index, itemCount(part));
    emit itemAboutToBeInserted(part, at);
    withList(m_profile, part, [&](auto &list) {
        list.insert(at, std::get<Element<decltype(list)>>(item));
        return 0;
    });
    emit itemInserted(part, at, itemName(part, at));
    emit changed();
}

void ComponentModel::removeItem(Part part, int index)
{
    if (index < 0 || index >= itemCount(part))
        return;
    const QString name = itemName(part, index);
    emit itemAboutToBeRemoved(part, index, name);
    withList(m_profile, part, [index](auto &list) {
        list.removeAt(index);
        return 0;
    });
    emit itemRemoved(part, index, name);
    emit changed();
}

void ComponentModel::setItem(Part part, int index, const PartItem &item)
{
    if (index < 0 || index >= itemCount(part) || this->item(part, index) == item)
        return;
    const QString oldName = itemName(part, index);
    withList(m_profile, part, [&](auto &list) {
        list[index] = std::get<Element<decltype(list)>>(item);
        return 0;
    });
    emit itemChanged(part, index, oldName, itemName(part, index));
    emit changed();
}

void ComponentModel::moveItem(Part part, int from, int to)
{
    const int count = itemCount(part);
    if (from == to || from < 0 || to < 0 || from >= count || to >= count)
        return;
    emit itemAboutToBeMoved(part, from, to);
    withList(m_profile, part, [from, to](auto &list) {
        list.move(from, to);
        return 0;
    });
    emit itemMoved(part, from, to, itemName(part, to));
    emit changed();
}

QString partLabel(Part part)
{
    switch (part) {
    case Part::DataPort:
        return Text::tr("data port");
    case Part::ServicePort:
        return Text::tr("service port");
    case Part::Configuration:
        break;
    }
    return Text::tr("configuration parameter");
}

} // namespace Builder
