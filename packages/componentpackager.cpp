// SPDX-License-Identifier: MIT
#include "componentpackager.h"

#include "debnames.h"
#include "packagetool.h"

#include <profileio.h>
#include <rtcprofile.h>

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <memory>

namespace Packages {

/// Everything one build collects on its way to the .deb.
struct ComponentPackager::Staged
{
    QString projectDir;
    QString buildDir;
    Profile::RtcProfile profile;
    QByteArray profileBytes;
    QString package;
    QString version;
    QString architecture;
    QString multiarch;
    QStringList binaries; ///< built files in the build folder
    QStringList pythonSources;
    std::unique_ptr<QTemporaryDir> work;
    QString root; ///< the package's file tree
    QStringList files;
    QStringList depends;
    QString sdkAbi;
    qint64 installedKiB = 0;
    QStringList warnings;
    DebControl control;
    QString debFile;
};

ComponentPackager::ComponentPackager(PackageOptions options)
    : m_options(std::move(options))
{ }

QString ComponentPackager::libraryFolder(const QString &multiarch, const QString &package)
{
    return QStringLiteral("/usr/lib/%1/rtstudio/components/%2").arg(multiarch, package);
}

QString ComponentPackager::dataFolder(const QString &package)
{
    return QStringLiteral("/usr/share/rtstudio/components/%1").arg(package);
}

QString ComponentPackager::profileId(const Profile::RtcProfile &profile)
{
    if (!profile.id.isEmpty())
        return profile.id;
    const Profile::RtcBasicInfo &info = profile.basicInfo;
    return QStringLiteral("RTC:%1:%2:%3:%4")
        .arg(info.vendor, info.category, info.name, info.version);
}

namespace {

QString firstLine(const ToolResult &result)
{
    return QString::fromLocal8Bit(result.out).trimmed().section(QLatin1Char('\n'), 0, 0);
}

bool isPython(const Profile::RtcProfile &profile)
{
    return profile.language
        && profile.language->kind.compare(QLatin1String("Python"), Qt::CaseInsensitive) == 0;
}

/// Copies @p from to <root>/<to> with @p permissions, creating folders.
bool install(const QString &from, const QString &root, const QString &to,
             QFile::Permissions permissions, QStringList *files, QString *error)
{
    const QString target = root + to;
    QDir().mkpath(QFileInfo(target).absolutePath());
    QFile::remove(target);
    if (!QFile::copy(from, target) || !QFile::setPermissions(target, permissions)) {
        *error = QStringLiteral("cannot copy %1 into the package").arg(from);
        return false;
    }
    *files << to;
    return true;
}

const QFile::Permissions dataPermissions = QFile::ReadOwner | QFile::WriteOwner | QFile::ReadUser
    | QFile::WriteUser | QFile::ReadGroup | QFile::ReadOther;
const QFile::Permissions programPermissions
    = dataPermissions | QFile::ExeOwner | QFile::ExeUser | QFile::ExeGroup | QFile::ExeOther;

/// The Description field: the profile's description as the summary, its documentation below.
QString description(const Profile::RtcProfile &profile, const QString &id)
{
    const Profile::RtcBasicInfo &info = profile.basicInfo;
    QString summary = info.description.value_or(QString()).simplified();
    if (summary.isEmpty())
        summary = QStringLiteral("RT-Component %1").arg(info.name);
    QStringList paragraphs;
    if (info.doc && info.doc->description)
        paragraphs << info.doc->description->trimmed();
    if (info.abstractText)
        paragraphs << info.abstractText->trimmed();
    paragraphs
        << QStringLiteral("RT-Component type %1 (%2), packaged by RT Studio.").arg(info.name, id);
    QString text = summary;
    bool first = true;
    for (const QString &paragraph : paragraphs) {
        if (paragraph.isEmpty() || paragraph.simplified() == summary)
            continue;
        if (!first)
            text += QStringLiteral("\n .");
        first = false;
        for (const QString &line : paragraph.split(QLatin1Char('\n'))) {
            const QString trimmed = line.trimmed();
            text += trimmed.isEmpty() ? QStringLiteral("\n .") : QStringLiteral("\n ") + trimmed;
        }
    }
    return text;
}

} // namespace

std::optional<PackageResult> ComponentPackager::build(QString *error)
{
    Staged staged;
    if (!stage(&staged, error) || !computeDepends(&staged, error))
        return std::nullopt;
    writeControl(&staged);
    if (!buildDeb(&staged, error))
        return std::nullopt;
    PackageResult result;
    result.debFile = staged.debFile;
    result.control = staged.control;
    result.files = staged.files;
    result.files.sort();
    result.warnings = staged.warnings;
    return result;
}

bool ComponentPackager::stage(Staged *staged, QString *error)
{
    return readProfile(staged, error) && findBinaries(staged, error) && copyFiles(staged, error);
}

bool ComponentPackager::readProfile(Staged *staged, QString *error)
{
    staged->projectDir = QDir(m_options.projectDir).absolutePath();
    const QString profilePath = staged->projectDir + QStringLiteral("/RTC.xml");
    if (!QFileInfo(staged->projectDir).isDir()) {
        *error = QStringLiteral("%1: no such project folder").arg(m_options.projectDir);
        return false;
    }
    QFile profileFile(profilePath);
    if (!profileFile.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: no RTC.xml (the component's profile) in the project")
                     .arg(profilePath);
        return false;
    }
    staged->profileBytes = profileFile.readAll();
    Profile::Diagnostics diagnostics;
    const std::optional<Profile::LoadedProfile> loaded
        = Profile::loadProfileFile(profilePath, &diagnostics);
    if (!loaded || !loaded->rtc) {
        *error = QStringLiteral("%1: not a readable RTC Profile").arg(profilePath);
        for (const Profile::Diagnostic &d : diagnostics)
            *error += QLatin1Char('\n') + d.toString();
        return false;
    }
    staged->profile = *loaded->rtc;
    const Profile::RtcBasicInfo &info = staged->profile.basicInfo;
    QString reason;
    std::optional<QString> package = m_options.packageName.isEmpty()
        ? componentPackageName(info.vendor, info.category, info.name, &reason)
        : std::optional<QString>(m_options.packageName);
    if (package && !isValidPackageName(*package)) {
        reason = QStringLiteral("'%1' is not a valid Debian package name").arg(*package);
        package.reset();
    }
    if (!package) {
        *error = QStringLiteral("%1: invalid package name: %2").arg(profilePath, reason);
        return false;
    }
    const std::optional<QString> version = debianVersion(info.version, &reason);
    if (!version) {
        *error = QStringLiteral("%1: invalid version: %2").arg(profilePath, reason);
        return false;
    }
    staged->package = *package;
    staged->version = *version;
    staged->buildDir = m_options.buildDir.isEmpty() ? staged->projectDir + QStringLiteral("/build")
                                                    : QDir(m_options.buildDir).absolutePath();
    return true;
}

bool ComponentPackager::copyFiles(Staged *staged, QString *error)
{
    const QString profilePath = staged->projectDir + QStringLiteral("/RTC.xml");
    staged->work = std::make_unique<QTemporaryDir>();
    if (!staged->work->isValid()) {
        *error = QStringLiteral("cannot create a temporary folder: %1")
                     .arg(staged->work->errorString());
        return false;
    }
    staged->root = staged->work->filePath(QStringLiteral("root"));
    const QString lib = libraryFolder(staged->multiarch, staged->package);
    const QString data = dataFolder(staged->package);
    for (const QString &binary : staged->binaries) {
        if (!install(binary, staged->root, lib + QLatin1Char('/') + QFileInfo(binary).fileName(),
                     programPermissions, &staged->files, error))
            return false;
    }
    for (const QString &source : staged->pythonSources) {
        if (!install(source, staged->root, data + QLatin1Char('/') + QFileInfo(source).fileName(),
                     dataPermissions, &staged->files, error))
            return false;
    }
    if (!install(profilePath, staged->root, data + QStringLiteral("/RTC.xml"), dataPermissions,
                 &staged->files, error))
        return false;
    const QDir project(staged->projectDir);
    for (const QString &conf :
         project.entryList({QStringLiteral("*.conf")}, QDir::Files, QDir::Name)) {
        if (!install(project.filePath(conf), staged->root, data + QLatin1Char('/') + conf,
                     dataPermissions, &staged->files, error))
            return false;
    }
    const QDir idl(project.filePath(QStringLiteral("idl")));
    for (const QString &file : idl.entryList({QStringLiteral("*.idl")}, QDir::Files, QDir::Name)) {
        if (!install(idl.filePath(file), staged->root, data + QStringLiteral("/idl/") + file,
                     dataPermissions, &staged->files, error))
            return false;
    }
    return true;
}

bool ComponentPackager::findBinaries(Staged *staged, QString *error)
{
    const QString name = staged->profile.basicInfo.name;
    if (isPython(staged->profile)) {
        const QString source = staged->projectDir + QLatin1Char('/') + name + QStringLiteral(".py");
        if (!QFileInfo::exists(source)) {
            *error = QStringLiteral("%1: missing (the Python component's module)").arg(source);
            return false;
        }
        staged->pythonSources << source;
        staged->architecture = QStringLiteral("all");
        staged->multiarch = QString();
        return true;
    }
    if (!QFileInfo(staged->buildDir).isDir()) {
        *error
            = QStringLiteral("%1: not built (no build folder; build it first, e.g. rtctl build %2)")
                  .arg(staged->buildDir, m_options.projectDir);
        return false;
    }
    const QStringList wanted {name + QStringLiteral(".so"), name + QStringLiteral("Comp")};
    QHash<QString, QString> found;
    QDirIterator it(staged->buildDir, wanted, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        const QString file = QFileInfo(path).fileName();
        // The first one found in the build folder's order; CMake puts both in one folder.
        if (!found.contains(file)
            && (file.endsWith(QLatin1String(".so")) || QFileInfo(path).isExecutable()))
            found.insert(file, path);
    }
    for (const QString &file : wanted) {
        if (found.contains(file))
            staged->binaries << found.value(file);
    }
    if (staged->binaries.isEmpty()) {
        *error = QStringLiteral(
                     "%1: not built (neither %2 nor %3 found; build it first, e.g. rtctl build %4)")
                     .arg(staged->buildDir, wanted.at(0), wanted.at(1), m_options.projectDir);
        return false;
    }
    const ToolResult arch
        = runTool(QStringLiteral("dpkg"), {QStringLiteral("--print-architecture")});
    const ToolResult multiarch
        = runTool(QStringLiteral("dpkg-architecture"), {QStringLiteral("-qDEB_HOST_MULTIARCH")});
    if (!arch.ok() || !multiarch.ok()) {
        *error = !arch.ok() ? arch.failure(QStringLiteral("dpkg --print-architecture"))
                            : multiarch.failure(QStringLiteral("dpkg-architecture"));
        return false;
    }
    staged->architecture = firstLine(arch);
    staged->multiarch = firstLine(multiarch);
    return true;
}

namespace {

/// Runs dpkg-shlibdeps on @p binaries in @p work; the Depends entries, and in @p unpackaged the
/// libraries they link that come from no Debian package.
std::optional<QStringList> shlibsDepends(const QStringList &binaries, const QString &package,
                                         const QString &work, QStringList *unpackaged,
                                         QString *error)
{
    // dpkg-shlibdeps reads a debian/control of a source package; a minimal one will do.
    const QString source = work + QStringLiteral("/source");
    QDir().mkpath(source + QStringLiteral("/debian"));
    QFile control(source + QStringLiteral("/debian/control"));
    const QByteArray text = "Source: " + package.toUtf8() + "\n\nPackage: " + package.toUtf8()
        + "\nArchitecture: any\n";
    if (!control.open(QIODevice::WriteOnly) || control.write(text) != text.size()) {
        *error = QStringLiteral("cannot write %1").arg(control.fileName());
        return std::nullopt;
    }
    control.close();
    // -v names the libraries that come from no package, which --ignore-missing-info passes over
    // in silence.
    QStringList arguments {QStringLiteral("-v"), QStringLiteral("-O"),
                           QStringLiteral("--ignore-missing-info")};
    for (const QString &binary : binaries)
        arguments << QStringLiteral("-e") + binary;
    const ToolResult result
        = runTool(QStringLiteral("dpkg-shlibdeps"), arguments, {source, {}, {}, 120000});
    if (!result.ok()) {
        *error = result.failure(QStringLiteral("dpkg-shlibdeps"));
        return std::nullopt;
    }
    QStringList depends;
    static const QRegularExpression noInfo(QStringLiteral(
        "(?:No associated package found for|no dependency information found for|cannot find "
        "library) (\\S+)"));
    // dpkg-shlibdeps writes its debug lines to standard output, its warnings to standard error.
    for (const QString &line :
         QString::fromUtf8(result.out + result.err).split(QLatin1Char('\n'))) {
        if (line.startsWith(QLatin1String("shlibs:Depends=")))
            depends << line.mid(15).split(QStringLiteral(", "), Qt::SkipEmptyParts);
        const QRegularExpressionMatch m = noInfo.match(line);
        const QString library = QFileInfo(m.captured(1)).fileName();
        if (m.hasMatch() && !unpackaged->contains(library))
            *unpackaged << library;
    }
    for (const QString &binary : binaries)
        unpackaged->removeAll(QFileInfo(binary).fileName());
    return depends;
}

/// The SONAME of the SDK library @p binaries link, or an empty string.
QString sdkAbi(const QStringList &binaries)
{
    static const QRegularExpression needed(
        QStringLiteral("NEEDED\\s+(librtstudio_rtm\\.so\\.\\S+)"));
    for (const QString &binary : binaries) {
        const ToolResult dump = runTool(QStringLiteral("objdump"), {QStringLiteral("-p"), binary});
        const QRegularExpressionMatch m = needed.match(QString::fromUtf8(dump.out));
        if (m.hasMatch())
            return m.captured(1);
    }
    return {};
}

/// Other component packages the profile names as its target environments' libraries.
QStringList profileDepends(const Profile::RtcProfile &profile, QStringList *warnings)
{
    QStringList depends;
    if (!profile.language)
        return depends;
    for (const Profile::RtcTargetEnvironment &target : profile.language->targets) {
        for (const Profile::RtcLibrary &library : target.libraries) {
            if (!isValidPackageName(library.name)) {
                *warnings << QStringLiteral("library '%1' of the profile is not a Debian package "
                                            "name: not in Depends")
                                 .arg(library.name);
                continue;
            }
            const QString version = library.version.value_or(QString()).trimmed();
            depends << (isValidVersion(version)
                            ? QStringLiteral("%1 (>= %2)").arg(library.name, version)
                            : library.name);
        }
    }
    return depends;
}

} // namespace

bool ComponentPackager::computeDepends(Staged *staged, QString *error)
{
    QStringList depends;
    if (!staged->binaries.isEmpty()) {
        QStringList unpackaged;
        const std::optional<QStringList> shlibs = shlibsDepends(
            staged->binaries, staged->package, staged->work->path(), &unpackaged, error);
        if (!shlibs)
            return false;
        depends = *shlibs;
        // The SDK library the component links: its SONAME is the ABI the component needs.
        staged->sdkAbi = sdkAbi(staged->binaries);
        for (const QString &library : unpackaged) {
            const bool sdk = library == staged->sdkAbi;
            staged->warnings << QStringLiteral(
                                    "%1 comes from no Debian package: left out of Depends%2")
                                    .arg(library,
                                         sdk ? QStringLiteral(" (%1 names it)").arg(Field::SdkAbi)
                                             : QString());
        }
        if (staged->sdkAbi.isEmpty())
            staged->warnings
                << QStringLiteral(
                       "the component does not link the RT Studio SDK library: no %1 field")
                       .arg(Field::SdkAbi);
    }
    depends << profileDepends(staged->profile, &staged->warnings) << m_options.depends;
    depends.removeDuplicates();
    staged->depends = depends;
    return true;
}

void ComponentPackager::writeControl(Staged *staged)
{
    const Profile::RtcBasicInfo &info = staged->profile.basicInfo;
    qint64 bytes = 0;
    for (const QString &file : staged->files)
        bytes += (QFileInfo(staged->root + file).size() + 1023) / 1024;
    QString maintainer = m_options.maintainer;
    if (maintainer.isEmpty()) {
        QString who = info.doc && info.doc->creator ? info.doc->creator->simplified() : QString();
        if (who.isEmpty())
            who = info.vendor.simplified();
        if (who.isEmpty())
            who = QStringLiteral("Unknown");
        // Debian wants "Name <address>"; a profile rarely has an address, and .invalid says so.
        maintainer = who.contains(QLatin1Char('<'))
            ? who
            : QStringLiteral("%1 <unknown@invalid>").arg(who);
    }
    const QString id = profileId(staged->profile);
    DebControl &c = staged->control;
    c.set(QStringLiteral("Package"), staged->package);
    c.set(QStringLiteral("Version"), staged->version);
    c.set(QStringLiteral("Architecture"), staged->architecture);
    c.set(QStringLiteral("Maintainer"), maintainer);
    c.set(QStringLiteral("Installed-Size"), QString::number(bytes));
    if (!staged->depends.isEmpty())
        c.set(QStringLiteral("Depends"), staged->depends.join(QStringLiteral(", ")));
    c.set(QStringLiteral("Section"), QStringLiteral("misc"));
    c.set(QStringLiteral("Priority"), QStringLiteral("optional"));
    c.set(Field::RtcTypes, info.name);
    c.set(Field::RtcProfileId, id);
    c.set(Field::RtcProfileSha256,
          QString::fromLatin1(
              QCryptographicHash::hash(staged->profileBytes, QCryptographicHash::Sha256).toHex()));
    if (!staged->sdkAbi.isEmpty())
        c.set(Field::SdkAbi, staged->sdkAbi);
    c.set(QStringLiteral("Description"), description(staged->profile, id));
}

bool ComponentPackager::buildDeb(Staged *staged, QString *error)
{
    const QString debian = staged->root + QStringLiteral("/DEBIAN");
    QDir().mkpath(debian);
    QFile control(debian + QStringLiteral("/control"));
    QFile md5sums(debian + QStringLiteral("/md5sums"));
    QByteArray sums;
    for (const QString &file : staged->files) {
        QFile f(staged->root + file);
        if (!f.open(QIODevice::ReadOnly)) {
            *error = QStringLiteral("cannot read %1").arg(f.fileName());
            return false;
        }
        sums += QCryptographicHash::hash(f.readAll(), QCryptographicHash::Md5).toHex() + "  "
            + file.mid(1).toUtf8() + '\n';
    }
    if (!control.open(QIODevice::WriteOnly) || control.write(staged->control.toText()) < 0
        || !md5sums.open(QIODevice::WriteOnly) || md5sums.write(sums) < 0) {
        *error = QStringLiteral("cannot write %1").arg(debian);
        return false;
    }
    control.close();
    md5sums.close();
    // Folders as dpkg expects them: 0755 all the way down.
    QDirIterator dirs(staged->root, QDir::Dirs | QDir::NoDotAndDotDot,
                      QDirIterator::Subdirectories);
    QFile::setPermissions(staged->root, programPermissions);
    while (dirs.hasNext())
        QFile::setPermissions(dirs.next(), programPermissions);

    const QString fileName
        = QStringLiteral("%1_%2_%3.deb")
              .arg(staged->package, versionInFileName(staged->version), staged->architecture);
    QString target = m_options.output.isEmpty() ? QDir::currentPath() : m_options.output;
    if (!target.endsWith(QLatin1String(".deb"))) {
        if (!QDir().mkpath(target)) {
            *error = QStringLiteral("%1: cannot create the output folder").arg(target);
            return false;
        }
        target = QDir(target).filePath(fileName);
    }
    target = QFileInfo(target).absoluteFilePath();
    // Built beside the target and renamed: a failed build leaves no partial .deb.
    const QString partial = target + QStringLiteral(".partial");
    const ToolResult result = runTool(
        QStringLiteral("dpkg-deb"),
        {QStringLiteral("--root-owner-group"), QStringLiteral("--build"), staged->root, partial});
    if (!result.ok()) {
        QFile::remove(partial);
        *error = result.failure(QStringLiteral("dpkg-deb --build"));
        return false;
    }
    QFile::remove(target);
    if (!QFile::rename(partial, target)) {
        QFile::remove(partial);
        *error = QStringLiteral("%1: cannot write the package").arg(target);
        return false;
    }
    staged->debFile = target;
    return true;
}

} // namespace Packages
