// SPDX-License-Identifier: MIT
#include "systemfile.h"

#include "systemmodel.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QUrl>

namespace SystemEditor {

using namespace Profile;

namespace {

const QString ComponentPathProperty = QStringLiteral("COMPONENT_PATH_ID");
const QString RtcFolder = QStringLiteral("RTCs");

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SystemEditor::SystemFile)
};

Diagnostic fileProblem(const QString &file, Diagnostic::Severity severity,
                       const QString &message)
{
    return severity == Diagnostic::Severity::Error ? Diagnostic::error(file, 0, 0, message)
                                                   : Diagnostic::warning(file, 0, 0, message);
}

void repointEnd(RtsTargetPort &end, const QHash<QString, QString> &newPaths)
{
    const auto it = newPaths.constFind(end.instanceName);
    if (it == newPaths.constEnd())
        return;
    // Only ends that carried the path get the new one; others stay as the file had them.
    for (RtsProperty &property : end.properties) {
        if (property.name == ComponentPathProperty)
            property.value = it.value();
    }
}

} // namespace

QString resolvePathUri(const QString &pathUri, const QString &systemFilePath)
{
    if (pathUri.trimmed().isEmpty())
        return {};
    QString local;
    if (pathUri.startsWith(QLatin1String("file:"), Qt::CaseInsensitive)) {
        local = QUrl(pathUri).toLocalFile();
    } else if (QDir::isAbsolutePath(pathUri)) {
        local = pathUri;
    } else {
        local = QFileInfo(systemFilePath).absoluteDir().filePath(pathUri);
    }
    const QFileInfo info(local);
    return info.isFile() ? info.absoluteFilePath() : QString();
}

QHash<QString, RtcProfile> resolveRtcProfiles(const RtsProfile &profile,
                                              const QString &systemFilePath,
                                              Diagnostics *warnings, QHash<QString, QString> *files)
{
    QHash<QString, RtcProfile> result;
    for (const RtsComponent &component : profile.components) {
        const QString file = resolvePathUri(component.pathUri, systemFilePath);
        if (file.isEmpty())
            continue;
        Diagnostics problems;
        const std::optional<LoadedProfile> loaded = loadProfileFile(file, &problems);
        if (!loaded || !loaded->rtc) {
            if (warnings) {
                warnings->append(fileProblem(
                    systemFilePath, Diagnostic::Severity::Warning,
                    Text::tr("The RTC profile of %1 (%2) could not be read; its ports come from the "
                       "system file.")
                        .arg(component.instanceName, component.pathUri)));
                for (Diagnostic d : problems) {
                    d.severity = Diagnostic::Severity::Warning;
                    warnings->append(d);
                }
            }
            continue;
        }
        result.insert(component.instanceName, *loaded->rtc);
        if (files)
            files->insert(component.instanceName, file);
    }
    return result;
}

std::optional<LoadedSystem> loadSystemFile(const QString &path, Diagnostics *diagnostics)
{
    Diagnostics problems;
    std::optional<LoadedProfile> loaded = loadProfileFile(path, &problems);
    if (!loaded || !loaded->rts) {
        if (loaded && !loaded->rts)
            problems.append(fileProblem(path, Diagnostic::Severity::Error,
                                        Text::tr("The file is no RT system profile.")));
        if (diagnostics)
            diagnostics->append(problems);
        return std::nullopt;
    }
    LoadedSystem system;
    system.profile = std::move(*loaded->rts);
    system.format = loaded->format;
    system.warnings = loaded->diagnostics;
    system.rtcProfiles =
        resolveRtcProfiles(system.profile, path, &system.warnings, &system.rtcFiles);
    if (diagnostics)
        diagnostics->append(system.warnings);
    return system;
}

RtsProfile profileForSave(const SystemModel &model, const SaveOptions &options)
{
    RtsProfile profile = model.profile();
    if (options.stampDates) {
        profile.updateDate = RtsProfile::currentDateTimeText();
        if (profile.creationDate.isEmpty())
            profile.creationDate = profile.updateDate;
    }
    if (profile.version.isEmpty())
        profile.version = RtsProfile::CurrentVersion;
    if (!options.copyRtcProfiles)
        return profile;
    QHash<QString, QString> newPaths;
    for (RtsComponent &component : profile.components) {
        if (!model.rtcProfile(component.instanceName))
            continue;
        component.pathUri = RtcFolder + QLatin1Char('/') + component.instanceName
            + QStringLiteral(".xml");
        newPaths.insert(component.instanceName, component.pathUri);
    }
    for (RtsDataPortConnector &c : profile.dataPortConnectors) {
        repointEnd(c.source, newPaths);
        repointEnd(c.target, newPaths);
    }
    for (RtsServicePortConnector &c : profile.servicePortConnectors) {
        repointEnd(c.source, newPaths);
        repointEnd(c.target, newPaths);
    }
    return profile;
}

bool saveSystemFile(SystemModel &model, const QString &path, Diagnostics *diagnostics,
                    const SaveOptions &options)
{
    const RtsProfile profile = profileForSave(model, options);
    const QDir folder = QFileInfo(path).absoluteDir();
    if (options.copyRtcProfiles) {
        for (const RtsComponent &component : profile.components) {
            const RtcProfile *rtc = model.rtcProfile(component.instanceName);
            if (!rtc)
                continue;
            if (!folder.mkpath(RtcFolder)) {
                if (diagnostics)
                    diagnostics->append(fileProblem(folder.filePath(RtcFolder), Diagnostic::Severity::Error,
                                                    Text::tr("Cannot create the folder.")));
                return false;
            }
            if (!saveRtcProfileFile(*rtc, folder.filePath(component.pathUri), diagnostics))
                return false;
        }
    }
    const FileFormat format = options.format.value_or(formatForFileName(path));
    if (!writeFileAtomically(path, serializeRtsProfile(profile, format), diagnostics))
        return false;
    model.adoptSavedProfile(profile);
    return true;
}

} // namespace SystemEditor
