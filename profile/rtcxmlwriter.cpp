// SPDX-License-Identifier: MIT
// Builds the XmlNode tree of an RtcProfile from the field tables (rtcfields_p.h), in schema order
// with OpenRTP's prefixes and xsi:types; the extras of each element go back where they were read.
#include "rtcfields_p.h"
#include "rtcxml.h"
#include "rtcxmlinternal.h"

namespace Profile {

namespace RtcXml {

namespace {

QString s(const char *text)
{
    return QString::fromLatin1(text);
}

XmlNode element(const QString &ns, const QString &name)
{
    XmlNode node(ns, name);
    node.prefix = Ns::preferredPrefix(ns);
    return node;
}

/// Attributes are written in one pass over a table, child elements in a second one.
enum class Pass { Attributes, Children };

template<typename T, typename Owner, typename Value>
void writeRow(XmlNode &node, const T &item, const Fields::Scalar<Owner, Value> &row, Pass pass)
{
    if (pass != Pass::Attributes)
        return;
    const QString name = s(row.xmlName);
    if constexpr (Fields::Scalar<Owner, Value>::required) {
        const QString &value = item.*row.member;
        setRequired(node, *row.xmlNamespace, name,
                    row.style == Fields::Style::Boolean ? normalizedBoolean(value) : value,
                    item.missing);
    } else {
        node.setAttribute(*row.xmlNamespace, name, item.*row.member);
    }
}

template<typename Owner, typename Member, typename Item>
XmlNode childElement(const Fields::Child<Owner, Member> &row, const Item &item)
{
    XmlNode node = element(*row.xmlNamespace, s(row.xmlName));
    if (row.xsiTypeNamespace)
        node.setXsiType(*row.xsiTypeNamespace, s(row.xsiTypeName));
    writeFields(node, item);
    return node;
}

template<typename T, typename Owner, typename Item>
void writeRow(XmlNode &node, const T &item, const Fields::Child<Owner, QList<Item>> &row, Pass pass)
{
    if (pass != Pass::Children)
        return;
    for (const Item &child : item.*row.member)
        node.addChild(childElement(row, child));
}

template<typename T, typename Owner, typename Item>
void writeRow(XmlNode &node, const T &item, const Fields::Child<Owner, std::optional<Item>> &row,
              Pass pass)
{
    if (pass == Pass::Children && item.*row.member)
        node.addChild(childElement(row, *(item.*row.member)));
}

/// A required child the source lacked stays out while it is still empty.
template<typename T, typename Owner, typename Item>
void writeRow(XmlNode &node, const T &item, const Fields::Child<Owner, Item> &row, Pass pass)
{
    const Item &child = item.*row.member;
    if (pass != Pass::Children || (item.missing.contains(s(row.xmlName)) && child == Item()))
        return;
    node.addChild(childElement(row, child));
}

template<typename T, typename Owner>
void writeRow(XmlNode &node, const T &item, const Fields::TextList<Owner> &row, Pass pass)
{
    if (pass != Pass::Children)
        return;
    for (const QString &text : item.*row.member)
        node.addChild(textElement(*row.xmlNamespace, s(row.xmlName), text));
}

/// Saving upgrades the file to the current format, as RTC Builder does.
void writeRow(XmlNode &node, const RtcProfile &, const Fields::Special<Fields::RtcProfileVersion> &,
              Pass pass)
{
    if (pass == Pass::Attributes)
        node.setAttribute(Ns::Rtc, s("version"), RtcProfile::CurrentVersion);
}

void writeRow(XmlNode &node, const RtcProfile &profile,
              const Fields::Special<Fields::RtcConfigurationSet> &, Pass pass)
{
    if (pass == Pass::Children
        && (profile.hasConfigurationSet || !profile.configurations.isEmpty()
            || !profile.configurationSetExtras.isEmpty()))
        node.addChild(configurationSetToXml(profile));
}

void writeRow(XmlNode &node, const RtcActions &actions,
              const Fields::Special<Fields::RtcActionStatuses> &, Pass pass)
{
    if (pass != Pass::Children)
        return;
    for (RtcAction action : rtcAllActions()) {
        if (const auto &status = actions[action]) {
            XmlNode child = element(Ns::Rtc, rtcActionElementName(action));
            child.setXsiType(Ns::RtcDoc, s("action_status_doc"));
            writeFields(child, *status);
            node.addChild(std::move(child));
        }
    }
}

template<typename T>
void writeRow(XmlNode &node, const T &item, const Fields::Special<Fields::RtcConstraintTree> &,
              Pass pass)
{
    if (pass == Pass::Children && item.constraint)
        node.addChild(constraintToXml(*item.constraint));
}

/// Files of RTC Builder's older versions type plain configurations rtcDoc:configuration_doc;
/// the extension type is needed only for the extension's fields.
bool keepsNarrowType(const RtcConfiguration &c)
{
    return c.extras.hasXsiType(Ns::RtcDoc, s("configuration_doc")) && !c.variableName && !c.comment
        && c.properties.isEmpty();
}

} // namespace

template<typename T> void writeFields(XmlNode &node, const T &item)
{
    for (Pass pass : {Pass::Attributes, Pass::Children}) {
        Fields::forEachXmlRow(Fields::RtcElement<T>::fields,
                              [&](const auto &row) { writeRow(node, item, row, pass); });
    }
    item.extras.applyTo(node);
}

// The YAML reader counts the children of each element type to place unknown keys after them.
template void writeFields(XmlNode &, const RtcProfile &);
template void writeFields(XmlNode &, const RtcProperty &);
template void writeFields(XmlNode &, const RtcBasicInfo &);
template void writeFields(XmlNode &, const RtcBasicDoc &);
template void writeFields(XmlNode &, const RtcActions &);
template void writeFields(XmlNode &, const RtcActionStatus &);
template void writeFields(XmlNode &, const RtcActionDoc &);
template void writeFields(XmlNode &, const RtcConfiguration &);
template void writeFields(XmlNode &, const RtcConfigurationDoc &);
template void writeFields(XmlNode &, const RtcDataPort &);
template void writeFields(XmlNode &, const RtcDataPortDoc &);
template void writeFields(XmlNode &, const RtcEvent &);
template void writeFields(XmlNode &, const RtcEventDoc &);
template void writeFields(XmlNode &, const RtcServicePort &);
template void writeFields(XmlNode &, const RtcServicePortDoc &);
template void writeFields(XmlNode &, const RtcServiceInterface &);
template void writeFields(XmlNode &, const RtcServiceInterfaceDoc &);
template void writeFields(XmlNode &, const RtcTransMethod &);
template void writeFields(XmlNode &, const RtcLanguage &);
template void writeFields(XmlNode &, const RtcTargetEnvironment &);
template void writeFields(XmlNode &, const RtcLibrary &);
template void writeFields(XmlNode &, const RtcParameter &);

XmlNode configurationSetToXml(const RtcProfile &profile)
{
    XmlNode node = element(Ns::Rtc, s("ConfigurationSet"));
    for (const RtcConfiguration &configuration : profile.configurations) {
        XmlNode child = element(Ns::Rtc, s("Configuration"));
        if (keepsNarrowType(configuration))
            child.setXsiType(Ns::RtcDoc, s("configuration_doc"));
        else
            child.setXsiType(Ns::RtcExt, s("configuration_ext"));
        writeFields(child, configuration);
        node.addChild(std::move(child));
    }
    profile.configurationSetExtras.applyTo(node);
    return node;
}

} // namespace RtcXml

XmlNode rtcProfileToXml(const RtcProfile &profile)
{
    XmlNode root = RtcXml::element(Ns::Rtc, QStringLiteral("RtcProfile"));
    RtcXml::writeFields(root, profile);
    return root;
}

QByteArray writeRtcXml(const RtcProfile &profile)
{
    return serializeXml(rtcProfileToXml(profile));
}

} // namespace Profile
