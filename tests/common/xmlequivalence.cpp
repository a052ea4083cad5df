// SPDX-License-Identifier: MIT
#include "xmlequivalence.h"

#include <QStringList>

#include <algorithm>

using Profile::XmlAttribute;
using Profile::XmlNode;

QString XmlNormalization::boolean(const QString &value)
{
    const QString t = value.trimmed().toLower();
    if (t == QLatin1String("1") || t == QLatin1String("true"))
        return QStringLiteral("true");
    if (t == QLatin1String("0") || t == QLatin1String("false"))
        return QStringLiteral("false");
    return value;
}

QString XmlNormalization::number(const QString &value)
{
    bool ok = false;
    const double d = value.trimmed().toDouble(&ok);
    return ok ? QString::number(d, 'g', 17) : value;
}

namespace {

/// A canonical, order-independent text form of an element, used both to sort siblings and to
/// compare them.
struct Canonical
{
    QString name;
    QStringList attributes; // sorted "name=value"
    QString text;
    std::vector<Canonical> children; // sorted by their serialised form
    QString serialized;
};

Canonical canonicalize(const XmlNode &node, const XmlNormalization &n)
{
    Canonical c;
    QString name = XmlNormalization::key(node.namespaceUri, node.name);
    c.name = n.elementRenames.value(name, name);

    QHash<QString, QString> values;
    for (const XmlAttribute &a : node.attributes) {
        QString key = XmlNormalization::key(a.namespaceUri, a.name);
        key = n.attributeRenames.value(key, key);
        QString value = a.value;
        if (const auto normalizer = n.valueNormalizers.value(key))
            value = normalizer(value);
        values.insert(key, value);
    }
    for (auto it = n.defaultedAttributes.cbegin(); it != n.defaultedAttributes.cend(); ++it) {
        // Only attributes of this element's kind are defaulted: the key names "Element@attr".
        const qsizetype at = it.key().indexOf(QLatin1Char('@'));
        if (at < 0 || it.key().left(at) != c.name)
            continue;
        const QString attribute = it.key().mid(at + 1);
        if (!values.contains(attribute)) {
            QString value = it.value();
            if (const auto normalizer = n.valueNormalizers.value(attribute))
                value = normalizer(value);
            values.insert(attribute, value);
        }
    }
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        c.attributes.append(it.key() + QLatin1Char('=') + it.value());
    c.attributes.sort();
    c.text = node.text.trimmed();

    for (const XmlNode &child : node.children) {
        Canonical cc = canonicalize(child, n);
        if (n.dropWhenEmpty.value(cc.name) && cc.attributes.isEmpty() && cc.children.empty()
            && cc.text.isEmpty()) {
            continue;
        }
        c.children.push_back(std::move(cc));
    }
    std::sort(c.children.begin(), c.children.end(),
              [](const Canonical &a, const Canonical &b) { return a.serialized < b.serialized; });

    c.serialized = c.name + QLatin1Char('[') + c.attributes.join(QLatin1Char(' ')) + QLatin1Char(']');
    if (!c.text.isEmpty())
        c.serialized += QLatin1Char('"') + c.text + QLatin1Char('"');
    c.serialized += QLatin1Char('(');
    for (const Canonical &cc : c.children)
        c.serialized += cc.serialized + QLatin1Char(',');
    c.serialized += QLatin1Char(')');
    return c;
}

QString describe(const Canonical &expected, const Canonical &actual, const QString &path)
{
    const QString here = path + QLatin1Char('/') + expected.name;
    if (expected.name != actual.name)
        return QStringLiteral("%1: element %2 became %3").arg(path, expected.name, actual.name);
    if (expected.attributes != actual.attributes) {
        QStringList missing, added;
        for (const QString &a : expected.attributes) {
            if (!actual.attributes.contains(a))
                missing << a;
        }
        for (const QString &a : actual.attributes) {
            if (!expected.attributes.contains(a))
                added << a;
        }
        return QStringLiteral("%1: attributes lost {%2}, gained {%3}")
            .arg(here, missing.join(QStringLiteral(", ")), added.join(QStringLiteral(", ")));
    }
    if (expected.text != actual.text)
        return QStringLiteral("%1: text \"%2\" became \"%3\"").arg(here, expected.text, actual.text);

    // Children: report the first one of either side that has no equal on the other side.
    QStringList actualForms;
    for (const Canonical &c : actual.children)
        actualForms << c.serialized;
    for (const Canonical &c : expected.children) {
        const qsizetype i = actualForms.indexOf(c.serialized);
        if (i >= 0) {
            actualForms.removeAt(i);
            continue;
        }
        // Find a same-named child to explain the difference in depth.
        for (const Canonical &a : actual.children) {
            if (a.name == c.name && !expected.serialized.contains(a.serialized))
                return describe(c, a, here);
        }
        return QStringLiteral("%1: child %2 is missing").arg(here, c.serialized.left(300));
    }
    if (!actualForms.isEmpty())
        return QStringLiteral("%1: unexpected child %2").arg(here, actualForms.first().left(300));
    return {};
}

} // namespace

QString xmlDifference(const XmlNode &expected, const XmlNode &actual,
                      const XmlNormalization &normalization)
{
    const Canonical e = canonicalize(expected, normalization);
    const Canonical a = canonicalize(actual, normalization);
    if (e.serialized == a.serialized)
        return {};
    const QString difference = describe(e, a, QString());
    return difference.isEmpty() ? QStringLiteral("documents differ") : difference;
}
