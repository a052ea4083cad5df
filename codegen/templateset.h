// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QMap>
#include <QString>

#include <optional>

namespace Codegen {

/// One line of a manifest: which template renders to which output path.
struct TemplateEntry
{
    QString templateName; ///< file name inside the template folder
    /// Output path relative to the project folder, itself a mustache template (`src/{{name}}.cpp`).
    QString outputPattern;
    /// Name of a list in the render context: the entry renders once per item, with the item's
    /// keys laid over the context. Empty: render once.
    QString forEach;

    bool operator==(const TemplateEntry &other) const;
    bool operator!=(const TemplateEntry &other) const { return !(*this == other); }
};

/**
 * The templates of one folder (`common`, `cpp`, `python`, `java`): its manifest and the text of
 * every template it names.
 *
 * Built-ins are the Qt resources of the `rttemplates` library (`:/rtstudio/templates/<key>/`).
 * A user template folder overrides them: `<userFolder>/<key>/manifest.json` replaces the
 * manifest, and any `<userFolder>/<key>/<template>` replaces that template.
 *
 * manifest.json: `{"files": [{"template": "a.mustache", "output": "src/{{name}}.cpp",
 * "forEach": "providedIdls"}]}` (forEach optional).
 */
class TemplateSet
{
public:
    /// The resource folder of the built-in templates.
    static QString builtinRoot();

    /// Loads the set `key`; nothing plus a message in `error` when the manifest or a template is
    /// missing or malformed. `userFolder` may be empty.
    static std::optional<TemplateSet> load(const QString &key, const QString &userFolder,
                                           QString *error);

    QString key() const { return m_key; }
    const QList<TemplateEntry> &entries() const { return m_entries; }
    /// The text of a template named in the manifest (empty for unknown names).
    QString templateText(const QString &templateName) const;
    /// Where a template was read from (resource or user file), for messages.
    QString templateOrigin(const QString &templateName) const;

private:
    QString m_key;
    QList<TemplateEntry> m_entries;
    QMap<QString, QString> m_texts;
    QMap<QString, QString> m_origins;
};

} // namespace Codegen
