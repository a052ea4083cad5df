// SPDX-License-Identifier: MIT
#include "repositoryindex.h"

#include "debnames.h"
#include "packagetool.h"

#include <QCryptographicHash>
#include <QFile>
#include <QLocale>

#include <algorithm>

namespace Packages {

QString IndexEntry::key() const
{
    return QStringLiteral("%1 %2 %3").arg(package(), version(), architecture());
}

std::optional<IndexEntry> readDebEntry(const QString &debFile, const QString &poolPath,
                                       QString *error)
{
    const ToolResult fields = runTool(QStringLiteral("dpkg-deb"), {QStringLiteral("-f"), debFile});
    if (!fields.ok()) {
        *error = QStringLiteral("%1: not a Debian package: %2")
                     .arg(debFile, fields.failure(QStringLiteral("dpkg-deb")));
        return std::nullopt;
    }
    QString reason;
    std::optional<DebControl> control = DebControl::parse(fields.out, &reason);
    if (!control) {
        *error = QStringLiteral("%1: unreadable control data: %2").arg(debFile, reason);
        return std::nullopt;
    }
    for (const char *field : {"Package", "Version", "Architecture"}) {
        if (control->value(QLatin1String(field)).isEmpty()) {
            *error = QStringLiteral("%1: the control data has no %2")
                         .arg(debFile, QLatin1String(field));
            return std::nullopt;
        }
    }
    QFile file(debFile);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: cannot read").arg(debFile);
        return std::nullopt;
    }
    QCryptographicHash md5(QCryptographicHash::Md5);
    QCryptographicHash sha256(QCryptographicHash::Sha256);
    while (!file.atEnd()) {
        const QByteArray block = file.read(1 << 20);
        md5.addData(block);
        sha256.addData(block);
    }
    IndexEntry entry {*control};
    entry.control.set(QStringLiteral("Filename"), poolPath);
    entry.control.set(QStringLiteral("Size"), QString::number(file.size()));
    entry.control.set(QStringLiteral("MD5sum"), QString::fromLatin1(md5.result().toHex()));
    entry.control.set(QStringLiteral("SHA256"), QString::fromLatin1(sha256.result().toHex()));
    // The Description goes last, as in Debian's own indexes.
    const QString description = entry.control.value(QStringLiteral("Description"));
    if (!description.isEmpty()) {
        entry.control.remove(QStringLiteral("Description"));
        entry.control.set(QStringLiteral("Description"), description);
    }
    return entry;
}

QString poolPath(const QString &component, const IndexEntry &entry)
{
    const QString name = entry.package();
    // Debian's pool splits lib* packages by their first four letters.
    const QString prefix
        = name.startsWith(QLatin1String("lib")) && name.size() > 3 ? name.left(4) : name.left(1);
    return QStringLiteral("pool/%1/%2/%3/%3_%4_%5.deb")
        .arg(component, prefix, name, versionInFileName(entry.version()), entry.architecture());
}

QByteArray packagesText(const QList<IndexEntry> &entries, const QString &architecture)
{
    QList<IndexEntry> selected;
    for (const IndexEntry &entry : entries) {
        if (entry.architecture() == architecture || entry.architecture() == QLatin1String("all"))
            selected << entry;
    }
    std::sort(selected.begin(), selected.end(), [](const IndexEntry &a, const IndexEntry &b) {
        if (a.package() != b.package())
            return a.package() < b.package();
        return compareVersions(a.version(), b.version()) < 0;
    });
    QByteArray text;
    for (const IndexEntry &entry : selected) {
        if (!text.isEmpty())
            text += '\n';
        text += entry.control.toText();
    }
    return text;
}

namespace {

std::optional<QByteArray> compress(const QString &program, const QByteArray &data, QString *error)
{
    ToolRun run;
    run.input = data;
    const ToolResult result
        = runTool(program, {QStringLiteral("-9"), QStringLiteral("-n"), QStringLiteral("-c")}, run);
    if (!result.ok()) {
        *error = result.failure(program);
        return std::nullopt;
    }
    return result.out;
}

} // namespace

std::optional<QList<IndexFile>> packagesFiles(const QList<IndexEntry> &entries,
                                              const ReleaseInfo &info, QString *error)
{
    QList<IndexFile> files;
    const bool xz = haveTool(QStringLiteral("xz"));
    for (const QString &architecture : info.architectures) {
        const QString folder = QStringLiteral("%1/binary-%2/").arg(info.component, architecture);
        const QByteArray text = packagesText(entries, architecture);
        files << IndexFile {folder + QStringLiteral("Packages"), text};
        const std::optional<QByteArray> gz = compress(QStringLiteral("gzip"), text, error);
        if (!gz)
            return std::nullopt;
        files << IndexFile {folder + QStringLiteral("Packages.gz"), *gz};
        if (xz) {
            // xz has no -n; its output carries no name or time anyway.
            ToolRun run;
            run.input = text;
            const ToolResult result = runTool(QStringLiteral("xz"), {QStringLiteral("-c")}, run);
            if (!result.ok()) {
                *error = result.failure(QStringLiteral("xz"));
                return std::nullopt;
            }
            files << IndexFile {folder + QStringLiteral("Packages.xz"), result.out};
        }
    }
    return files;
}

QByteArray releaseText(const ReleaseInfo &info, const QList<IndexFile> &files)
{
    DebControl release;
    if (!info.origin.isEmpty())
        release.set(QStringLiteral("Origin"), info.origin);
    if (!info.label.isEmpty())
        release.set(QStringLiteral("Label"), info.label);
    release.set(QStringLiteral("Suite"), info.suite);
    release.set(QStringLiteral("Codename"), info.codename.isEmpty() ? info.suite : info.codename);
    const QDateTime date
        = info.date.isValid() ? info.date.toUTC() : QDateTime::currentDateTimeUtc();
    release.set(QStringLiteral("Date"),
                QLocale::c().toString(date, QStringLiteral("ddd, dd MMM yyyy HH:mm:ss"))
                    + QStringLiteral(" UTC"));
    release.set(QStringLiteral("Architectures"), info.architectures.join(QLatin1Char(' ')));
    release.set(QStringLiteral("Components"), info.component);
    if (!info.description.isEmpty())
        release.set(QStringLiteral("Description"), info.description);
    QString md5;
    QString sha256;
    for (const IndexFile &file : files) {
        const QString size = QString::number(file.data.size()).rightJustified(10);
        md5 += QStringLiteral("\n %1 %2 %3")
                   .arg(QString::fromLatin1(
                            QCryptographicHash::hash(file.data, QCryptographicHash::Md5).toHex()),
                        size, file.path);
        sha256
            += QStringLiteral("\n %1 %2 %3")
                   .arg(
                       QString::fromLatin1(
                           QCryptographicHash::hash(file.data, QCryptographicHash::Sha256).toHex()),
                       size, file.path);
    }
    release.set(QStringLiteral("MD5Sum"), md5);
    release.set(QStringLiteral("SHA256"), sha256);
    return release.toText();
}

} // namespace Packages
