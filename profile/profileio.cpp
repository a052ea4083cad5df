// SPDX-License-Identifier: MIT
#include "profileio.h"
#include "namespaces.h"
#include "xmlnode.h"
#include "rtcxml.h"
#include "rtcyaml.h"
#include "rtsxml.h"
#include "rtsyaml.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSaveFile>
#include <QXmlStreamReader>

namespace Profile {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::Io", text);
}

/// Profiles are small; anything beyond this is not a profile and is refused before it is read.
constexpr qint64 MaxProfileBytes = 512LL * 1024 * 1024;

ProfileKind kindOfXmlRoot(const QByteArray &data)
{
    QXmlStreamReader reader(data);
    while (!reader.atEnd()) {
        if (reader.readNext() == QXmlStreamReader::StartElement) {
            if (reader.namespaceUri() == Ns::Rtc && reader.name() == QLatin1String("RtcProfile"))
                return ProfileKind::Rtc;
            if (reader.namespaceUri() == Ns::Rts && reader.name() == QLatin1String("RtsProfile"))
                return ProfileKind::Rts;
            return ProfileKind::Unknown;
        }
    }
    return ProfileKind::Unknown;
}

ProfileKind kindOfYamlTopKey(const QByteArray &data)
{
    static const QRegularExpression topKey(
        QStringLiteral(R"(^["']?(rtcProfile|rtsProfile)["']?\s*:)"),
        QRegularExpression::MultilineOption);
    const QRegularExpressionMatch match = topKey.match(QString::fromUtf8(data));
    if (!match.hasMatch())
        return ProfileKind::Unknown;
    return match.captured(1) == QLatin1String("rtcProfile") ? ProfileKind::Rtc : ProfileKind::Rts;
}

/// Says why a file is neither profile kind: its syntax error where it has one, else what its root
/// element is.
void reportUnknownKind(const QByteArray &data, FileFormat format, const QString &fileName,
                       Diagnostics *found)
{
    const QString expected = tr("expected an rtc:RtcProfile or rts:RtsProfile root element, or a "
                                "top-level rtcProfile: or rtsProfile: key");
    if (format == FileFormat::Yaml) {
        found->append(Diagnostic::error(fileName, 1, 1,
                                        tr("not an RTC Profile or RTS Profile (%1)").arg(expected)));
        return;
    }
    const auto root = parseXml(data, fileName, found);
    if (!root)
        return;
    found->append(Diagnostic::error(
        fileName, root->location.line, root->location.column,
        tr("the root element <%1> (namespace \"%2\") is not an RTC Profile or RTS Profile (%3)")
            .arg(root->prefix.isEmpty() ? root->name : root->prefix + QLatin1Char(':') + root->name,
                 root->namespaceUri, expected)));
}

} // namespace

FileFormat formatForFileName(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("yaml") || suffix == QLatin1String("yml") ? FileFormat::Yaml
                                                                               : FileFormat::Xml;
}

FileFormat detectFormat(const QByteArray &data)
{
    for (const char c : data) {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
            continue;
        // A UTF-8 byte order mark may precede the document.
        if (c == '\xef' || c == '\xbb' || c == '\xbf')
            continue;
        return c == '<' ? FileFormat::Xml : FileFormat::Yaml;
    }
    return FileFormat::Xml;
}

ProfileKind detectProfileKind(const QByteArray &data)
{
    return detectFormat(data) == FileFormat::Xml ? kindOfXmlRoot(data) : kindOfYamlTopKey(data);
}

std::optional<LoadedProfile> loadProfileData(const QByteArray &data, const QString &fileName,
                                             Diagnostics *diagnostics)
{
    LoadedProfile loaded;
    loaded.format = detectFormat(data);
    loaded.kind = detectProfileKind(data);
    Diagnostics found;
    const bool xml = loaded.format == FileFormat::Xml;
    switch (loaded.kind) {
    case ProfileKind::Rtc:
        loaded.rtc = xml ? readRtcXml(data, fileName, &found) : readRtcYaml(data, fileName, &found);
        break;
    case ProfileKind::Rts:
        loaded.rts = xml ? readRtsXml(data, fileName, &found) : readRtsYaml(data, fileName, &found);
        break;
    case ProfileKind::Unknown:
        reportUnknownKind(data, loaded.format, fileName, &found);
        break;
    }
    const bool ok = (loaded.rtc || loaded.rts) && !hasErrors(found);
    if (!ok) {
        if (!hasErrors(found))
            found.append(Diagnostic::error(fileName, 0, 0, tr("the profile could not be read")));
        if (diagnostics)
            diagnostics->append(found);
        return std::nullopt;
    }
    loaded.diagnostics = found;
    if (diagnostics)
        diagnostics->append(found);
    return loaded;
}

std::optional<LoadedProfile> loadProfileFile(const QString &path, Diagnostics *diagnostics)
{
    QFile file(path);
    const QFileInfo info(path);
    auto fail = [&](const QString &message) -> std::optional<LoadedProfile> {
        if (diagnostics)
            diagnostics->append(Diagnostic::error(path, 0, 0, message));
        return std::nullopt;
    };
    if (!info.exists())
        return fail(tr("no such file"));
    if (info.isDir())
        return fail(tr("is a folder, not a profile file"));
    if (info.size() > MaxProfileBytes)
        return fail(tr("file is too large to be a profile (%1 bytes)").arg(info.size()));
    if (!file.open(QIODevice::ReadOnly))
        return fail(tr("cannot be read: %1").arg(file.errorString()));
    return loadProfileData(file.readAll(), path, diagnostics);
}

QByteArray serializeRtcProfile(const RtcProfile &profile, FileFormat format)
{
    return format == FileFormat::Yaml ? writeRtcYaml(profile) : writeRtcXml(profile);
}

QByteArray serializeRtsProfile(const RtsProfile &profile, FileFormat format)
{
    return format == FileFormat::Yaml ? writeRtsYaml(profile) : writeRtsXml(profile);
}

bool writeFileAtomically(const QString &path, const QByteArray &data, Diagnostics *diagnostics)
{
    QSaveFile file(path);
    auto fail = [&](const QString &message) {
        if (diagnostics)
            diagnostics->append(Diagnostic::error(path, 0, 0, message));
        return false;
    };
    // Unbuffered, and flushed before the commit: Qt's QSaveFile commits even when its buffered
    // data could not be flushed (a full disk), which would replace the old file with an empty one.
    if (!file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return fail(tr("cannot be written: %1").arg(file.errorString()));
    if (file.write(data) != data.size() || !file.flush()) {
        const QString reason = file.errorString();
        file.cancelWriting();
        return fail(tr("writing failed: %1").arg(reason));
    }
    if (!file.commit())
        return fail(tr("could not be saved: %1").arg(file.errorString()));
    return true;
}

bool saveRtcProfileFile(const RtcProfile &profile, const QString &path, Diagnostics *diagnostics)
{
    return writeFileAtomically(path, serializeRtcProfile(profile, formatForFileName(path)),
                               diagnostics);
}

bool saveRtsProfileFile(const RtsProfile &profile, const QString &path, Diagnostics *diagnostics)
{
    return writeFileAtomically(path, serializeRtsProfile(profile, formatForFileName(path)),
                               diagnostics);
}

} // namespace Profile
