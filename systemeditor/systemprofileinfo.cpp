// SPDX-License-Identifier: MIT
#include "systemprofileinfo.h"

#include "rtsprofile.h"

#include <QCoreApplication>

namespace SystemEditor {

QString SystemProfileInfo::systemId() const
{
    return QStringLiteral("RTSystem:%1:%2:%3").arg(vendor, systemName, version);
}

SystemProfileInfo SystemProfileInfo::fromProfile(const Profile::RtsProfile &profile)
{
    SystemProfileInfo info;
    // Like the reference's dialog, take vendor and version from both ends so that a name holding
    // ':' survives; a malformed id leaves the parts empty for the user to fill in.
    const QStringList parts = profile.id.split(QLatin1Char(':'));
    if (parts.size() >= 4 && parts.first() == QLatin1String("RTSystem")) {
        info.vendor = parts.at(1);
        info.version = parts.last();
        info.systemName = parts.mid(2, parts.size() - 3).join(QLatin1Char(':'));
    }
    info.abstract = profile.abstract;
    info.creationDate = profile.creationDate;
    info.updateDate = profile.updateDate;
    for (const Profile::RtsComponent &component : profile.components) {
        if (component.isRequiredValue())
            info.requiredComponents.insert(component.instanceName);
    }
    return info;
}

void SystemProfileInfo::applyTo(Profile::RtsProfile &profile) const
{
    profile.id = systemId();
    profile.abstract = abstract;
    profile.creationDate = creationDate;
    profile.updateDate = updateDate;
    for (Profile::RtsComponent &component : profile.components) {
        const bool required = requiredComponents.contains(component.instanceName);
        // Keep the file's spelling when the meaning does not change (lossless round trips).
        if (required != component.isRequiredValue())
            component.isRequired = required ? QStringLiteral("true") : QStringLiteral("false");
    }
}

QStringList SystemProfileInfo::problems() const
{
    QStringList result;
    const auto check = [&result](const QString &value, const char *label) {
        const QString what = QCoreApplication::translate("SystemProfileInfo", label);
        if (value.trimmed().isEmpty())
            result << QCoreApplication::translate("SystemProfileInfo", "The %1 is empty.").arg(what);
        else if (value.contains(QLatin1Char(':')))
            result << QCoreApplication::translate("SystemProfileInfo", "The %1 must not contain ':'.")
                          .arg(what);
    };
    check(vendor, QT_TRANSLATE_NOOP("SystemProfileInfo", "vendor"));
    check(systemName, QT_TRANSLATE_NOOP("SystemProfileInfo", "system name"));
    check(version, QT_TRANSLATE_NOOP("SystemProfileInfo", "version"));
    return result;
}

bool SystemProfileInfo::operator==(const SystemProfileInfo &other) const
{
    return vendor == other.vendor && systemName == other.systemName && version == other.version
        && abstract == other.abstract && creationDate == other.creationDate
        && updateDate == other.updateDate && requiredComponents == other.requiredComponents;
}

} // namespace SystemEditor
