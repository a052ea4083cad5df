// SPDX-License-Identifier: MIT
// Maps an XmlNode tree onto RtsProfile. Legacy spellings of the reference tools are accepted here
// and never written back (the writer produces the schema form).
#include "rtsfields_p.h"
#include "rtsxml.h"

#include <QCoreApplication>

#include <algorithm>

namespace Profile {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtsXml", text);
}

/// Longer attribute values are refused: no real system needs them and a GUI would choke on them.
constexpr qsizetype MaxAttributeLength = 256 * 1024;

QString rtsName(const char *name)
{
    return QString::fromLatin1(name);
}

class RtsXmlReader
{
public:
    RtsXmlReader(const QString &fileName, Diagnostics *diagnostics)
        : m_fileName(fileName)
        , m_diagnostics(diagnostics)
    { }

    std::optional<RtsProfile> read(const XmlNode &root)
    {
        if (!checkRoot(root) || !checkSizes(root))
            return std::nullopt;
        return readElement<RtsProfile>(root);
    }

private:
    NodeReader reader(const XmlNode &node) { return NodeReader(node, m_fileName, m_diagnostics); }

    void error(const SourceLocation &where, const QString &message)
    {
        if (m_diagnostics)
            m_diagnostics->append(Diagnostic::error(m_fileName, where.line, where.column, message));
    }

    bool checkRoot(const XmlNode &root)
    {
        if (root.is(Ns::Rts, rtsName("RtsProfile")))
            return true;
        if (root.name == QLatin1String("RtsProfile")) {
            error(root.location,
                  tr("the root element <RtsProfile> is in namespace '%1', expected '%2'")
                      .arg(root.namespaceUri, Ns::Rts));
        } else {
            const QString shown
                = root.prefix.isEmpty() ? root.name : root.prefix + QLatin1Char(':') + root.name;
            error(root.location,
                  tr("not an RTS Profile: the root element is <%1>, expected <rts:RtsProfile>")
                      .arg(shown));
        }
        return false;
    }

    bool checkSizes(const XmlNode &node)
    {
        for (const XmlAttribute &a : node.attributes) {
            if (a.value.size() > MaxAttributeLength) {
                error(node.location,
                      tr("the value of attribute '%1' on <%2> is %3 characters long "
                         "(at most %4 are accepted)")
                          .arg(a.name, node.name)
                          .arg(a.value.size())
                          .arg(MaxAttributeLength));
                return false;
            }
        }
        for (const XmlNode &child : node.children) {
            if (!checkSizes(child))
                return false;
        }
        return true;
    }

    template<typename T> void finish(T &item, const NodeReader &r)
    {
        item.extras = r.extras();
        item.location = r.location();
        // XmlExtras has no place for character data; say so rather than drop it silently.
        if (!r.node().text.trimmed().isEmpty())
            r.warn(tr("text inside <%1> is not part of an RTS Profile and is not kept")
                       .arg(r.node().name));
    }

    /// Attributes first, then child elements, each in table order (the order of diagnostics).
    template<typename T> T readElement(const XmlNode &node)
    {
        NodeReader r = reader(node);
        T item;
        const auto &fields = Fields::RtsElement<T>::fields;
        Fields::forEachXmlRow(fields, [&](const auto &row) { readAttribute(r, item, row); });
        Fields::forEachXmlRow(fields, [&](const auto &row) { readChildren(r, item, row); });
        finish(item, r);
        return item;
    }

    template<typename T, typename Owner, typename Value>
    void readAttribute(NodeReader &r, T &item, const Fields::Scalar<Owner, Value> &row)
    {
        const QString name = rtsName(row.xmlName);
        QStringList legacy;
        if (row.xmlLegacyName)
            legacy.append(rtsName(row.xmlLegacyName));
        Value value;
        if constexpr (Fields::Scalar<Owner, Value>::required)
            value = r.required(*row.xmlNamespace, name, legacy);
        else
            value = r.attribute(*row.xmlNamespace, name, legacy);
        if (row.normalize)
            value = normalized(value, row.normalize);
        item.*row.member = value;
    }
    template<typename T, typename Row> void readAttribute(NodeReader &, T &, const Row &) { }

    static QString normalized(const QString &text, QString (*normalize)(const QString &))
    {
        return normalize(text);
    }
    static std::optional<QString> normalized(const std::optional<QString> &text,
                                             QString (*normalize)(const QString &))
    {
        return text ? std::optional<QString>(normalize(*text)) : std::nullopt;
    }

    template<typename T, typename Owner, typename Value>
    void readChildren(NodeReader &, T &, const Fields::Scalar<Owner, Value> &)
    { }

    template<typename T, typename Owner, typename Item>
    void readChildren(NodeReader &r, T &item, const Fields::Child<Owner, QList<Item>> &row)
    {
        QList<Item> &result = item.*row.member;
        const auto nodes = r.children(*row.xmlNamespace, rtsName(row.xmlName));
        result.reserve(qsizetype(nodes.size()));
        for (const XmlNode *node : nodes)
            result.append(readElement<Item>(*node));
    }

    template<typename T, typename Owner, typename Item>
    void readChildren(NodeReader &r, T &item, const Fields::Child<Owner, std::optional<Item>> &row)
    {
        if (const XmlNode *node = r.child(*row.xmlNamespace, rtsName(row.xmlName)))
            item.*row.member = readElement<Item>(*node);
    }

    template<typename T, typename Owner, typename Item>
    void readChildren(NodeReader &r, T &item, const Fields::Child<Owner, Item> &row)
    {
        const QString name = rtsName(row.xmlName);
        if (const XmlNode *node = r.child(*row.xmlNamespace, name))
            item.*row.member = readElement<Item>(*node);
        else
            r.error(tr("<%1> lacks its <%2> element").arg(r.node().name, name));
    }

    template<typename T, typename Owner>
    void readChildren(NodeReader &r, T &item, const Fields::TextList<Owner> &row)
    {
        std::vector<const XmlNode *> nodes = r.children(*row.xmlNamespace, rtsName(row.xmlName));
        if (row.xmlLegacyName) {
            const auto legacy = r.children(*row.xmlNamespace, rtsName(row.xmlLegacyName));
            nodes.insert(nodes.end(), legacy.begin(), legacy.end());
            // The nodes live in one vector of siblings, so address order is document order.
            std::sort(nodes.begin(), nodes.end());
        }
        for (const XmlNode *node : nodes)
            (item.*row.member).append(node->text);
    }

    QString m_fileName;
    Diagnostics *m_diagnostics;
};

} // namespace

std::optional<RtsProfile> readRtsXml(const QByteArray &data, const QString &fileName,
                                     Diagnostics *diagnostics)
{
    const std::optional<XmlNode> root = parseXml(data, fileName, diagnostics);
    if (!root)
        return std::nullopt;
    return RtsXmlReader(fileName, diagnostics).read(*root);
}

} // namespace Profile
