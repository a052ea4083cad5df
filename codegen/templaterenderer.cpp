// SPDX-License-Identifier: MIT
#include "templaterenderer.h"

#include <QRegularExpression>
#include <QVariantList>

#include <kainjow/mustache.hpp>

namespace Codegen {

namespace {

namespace mustache = kainjow::mustache;

mustache::data toData(const QVariant &value);

mustache::data toData(const QVariantMap &map)
{
    mustache::data object{mustache::data::type::object};
    for (auto it = map.cbegin(); it != map.cend(); ++it)
        object.set(it.key().toStdString(), toData(it.value()));
    return object;
}

mustache::data toData(const QVariantList &values)
{
    mustache::data list{mustache::data::type::list};
    for (const QVariant &value : values)
        list.push_back(toData(value));
    return list;
}

mustache::data toData(const QVariant &value)
{
    switch (value.typeId()) {
    case QMetaType::QVariantMap:
        return toData(value.toMap());
    case QMetaType::QVariantList:
        return toData(value.toList());
    case QMetaType::QStringList: {
        mustache::data list{mustache::data::type::list};
        for (const QString &text : value.toStringList())
            list.push_back(mustache::data{text.toStdString()});
        return list;
    }
    case QMetaType::Bool:
        return mustache::data{value.toBool()};
    default:
        return mustache::data{value.toString().toStdString()};
    }
}

/// Mustache's "standalone" rule done before rendering: a line holding nothing but one section,
/// inverted-section, end or comment tag disappears with its newline. kainjow applies the rule
/// itself only in some places and leaves blank lines behind sections nested in lists.
QString joinStandaloneTags(const QString &text)
{
    static const QRegularExpression standalone(
        QStringLiteral("^[ \\t]*(\\{\\{[#^/!][^}]*\\}\\})[ \\t]*\\r?\\n"),
        QRegularExpression::MultilineOption);
    QString result = text;
    return result.replace(standalone, QStringLiteral("\\1"));
}

} // namespace

std::optional<QString> renderTemplate(const QString &templateText, const QVariantMap &context,
                                      QString *error)
{
    mustache::mustache engine{joinStandaloneTags(templateText).toStdString()};
    if (!engine.is_valid()) {
        if (error)
            *error = QString::fromStdString(engine.error_message());
        return std::nullopt;
    }
    // Generated files are source code, not HTML: `<` and `&` must stay as they are.
    engine.set_custom_escape([](const std::string &text) { return text; });
    return QString::fromStdString(engine.render(toData(context)));
}

} // namespace Codegen
