// SPDX-License-Identifier: MIT
#include "rtcfields_p.h"
#include "rtcxml.h"
#include "rtcxmlinternal.h"

#include <QCoreApplication>

namespace Profile {

using namespace RtcXml;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcXml", text);
}

QString s(const char *text)
{
    return QString::fromLatin1(text);
}

/// Maps XmlNodes onto the model by walking the field tables (rtcfields_p.h): attributes first,
/// then child elements, each in table order.
class Reader
{
public:
    explicit Reader(const ReadContext &context)
        : m_context(context)
    { }

    template<typename T> T readElement(const XmlNode &node) const
    {
        NodeReader r = reader(node);
        T item;
        item.location = node.location;
        const auto &fields = Fields::RtcElement<T>::fields;
        Fields::forEachXmlRow(fields, [&](const auto &row) { readAttribute(r, item, row); });
        Fields::forEachXmlRow(fields, [&](const auto &row) { readChildren(r, item, row); });
        item.extras = r.extras();
        return item;
    }

private:
    NodeReader reader(const XmlNode &node) const
    {
        return NodeReader(node, m_context.fileName, m_context.diagnostics);
    }

    template<typename T, typename Owner, typename Value>
    void readAttribute(NodeReader &r, T &item, const Fields::Scalar<Owner, Value> &row) const
    {
        const QString name = s(row.xmlName);
        QStringList legacy;
        if (row.xmlLegacyName)
            legacy.append(s(row.xmlLegacyName));
        std::optional<QString> value = r.attribute(*row.xmlNamespace, name, legacy);
        if (!value && row.xmlLegacyNamespace)
            value = r.attribute(*row.xmlLegacyNamespace, s(row.xmlLegacyName));
        if constexpr (Fields::Scalar<Owner, Value>::required) {
            if (!value)
                value = requiredAttribute(r, *row.xmlNamespace, name, item.missing);
        }
        if (value && row.normalize)
            value = row.normalize(*value);
        if constexpr (Fields::Scalar<Owner, Value>::required)
            item.*row.member = *value;
        else
            item.*row.member = value;
    }

    /// The version is required like any attribute; it is only written differently.
    template<typename T>
    void readAttribute(NodeReader &r, T &item,
                       const Fields::Special<Fields::RtcProfileVersion> &) const
    {
        item.version = requiredAttribute(r, Ns::Rtc, s("version"), item.missing);
    }

    template<typename T, typename Row> void readAttribute(NodeReader &, T &, const Row &) const { }

    template<typename T, typename Owner, typename Item>
    void readChildren(NodeReader &r, T &item, const Fields::Child<Owner, QList<Item>> &row) const
    {
        for (const XmlNode *child : r.children(*row.xmlNamespace, s(row.xmlName)))
            (item.*row.member).append(readElement<Item>(*child));
    }

    template<typename T, typename Owner, typename Item>
    void readChildren(NodeReader &r, T &item,
                      const Fields::Child<Owner, std::optional<Item>> &row) const
    {
        if (const XmlNode *child = r.child(*row.xmlNamespace, s(row.xmlName)))
            item.*row.member = readElement<Item>(*child);
    }

    template<typename T, typename Owner, typename Item>
    void readChildren(NodeReader &r, T &item, const Fields::Child<Owner, Item> &row) const
    {
        if (const XmlNode *child = r.child(*row.xmlNamespace, s(row.xmlName)))
            item.*row.member = readElement<Item>(*child);
        else
            reportMissingChild(r, s(row.xmlName), item.missing);
    }

    /// Unlike the RTS reader, the legacy spelling's elements follow the schema one's.
    template<typename T, typename Owner>
    void readChildren(NodeReader &r, T &item, const Fields::TextList<Owner> &row) const
    {
        for (const char *name : {row.xmlName, row.xmlLegacyName}) {
            if (!name)
                continue;
            for (const XmlNode *child : r.children(*row.xmlNamespace, s(name)))
                (item.*row.member).append(simpleText(*child, m_context));
        }
    }

    template<typename T>
    void readChildren(NodeReader &r, T &item,
                      const Fields::Special<Fields::RtcConstraintTree> &) const
    {
        if (const XmlNode *child = r.child(Ns::Rtc, s("Constraint")))
            item.constraint = readConstraint(*child, m_context);
    }

    void readChildren(NodeReader &r, RtcActions &actions,
                      const Fields::Special<Fields::RtcActionStatuses> &) const
    {
        for (RtcAction action : rtcAllActions()) {
            if (const XmlNode *child = r.child(Ns::Rtc, rtcActionElementName(action)))
                actions[action] = readElement<RtcActionStatus>(*child);
        }
    }

    void readChildren(NodeReader &r, RtcProfile &profile,
                      const Fields::Special<Fields::RtcConfigurationSet> &) const
    {
        const XmlNode *node = r.child(Ns::Rtc, s("ConfigurationSet"));
        if (!node)
            return;
        NodeReader set = reader(*node);
        profile.configurationSetLocation = node->location;
        for (const XmlNode *child : set.children(Ns::Rtc, s("Configuration")))
            profile.configurations.append(readElement<RtcConfiguration>(*child));
        profile.hasConfigurationSet = profile.configurations.isEmpty();
        profile.configurationSetExtras = set.extras();
    }

    template<typename T, typename Row> void readChildren(NodeReader &, T &, const Row &) const { }

    ReadContext m_context;
};

/// Explains why a root element is not an RTC Profile; empty when it is one.
QString rootProblem(const XmlNode &root)
{
    if (root.name != QLatin1String("RtcProfile")) {
        return tr("the root element is <%1>, not <rtc:RtcProfile>: this is not an RTC Profile")
            .arg(root.name);
    }
    if (root.namespaceUri != Ns::Rtc) {
        return tr("<RtcProfile> is in the namespace '%1' instead of '%2'")
            .arg(root.namespaceUri.isEmpty() ? tr("(none)") : root.namespaceUri, Ns::Rtc);
    }
    return {};
}

} // namespace

std::optional<RtcProfile> readRtcXml(const QByteArray &data, const QString &fileName,
                                     Diagnostics *diagnostics)
{
    Diagnostics local;
    Diagnostics *sink = diagnostics ? diagnostics : &local;
    const std::optional<XmlNode> root = parseXml(data, fileName, sink);
    if (!root)
        return std::nullopt;
    const QString problem = rootProblem(*root);
    if (!problem.isEmpty()) {
        sink->append(
            Diagnostic::error(fileName, root->location.line, root->location.column, problem));
        return std::nullopt;
    }
    return Reader(ReadContext {fileName, sink}).readElement<RtcProfile>(*root);
}

} // namespace Profile
