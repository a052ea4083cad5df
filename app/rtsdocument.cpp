// SPDX-License-Identifier: MIT
#include "rtsdocument.h"

#include "systemfile.h"
#include "systemmodel.h"

#include <QCoreApplication>
#include <QUndoStack>

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
    , m_model(new SystemEditor::SystemModel(std::move(profile), this))
{
    using SystemEditor::SystemModel;
    connect(m_model, &SystemModel::systemInfoChanged, this, &RtsDocument::systemInfoChanged);
    for (auto signal : {&SystemModel::componentAdded, &SystemModel::componentRemoved,
                        &SystemModel::componentChanged, &SystemModel::connectorAdded,
                        &SystemModel::connectorRemoved, &SystemModel::connectorChanged})
        connect(m_model, signal, this, &RtsDocument::systemChanged);
    connect(m_model, &SystemModel::componentRenamed, this, &RtsDocument::systemChanged);
    connect(m_model, &SystemModel::reset, this, &RtsDocument::systemChanged);
    // Relative pathUris mean something only once the document knows its file.
    connect(this, &Document::filePathChanged, this, &RtsDocument::resolveComponentProfiles);
}

const Profile::RtsProfile &RtsDocument::profile() const
{
    return m_model->profile();
}

QByteArray RtsDocument::serialize(Profile::FileFormat format) const
{
    return Profile::serializeRtsProfile(profile(), format);
}

void RtsDocument::setSystemId(const QString &id)
{
    m_model->setSystemId(id);
}

void RtsDocument::setAbstract(const std::optional<QString> &abstract)
{
    m_model->setAbstract(abstract);
}

bool RtsDocument::writeFiles(const QString &path, Profile::FileFormat format,
                             Profile::Diagnostics *diagnostics)
{
    SystemEditor::SaveOptions options;
    options.format = format;
    // An unedited system saves as it was read, dates included.
    options.stampDates = isModified();
    return SystemEditor::saveSystemFile(*m_model, path, diagnostics, options);
}

void RtsDocument::resolveComponentProfiles()
{
    // Components whose RTC profile is already known (e.g. dropped from the repository) keep it.
    Profile::Diagnostics warnings;
    const QHash<QString, Profile::RtcProfile> found =
        SystemEditor::resolveRtcProfiles(profile(), filePath(), &warnings);
    for (auto it = found.cbegin(); it != found.cend(); ++it) {
        if (!m_model->rtcProfile(it.key()))
            m_model->setRtcProfile(it.key(), it.value());
    }
}

QString RtsDocument::systemField(SystemField field) const
{
    if (field == SystemField::Abstract)
        return profile().abstract.value_or(QString());
    const std::optional<QStringList> parts = idParts(profile().id);
    return parts ? parts->at(partIndex(field)) : QString();
}

bool RtsDocument::hasWellFormedId() const
{
    return idParts(profile().id).has_value();
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
