// SPDX-License-Identifier: MIT
#pragma once

#include "document.h"
#include "rtsprofile.h"

namespace SystemEditor {
class SystemModel;
}

namespace Studio {

/**
 * An open RTS Profile (a system). Owns the System Editor's editing model
 * (SystemEditor::SystemModel), which holds the profile and the RTC profiles of its components;
 * every change goes through the model, and the document re-announces what its views need.
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
    const Profile::RtsProfile &profile() const;
    /// The editing model; System Editor views and commands work on it.
    SystemEditor::SystemModel *model() const { return m_model; }
    QByteArray serialize(Profile::FileFormat format) const override;

    QString systemId() const { return profile().id; }
    void setSystemId(const QString &id);
    std::optional<QString> abstract() const { return profile().abstract; }
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
    /// Components or connectors were added, removed, renamed or changed.
    void systemChanged();

protected:
    /// Saves through the System Editor: known RTC profiles are copied to `RTCs/` beside the
    /// file, and the update date is stamped when the system was edited since the last save.
    bool writeFiles(const QString &path, Profile::FileFormat format,
                    Profile::Diagnostics *diagnostics) override;

private:
    void resolveComponentProfiles();

    SystemEditor::SystemModel *m_model;
};

} // namespace Studio
