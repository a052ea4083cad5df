// SPDX-License-Identifier: MIT
#pragma once

#include "document.h"
#include "rtcprofile.h"

namespace Studio {

/**
 * An open RTC Profile (a component, as RTC Builder edits it). Holds the profile value; its setters
 * are the only way the application changes it, and each announces the change.
 */
class RtcDocument : public Document
{
    Q_OBJECT

public:
    /// The fields of the Builder's "Basic" page.
    enum class BasicField {
        Name,
        Description,
        Version,
        Vendor,
        Category,
        ComponentType,
        ActivityType,
        MaxInstances,
        ExecutionType,
        ExecutionRate,
    };
    Q_ENUM(BasicField)

    explicit RtcDocument(Profile::RtcProfile profile, QObject *parent = nullptr);

    Profile::ProfileKind kind() const override { return Profile::ProfileKind::Rtc; }
    const Profile::RtcProfile &profile() const { return m_profile; }
    QByteArray serialize(Profile::FileFormat format) const override;

    /// The field's value; nothing when an optional attribute is absent.
    std::optional<QString> basicField(BasicField field) const;
    /// Sets a field; for a required field an absent value is stored as empty text.
    void setBasicField(BasicField field, const std::optional<QString> &value);

    /// The component id (`RTC:vendor:category:name:version`).
    QString componentId() const { return m_profile.id; }
    void setComponentId(const QString &id);

    /// Optional in the schema (description, max instances, execution rate).
    static bool isOptional(BasicField field);
    /// Part of the component id (name, vendor, category, version).
    static bool isIdPart(BasicField field);
    /// The user-visible name of a field, e.g. "execution rate".
    static QString fieldLabel(BasicField field);
    /// The id `profile` gets when `field` is set to `value` and its id follows its basic info;
    /// an id that does not follow the basic info (hand-edited files) is left as it is.
    static QString idAfterEdit(const Profile::RtcProfile &profile, BasicField field,
                               const QString &value);

signals:
    void basicFieldChanged(Studio::RtcDocument::BasicField field);
    void componentIdChanged(const QString &id);

private:
    Profile::RtcProfile m_profile;
};

} // namespace Studio
