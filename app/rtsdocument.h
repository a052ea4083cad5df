// SPDX-License-Identifier: MIT
#pragma once

#include "document.h"
#include "rtsprofile.h"

namespace Studio {

/**
 * An open RTS Profile (a system). Holds the profile value; its setters are the only way the
 * application changes it, and each announces the change.
 *
 * The system's vendor, name and version live inside the system id
 * (`RTSystem:vendor:name:version`); systemField() reads them from there and idWithField() builds
 * the id that an edit of one of them produces.
 */
class RtsDocument : public Document
{
    Q_OBJECT

public:
    /// The "system info" fields the System Editor edits.
    enum class SystemField { Vendor, Name, Version, Abstract };
    Q_ENUM(SystemField)

    explicit RtsDocument(Profile::RtsProfile profile, QObject *parent = nullptr);

    Profile::ProfileKind kind() const override { return Profile::ProfileKind::Rts; }
    const Profile::RtsProfile &profile() const { return m_profile; }
    QByteArray serialize(Profile::FileFormat format) const override;

    QString systemId() const { return m_profile.id; }
    void setSystemId(const QString &id);
    std::optional<QString> abstract() const { return m_profile.abstract; }
    void setAbstract(const std::optional<QString> &abstract);

    /// A part of the system id, or the abstract text (empty when absent).
    QString systemField(SystemField field) const;
    /// True when the system id has the form `RTSystem:vendor:name:version`.
    bool hasWellFormedId() const;

    /// `id` with one of its vendor/name/version parts replaced by `value`.
    static QString idWithField(const QString &id, SystemField field, const QString &value);
    /// The user-visible name of a field, e.g. "vendor".
    static QString fieldLabel(SystemField field);

signals:
    /// The id or the abstract changed.
    void systemInfoChanged();

private:
    Profile::RtsProfile m_profile;
};

} // namespace Studio
