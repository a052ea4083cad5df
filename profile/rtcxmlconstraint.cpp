// SPDX-License-Identifier: MIT
// The constraint tree of RTC.xml, plus the small helpers both XML directions share.
#include "namespaces.h"
#include "rtcxmlinternal.h"

#include <QCoreApplication>

namespace Profile::RtcXml {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcXml", text);
}

const QString Constraint = QStringLiteral("Constraint");
const QString Literal = QStringLiteral("Literal");
const QString Lower = QStringLiteral("LowerBoundary");
const QString Upper = QStringLiteral("UpperBoundary");
const QString IsNullText = QStringLiteral("propertyIsNull");

std::vector<RtcConstraint> readMembers(NodeReader &reader, const ReadContext &context)
{
    std::vector<RtcConstraint> members;
    for (const XmlNode *child : reader.children(Ns::Rtc, Constraint))
        members.push_back(readConstraint(*child, context));
    return members;
}

/// The text of a required child element, or "" with the name recorded as missing.
QString requiredText(NodeReader &reader, const QString &name, RtcMissing &missing,
                     const ReadContext &context)
{
    if (const XmlNode *child = reader.child(Ns::Rtc, name))
        return simpleText(*child, context);
    reportMissingChild(reader, name, missing);
    return {};
}

void readOperator(const XmlNode &node, RtcConstraint &c, const ReadContext &context)
{
    NodeReader reader(node, context.fileName, context.diagnostics);
    switch (c.op) {
    case RtcConstraintOperator::Not:
    case RtcConstraintOperator::And:
    case RtcConstraintOperator::Or:
        c.members = readMembers(reader, context);
        break;
    case RtcConstraintOperator::IsNull:
        c.literal = requiredText(reader, IsNullText, c.missing, context);
        break;
    case RtcConstraintOperator::Like:
        c.literal = requiredText(reader, Literal, c.missing, context);
        c.wildCard = reader.attribute(Ns::Rtc, QStringLiteral("wildCard"));
        c.singleChar = reader.attribute(Ns::Rtc, QStringLiteral("singleChar"));
        c.escapeChar = reader.attribute(Ns::Rtc, QStringLiteral("escapeChar"));
        break;
    case RtcConstraintOperator::Between:
        c.literal = requiredText(reader, Lower, c.missing, context);
        c.upperBoundary = requiredText(reader, Upper, c.missing, context);
        break;
    default:
        c.literal = requiredText(reader, Literal, c.missing, context);
        if (const auto matchCase = reader.attribute(Ns::Rtc, QStringLiteral("matchCase")))
            c.matchCase = normalizedBoolean(*matchCase);
        break;
    }
    c.operatorExtras = reader.extras();
}

void readUnit(const XmlNode &node, RtcConstraint &c, const ReadContext &context)
{
    NodeReader reader(node, context.fileName, context.diagnostics);
    c.key = reader.attribute(Ns::Rtc, QStringLiteral("key"));
    // The schema allows exactly one operator; further ones stay as extras.
    for (const XmlNode &child : node.children) {
        if (child.namespaceUri != Ns::Rtc)
            continue;
        const auto op = rtcConstraintOperatorFromElementName(child.name);
        if (!op)
            continue;
        c.op = *op;
        readOperator(*reader.child(Ns::Rtc, child.name), c, context);
        break;
    }
    c.typeExtras = reader.extras();
}

void addMembers(XmlNode &node, const std::vector<RtcConstraint> &members)
{
    for (const RtcConstraint &member : members)
        node.addChild(constraintToXml(member));
}

void addRequiredText(XmlNode &node, const QString &name, const QString &text,
                     const RtcMissing &missing)
{
    if (text.isEmpty() && missing.contains(name))
        return;
    node.addChild(textElement(Ns::Rtc, name, text));
}

XmlNode operatorToXml(const RtcConstraint &c)
{
    XmlNode node(Ns::Rtc, rtcConstraintOperatorElementName(c.op));
    node.prefix = Ns::preferredPrefix(Ns::Rtc);
    switch (c.op) {
    case RtcConstraintOperator::Not:
    case RtcConstraintOperator::And:
    case RtcConstraintOperator::Or:
        addMembers(node, c.members);
        break;
    case RtcConstraintOperator::IsNull:
        addRequiredText(node, IsNullText, c.literal, c.missing);
        break;
    case RtcConstraintOperator::Like:
        node.setAttribute(Ns::Rtc, QStringLiteral("wildCard"), c.wildCard);
        node.setAttribute(Ns::Rtc, QStringLiteral("singleChar"), c.singleChar);
        node.setAttribute(Ns::Rtc, QStringLiteral("escapeChar"), c.escapeChar);
        addRequiredText(node, Literal, c.literal, c.missing);
        break;
    case RtcConstraintOperator::Between:
        addRequiredText(node, Lower, c.literal, c.missing);
        addRequiredText(node, Upper, c.upperBoundary, c.missing);
        break;
    default:
        if (c.matchCase)
            node.setAttribute(Ns::Rtc, QStringLiteral("matchCase"),
                              normalizedBoolean(*c.matchCase));
        addRequiredText(node, Literal, c.literal, c.missing);
        break;
    }
    c.operatorExtras.applyTo(node);
    return node;
}

} // namespace

