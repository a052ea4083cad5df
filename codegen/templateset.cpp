// SPDX-License-Identifier: MIT
#include "templateset.h"

#include "builtintemplates.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace Codegen {

namespace {

const QString ManifestName = QStringLiteral("manifest.json");

/// The user's file when there is one, else the built-in resource.
QString pickFile(const QString &key, const QString &userFolder, const QString &name)
{
    if (!userFolder.isEmpty()) {
        const QString user = QDir(userFolder).filePath(key + QLatin1Char('/') + name);
        if (QFile::exists(user))
            return user;
    }
    return TemplateSet::builtinRoot() + key + QLatin1Char('/') + name;
}

std::optional<QString> readText(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: cannot read template: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    return QString::fromUtf8(file.readAll());
}

// A template name must stay inside its folder: the manifest may come from a user folder.
bool isPlainName(const QString &name)
{
    return !name.isEmpty() && !name.contains(QLatin1Char('/')) && !name.contains(QLatin1Char('\\'))
        && name != QLatin1String("..") && name != QLatin1String(".");
}

std::optional<QList<TemplateEntry>> parseManifest(const QString &path, const QByteArray &json,
                                                  QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !document.isObject()) {
        *error = QStringLiteral("%1: not a JSON object: %2").arg(path, parseError.errorString());
        return std::nullopt;
    }
    QList<TemplateEntry> entries;
    const QJsonArray files = document.object().value(QStringLiteral("files")).toArray();
    for (const QJsonValue &value : files) {
        const QJsonObject object = value.toObject();
        TemplateEntry entry;
        entry.templateName = object.value(QStringLiteral("template")).toString();
        entry.outputPattern = object.value(QStringLiteral("output")).toString();
        entry.forEach = object.value(QStringLiteral("forEach")).toString();
        if (!isPlainName(entry.templateName) || entry.outputPattern.isEmpty()) {
            *error = QStringLiteral("%1: entry %2 needs a plain \"template\" name and an \"output\"")
                         .arg(path)
                         .arg(entries.size() + 1);
            return std::nullopt;
        }
        entries.append(entry);
    }
    return entries;
}

} // namespace

bool TemplateEntry::operator==(const TemplateEntry &other) const
{
    return templateName == other.templateName && outputPattern == other.outputPattern
        && forEach == other.forEach;
}

QString TemplateSet::builtinRoot()
{
    return Templates::builtinRoot();
}

std::optional<TemplateSet> TemplateSet::load(const QString &key, const QString &userFolder,
                                             QString *error)
{
    QString message;
    const QString manifestPath = pickFile(key, userFolder, ManifestName);
    const std::optional<QString> manifest = readText(manifestPath, &message);
    std::optional<QList<TemplateEntry>> entries;
    if (manifest)
        entries = parseManifest(manifestPath, manifest->toUtf8(), &message);
    if (!entries) {
        if (error)
            *error = message;
        return std::nullopt;
    }
    TemplateSet set;
    set.m_key = key;
    set.m_entries = *entries;
    for (const TemplateEntry &entry : std::as_const(set.m_entries)) {
        if (set.m_texts.contains(entry.templateName))
            continue;
        const QString path = pickFile(key, userFolder, entry.templateName);
        const std::optional<QString> text = readText(path, &message);
        if (!text) {
            if (error)
                *error = message;
            return std::nullopt;
        }
        set.m_texts.insert(entry.templateName, *text);
        set.m_origins.insert(entry.templateName, path);
    }
    return set;
}

QString TemplateSet::templateText(const QString &templateName) const
{
    return m_texts.value(templateName);
}

QString TemplateSet::templateOrigin(const QString &templateName) const
{
    return m_origins.value(templateName);
}

} // namespace Codegen
