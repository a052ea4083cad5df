// SPDX-License-Identifier: MIT
// Writes RTC Builder's YAML dialect through the field tables; constraint trees have code of their
// own. The emitter sorts each mapping's keys by their local name, as RTC Builder does.
#include "rtcfields_p.h"
#include "rtcyaml.h"
#include "rtcyamlinternal.h"

namespace Profile {

using namespace RtcYaml;

namespace {

QString s(const char *text)
{
    return QString::fromLatin1(text);
}

Value scalarValue(Fields::Style style, const QString &text)
{
    switch (style) {
    case Fields::Style::Number:
        return Value::number(text);
    case Fields::Style::Boolean:
        return Value::boolean(text);
    case Fields::Style::Date:
        return dateValue(text);
    case Fields::Style::Text:
        break;
    }
    return Value::string(text);
}

Value constraintValue(const RtcConstraint &c);

Value membersValue(const std::vector<RtcConstraint> &members)
{
    Value list = Value::sequence();
    for (const RtcConstraint &member : members)
        list.items.push_back(constraintValue(member));
    return list;
}

Value operatorValue(const RtcConstraint &c)
{
    Value v;
    switch (c.op) {
    case RtcConstraintOperator::Not:
        v.set(s("constraint"),
              c.members.size() == 1 ? constraintValue(c.members.front()) : membersValue(c.members));
        break;
    case RtcConstraintOperator::And:
    case RtcConstraintOperator::Or:
        v.set(s("constraint"), membersValue(c.members));
        break;
    case RtcConstraintOperator::IsNull:
        v.setRequired(s("propertyIsNull"), c.literal, c.missing);
        break;
    case RtcConstraintOperator::Like:
        v.setRequired(s("literal"), c.literal, c.missing, s("Literal"));
        v.set(s("wildCard"), c.wildCard);
        v.set(s("singleChar"), c.singleChar);
        v.set(s("escapeChar"), c.escapeChar);
        break;
    case RtcConstraintOperator::Between:
        v.setRequired(s("lowerBoundary"), c.literal, c.missing, s("LowerBoundary"));
        v.setRequired(s("upperBoundary"), c.upperBoundary, c.missing, s("UpperBoundary"));
        break;
    default:
        v.setRequired(s("literal"), c.literal, c.missing, s("Literal"));
        if (c.matchCase)
            v.set(s("matchCase"), Value::boolean(*c.matchCase));
        break;
    }
    v.addExtras(c.operatorExtras);
    return v;
}

Value constraintValue(const RtcConstraint &c)
{
    Value v;
    Value type;
    switch (c.kind) {
    case RtcConstraintKind::Empty:
        break;
    case RtcConstraintKind::Hash:
    case RtcConstraintKind::List:
        type.set(s("constraint"), membersValue(c.members));
        break;
    case RtcConstraintKind::Unit:
        type.set(s("key"), c.key);
        if (c.op != RtcConstraintOperator::None) {
            QString key = rtcConstraintOperatorElementName(c.op);
            key[0] = key[0].toLower();
            type.set(key, operatorValue(c));
        }
        break;
    }
    if (c.kind != RtcConstraintKind::Empty) {
        type.addExtras(c.typeExtras);
        static const char *names[]
            = {"", "constraintHashType", "constraintListType", "constraintUnitType"};
        v.set(s(names[int(c.kind)]), type);
    }
    v.addExtras(c.extras);
    return v;
}

template<typename T> Value elementValue(const T &item);

template<typename T, typename Owner, typename Text>
void writeRow(Value &value, const T &item, const Fields::Scalar<Owner, Text> &row)
{
    const QString key = s(row.yamlKey);
    if constexpr (Fields::Scalar<Owner, Text>::required) {
        const QString &text = item.*row.member;
        // A required part the source lacked stays out while it is still empty.
        if (text.isEmpty() && item.missing.contains(s(row.xmlName)))
            return;
        value.set(key, scalarValue(row.style, text));
    } else if (const std::optional<QString> &text = item.*row.member) {
        value.set(key, scalarValue(row.style, *text));
    }
}

template<typename T, typename Owner, typename Item>
void writeRow(Value &value, const T &item, const Fields::Child<Owner, QList<Item>> &row)
{
    const QList<Item> &items = item.*row.member;
    if (items.isEmpty())
        return;
    Value list = Value::sequence();
    for (const Item &child : items)
        list.items.push_back(elementValue(child));
    value.set(s(row.yamlKey), list);
}

template<typename T, typename Owner, typename Item>
void writeRow(Value &value, const T &item, const Fields::Child<Owner, std::optional<Item>> &row)
{
    if (const std::optional<Item> &child = item.*row.member)
        value.set(s(row.yamlKey), elementValue(*child));
}

template<typename T, typename Owner, typename Item>
void writeRow(Value &value, const T &item, const Fields::Child<Owner, Item> &row)
{
    const Item &child = item.*row.member;
    if (!(item.missing.contains(s(row.xmlName)) && child == Item()))
        value.set(s(row.yamlKey), elementValue(child));
}

template<typename T, typename Owner>
void writeRow(Value &value, const T &item, const Fields::TextList<Owner> &row)
{
    if (!(item.*row.member).isEmpty())
        value.set(s(row.yamlKey), Value::stringList(item.*row.member));
}

/// Saving upgrades the file to the current format, as RTC Builder does.
void writeRow(Value &value, const RtcProfile &, const Fields::Special<Fields::RtcProfileVersion> &)
{
    value.set(s("version"), Value::string(RtcProfile::CurrentVersion));
}

void writeRow(Value &value, const RtcProfile &p,
              const Fields::Special<Fields::RtcConfigurationSet> &)
{
    if (!p.hasConfigurationSet && p.configurations.isEmpty() && p.configurationSetExtras.isEmpty())
        return;
    Value set;
    Value list = Value::sequence();
    for (const RtcConfiguration &c : p.configurations)
        list.items.push_back(elementValue(c));
    set.set(s("configuration"), list);
    set.addExtras(p.configurationSetExtras);
    value.set(s("configurationSet"), set);
}

void writeRow(Value &value, const RtcActions &actions,
              const Fields::Special<Fields::RtcActionStatuses> &)
{
    for (RtcAction action : rtcAllActions()) {
        if (const auto &status = actions[action])
            value.set(rtcActionKey(action), elementValue(*status));
    }
}

template<typename T>
void writeRow(Value &value, const T &item, const Fields::Special<Fields::RtcConstraintTree> &)
{
    if (item.constraint)
        value.set(s("constraint"), constraintValue(*item.constraint));
}

/// The keys of the table's rows (RTC Builder's order comes from sorting them), then the extras.
template<typename T> Value elementValue(const T &item)
{
    Value value;
    Fields::forEachRow(Fields::RtcElement<T>::fields,
                       [&](const auto &row) { writeRow(value, item, row); });
    value.addExtras(item.extras);
    return value;
}

} // namespace

QByteArray writeRtcYaml(const RtcProfile &profile)
{
    Value root;
    root.set(s("rtcProfile"), elementValue(profile));
    return emitDocument(root);
}

} // namespace Profile
