// SPDX-License-Identifier: MIT
// Builds the XmlNode tree of an RtsProfile from the field tables (rtsfields_p.h), in schema order
// with OpenRTP's xsi:types; the extras of each element are put back at the positions they were
// read from.
#include "rtsfields_p.h"
#include "rtsxml.h"

namespace Profile {

namespace {

QString n(const char *name)
{
    return QString::fromLatin1(name);
}

/// Which rows one pass over a table writes.
enum class Pass { BaseAttributes, ExtensionAttributes, FirstChildren, Children };

template<typename T> void writeElement(XmlNode &node, const T &item);

template<typename T, typename Owner, typename Value>
void writeRow(XmlNode &node, const T &item, const Fields::Scalar<Owner, Value> &row, Pass pass)
{
    // The rtsExt attributes come from the extension types, which the schema adds after the base.
    const bool extension = *row.xmlNamespace == Ns::RtsExt;
    if (pass == (extension ? Pass::ExtensionAttributes : Pass::BaseAttributes))
        node.setAttribute(*row.xmlNamespace, n(row.xmlName), item.*row.member);
}

template<typename Owner, typename Member>
bool isChildPass(const Fields::Child<Owner, Member> &row, Pass pass)
{
    return pass == (row.xmlPlace == Fields::XmlPlace::First ? Pass::FirstChildren : Pass::Children);
}

template<typename Owner, typename Member, typename Item>
void writeChild(XmlNode &parent, const Fields::Child<Owner, Member> &row, const Item &item)
{
    XmlNode &node = parent.addChild(*row.xmlNamespace, n(row.xmlName));
    if (row.xsiTypeNamespace)
        node.setXsiType(*row.xsiTypeNamespace, n(row.xsiTypeName));
    writeElement(node, item);
}

template<typename T, typename Owner, typename Item>
void writeRow(XmlNode &node, const T &item, const Fields::Child<Owner, QList<Item>> &row, Pass pass)
{
    if (isChildPass(row, pass)) {
        for (const Item &child : item.*row.member)
            writeChild(node, row, child);
    }
}

template<typename T, typename Owner, typename Item>
void writeRow(XmlNode &node, const T &item, const Fields::Child<Owner, std::optional<Item>> &row,
              Pass pass)
{
    if (isChildPass(row, pass) && item.*row.member)
        writeChild(node, row, *(item.*row.member));
}

template<typename T, typename Owner, typename Item>
void writeRow(XmlNode &node, const T &item, const Fields::Child<Owner, Item> &row, Pass pass)
{
    if (isChildPass(row, pass))
        writeChild(node, row, item.*row.member);
}

template<typename T, typename Owner>
void writeRow(XmlNode &node, const T &item, const Fields::TextList<Owner> &row, Pass pass)
{
    if (pass != Pass::Children)
        return;
    for (const QString &text : item.*row.member)
        node.addChild(*row.xmlNamespace, n(row.xmlName)).text = text;
}

template<typename T> void writeElement(XmlNode &node, const T &item)
{
    for (Pass pass :
         {Pass::BaseAttributes, Pass::ExtensionAttributes, Pass::FirstChildren, Pass::Children}) {
        Fields::forEachXmlRow(Fields::RtsElement<T>::fields,
                              [&](const auto &row) { writeRow(node, item, row, pass); });
    }
    item.extras.applyTo(node);
}

} // namespace

QByteArray writeRtsXml(const RtsProfile &profile)
{
    XmlNode root(Ns::Rts, n("RtsProfile"));
    root.prefix = Ns::preferredPrefix(Ns::Rts);
    root.children.reserve(std::size_t(profile.components.size() + profile.dataPortConnectors.size()
                                      + profile.servicePortConnectors.size() + 16));
    writeElement(root, profile);
    return serializeXml(root);
}

} // namespace Profile