QString requiredAttribute(NodeReader &reader, const QString &ns, const QString &name,
                          RtcMissing &missing, const QStringList &legacyNames)
{
    if (auto value = reader.attribute(ns, name, legacyNames))
        return *value;
    missing.append(name);
    reader.warn(tr("<%1> lacks the required attribute '%2'").arg(reader.node().name, name));
    return {};
}

void reportMissingChild(const NodeReader &reader, const QString &name, RtcMissing &missing)
{
    missing.append(name);
    reader.warn(tr("<%1> lacks the required element <%2>").arg(reader.node().name, name));
}

QString simpleText(const XmlNode &node, const ReadContext &context)
{
    if ((!node.attributes.isEmpty() || !node.children.empty()) && context.diagnostics) {
        context.diagnostics->append(Diagnostic::warning(
            context.fileName, node.location.line, node.location.column,
            tr("<%1> should hold only text; its attributes and elements are not kept")
                .arg(node.name)));
    }
    return node.text;
}

QString normalizedBoolean(const QString &value)
{
    const auto parsed = parseBoolean(value);
    return parsed ? booleanText(*parsed) : value;
}

QString normalizedPosition(const QString &value)
{
    const QString upper = value.toUpper();
    return rtcPositions().contains(upper) ? upper : value;
}

void setRequired(XmlNode &node, const QString &ns, const QString &name, const QString &value,
                 const RtcMissing &missing)
{
    if (value.isEmpty() && missing.contains(name))
        return;
    node.setAttribute(ns, name, value);
}

XmlNode textElement(const QString &ns, const QString &name, const QString &text)
{
    XmlNode node(ns, name);
    node.prefix = Ns::preferredPrefix(ns);
    node.text = text;
    return node;
}

RtcConstraint readConstraint(const XmlNode &node, const ReadContext &context)
{
    NodeReader reader(node, context.fileName, context.diagnostics);
    RtcConstraint c;
    c.location = node.location;
    const XmlNode *type = nullptr;
    if ((type = reader.child(Ns::Rtc, QStringLiteral("ConstraintHashType"))))
        c.kind = RtcConstraintKind::Hash;
    else if ((type = reader.child(Ns::Rtc, QStringLiteral("ConstraintListType"))))
        c.kind = RtcConstraintKind::List;
    else if ((type = reader.child(Ns::Rtc, QStringLiteral("ConstraintUnitType"))))
        c.kind = RtcConstraintKind::Unit;
    else
        c.kind = RtcConstraintKind::Empty;
    c.extras = reader.extras();
    if (!type)
        return c;
    if (c.kind == RtcConstraintKind::Unit) {
        readUnit(*type, c, context);
    } else {
        NodeReader typeReader(*type, context.fileName, context.diagnostics);
        c.members = readMembers(typeReader, context);
        c.typeExtras = typeReader.extras();
    }
    return c;
}

XmlNode constraintToXml(const RtcConstraint &c)
{
    XmlNode node(Ns::Rtc, Constraint);
    node.prefix = Ns::preferredPrefix(Ns::Rtc);
    if (c.kind != RtcConstraintKind::Empty) {
        static const QString typeNames[]
            = {QString(), QStringLiteral("ConstraintHashType"),
               QStringLiteral("ConstraintListType"), QStringLiteral("ConstraintUnitType")};
        XmlNode &type = node.addChild(Ns::Rtc, typeNames[int(c.kind)]);
        if (c.kind == RtcConstraintKind::Unit) {
            type.setAttribute(Ns::Rtc, QStringLiteral("key"), c.key);
            if (c.op != RtcConstraintOperator::None)
                type.addChild(operatorToXml(c));
        } else {
            addMembers(type, c.members);
        }
        c.typeExtras.applyTo(type);
    }
    c.extras.applyTo(node);
    return node;
}

} // namespace Profile::RtcXml
