// SPDX-License-Identifier: MIT
#include "rtcyaml.h"
#include "rtcyamlinternal.h"

namespace Profile {

using namespace RtcYaml;

namespace {

QString s(const char *text)
{
    return QString::fromLatin1(text);
}

Value propertiesValue(const RtcProperties &properties)
{
    Value list = Value::sequence();
    for (const RtcProperty &property : properties) {
        Value item;
        item.setRequired(s("name"), property.name, property.missing);
        item.set(s("value"), property.value);
        item.addExtras(property.extras);
        list.items.push_back(item);
    }
    return list;
}

void setProperties(Value &value, const RtcProperties &properties)
{
    if (!properties.isEmpty())
        value.set(s("rtcExt::properties"), propertiesValue(properties));
}

/// `"rtcDoc::doc"` with the given attributes (name → value) and extras.
template<typename Doc>
void setDoc(Value &value, const std::optional<Doc> &doc,
            std::initializer_list<std::pair<const char *, std::optional<QString>>> fields)
{
    if (!doc)
        return;
    Value d;
    for (const auto &field : fields)
        d.set(s(field.first), field.second);
    d.addExtras(doc->extras);
    value.set(s("rtcDoc::doc"), d);
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

Value basicInfoValue(const RtcBasicInfo &b)
{
    Value v;
    const RtcMissing &m = b.missing;
    v.setRequired(s("name"), b.name, m);
    v.setRequired(s("componentType"), b.componentType, m);
    v.setRequired(s("activityType"), b.activityType, m);
    v.setRequired(s("componentKind"), b.componentKind, m);
    v.set(s("rtcType"), b.rtcType);
    v.setRequired(s("category"), b.category, m);
    v.set(s("description"), b.description);
    if (b.executionRate)
        v.set(s("executionRate"), Value::number(*b.executionRate));
    v.setRequired(s("executionType"), b.executionType, m);
    if (b.maxInstances)
        v.set(s("maxInstances"), Value::number(*b.maxInstances));
    v.setRequired(s("vendor"), b.vendor, m);
    v.setRequired(s("version"), b.version, m);
    v.set(s("abstract"), b.abstractText);
    v.set(s("hardwareProfile"), b.hardwareProfile);
    if (!(b.creationDate.isEmpty() && m.contains(s("creationDate"))))
        v.set(s("creationDate"), dateValue(b.creationDate));
    if (!(b.updateDate.isEmpty() && m.contains(s("updateDate"))))
        v.set(s("updateDate"), dateValue(b.updateDate));
    v.set(s("rtcExt::comment"), b.comment);
    v.set(s("rtcExt::saveProject"), b.saveProject);
    setDoc(v, b.doc,
           {{"description", b.doc ? b.doc->description : std::nullopt},
            {"inout", b.doc ? b.doc->inout : std::nullopt},
            {"algorithm", b.doc ? b.doc->algorithm : std::nullopt},
            {"creator", b.doc ? b.doc->creator : std::nullopt},
            {"license", b.doc ? b.doc->license : std::nullopt},
            {"reference", b.doc ? b.doc->reference : std::nullopt}});
    if (!b.versionUpLogs.isEmpty())
        v.set(s("rtcExt::versionUpLogs"), Value::stringList(b.versionUpLogs));
    setProperties(v, b.properties);
    v.addExtras(b.extras);
    return v;
}

Value actionsValue(const RtcActions &actions)
{
    Value v;
    for (RtcAction action : rtcAllActions()) {
        const auto &status = actions[action];
        if (!status)
            continue;
        Value a;
        if (!(status->implemented.isEmpty() && status->missing.contains(s("implemented"))))
            a.set(s("implemented"), Value::boolean(status->implemented));
        const auto &doc = status->doc;
        setDoc(a, doc,
               {{"description", doc ? doc->description : std::nullopt},
                {"preCondition", doc ? doc->preCondition : std::nullopt},
                {"postCondition", doc ? doc->postCondition : std::nullopt}});
        a.addExtras(status->extras);
        v.set(rtcActionKey(action), a);
    }
    v.addExtras(actions.extras);
    return v;
}

Value configurationValue(const RtcConfiguration &c)
{
    Value v;
    v.setRequired(s("name"), c.name, c.missing);
    v.setRequired(s("type"), c.type, c.missing);
    v.setRequired(s("defaultValue"), c.defaultValue, c.missing);
    v.set(s("unit"), c.unit);
    v.set(s("rtcExt::variableName"), c.variableName);
    v.set(s("rtcExt::comment"), c.comment);
    if (c.constraint)
        v.set(s("constraint"), constraintValue(*c.constraint));
    const auto &doc = c.doc;
    setDoc(v, doc,
           {{"dataname", doc ? doc->dataname : std::nullopt},
            {"defaultValue", doc ? doc->defaultValue : std::nullopt},
            {"description", doc ? doc->description : std::nullopt},
            {"unit", doc ? doc->unit : std::nullopt},
            {"range", doc ? doc->range : std::nullopt},
            {"constraint", doc ? doc->constraint : std::nullopt}});
    setProperties(v, c.properties);
    v.addExtras(c.extras);
    return v;
}

Value eventValue(const RtcEvent &e)
{
    Value v;
    v.setRequired(s("name"), e.name, e.missing);
    v.set(s("condition"), e.condition);
    v.setRequired(s("source"), e.source, e.missing);
    v.setRequired(s("target"), e.target, e.missing);
    v.set(s("type"), e.type);
    const auto &doc = e.doc;
    setDoc(v, doc,
           {{"description", doc ? doc->description : std::nullopt},
            {"type", doc ? doc->type : std::nullopt},
            {"number", doc ? doc->number : std::nullopt},
            {"semantics", doc ? doc->semantics : std::nullopt},
            {"unit", doc ? doc->unit : std::nullopt},
            {"operation", doc ? doc->operation : std::nullopt}});
    v.addExtras(e.extras);
    return v;
}

Value dataPortValue(const RtcDataPort &p)
{
    Value v;
    v.setRequired(s("portType"), p.portType, p.missing);
    v.setRequired(s("name"), p.name, p.missing);
    v.setRequired(s("type"), p.type, p.missing);
    v.set(s("idlFile"), p.idlFile);
    v.set(s("interfaceType"), p.interfaceType);
    v.set(s("dataflowType"), p.dataflowType);
    v.set(s("subscriptionType"), p.subscriptionType);
    v.set(s("unit"), p.unit);
    v.setRequired(s("rtcExt::position"), p.position, p.missing);
    v.set(s("rtcExt::variableName"), p.variableName);
    v.set(s("rtcExt::comment"), p.comment);
    if (p.constraint)
        v.set(s("constraint"), constraintValue(*p.constraint));
    if (!p.events.isEmpty()) {
        Value events = Value::sequence();
        for (const RtcEvent &event : p.events)
            events.items.push_back(eventValue(event));
        v.set(s("event"), events);
    }
    const auto &doc = p.doc;
    setDoc(v, doc,
           {{"description", doc ? doc->description : std::nullopt},
            {"type", doc ? doc->type : std::nullopt},
            {"number", doc ? doc->number : std::nullopt},
            {"semantics", doc ? doc->semantics : std::nullopt},
            {"unit", doc ? doc->unit : std::nullopt},
            {"occerrence", doc ? doc->occerrence : std::nullopt},
            {"operation", doc ? doc->operation : std::nullopt}});
    setProperties(v, p.properties);
    v.addExtras(p.extras);
    return v;
}

Value serviceInterfaceValue(const RtcServiceInterface &i)
{
    Value v;
    v.setRequired(s("name"), i.name, i.missing);
    v.setRequired(s("direction"), i.direction, i.missing);
    v.set(s("instanceName"), i.instanceName);
    v.set(s("idlFile"), i.idlFile);
    v.setRequired(s("type"), i.type, i.missing);
    v.set(s("path"), i.path);
    v.set(s("rtcExt::variableName"), i.variableName);
    v.set(s("rtcExt::comment"), i.comment);
    const auto &doc = i.doc;
    setDoc(v, doc,
           {{"description", doc ? doc->description : std::nullopt},
            {"docArgument", doc ? doc->docArgument : std::nullopt},
            {"docReturn", doc ? doc->docReturn : std::nullopt},
            {"docException", doc ? doc->docException : std::nullopt},
            {"docPreCondition", doc ? doc->docPreCondition : std::nullopt},
            {"docPostCondition", doc ? doc->docPostCondition : std::nullopt}});
    setProperties(v, i.properties);
    v.addExtras(i.extras);
    return v;
}

Value servicePortValue(const RtcServicePort &p)
{
    Value v;
    v.setRequired(s("name"), p.name, p.missing);
    v.setRequired(s("rtcExt::position"), p.position, p.missing);
    v.set(s("rtcExt::comment"), p.comment);
    if (!p.interfaces.isEmpty()) {
        Value interfaces = Value::sequence();
        for (const RtcServiceInterface &interface : p.interfaces)
            interfaces.items.push_back(serviceInterfaceValue(interface));
        v.set(s("serviceInterface"), interfaces);
    }
    if (!p.transMethods.isEmpty()) {
        Value methods = Value::sequence();
        for (const RtcTransMethod &method : p.transMethods) {
            Value m;
            m.setRequired(s("kind"), method.kind, method.missing);
            m.addExtras(method.extras);
            methods.items.push_back(m);
        }
        v.set(s("transMethods"), methods);
    }
    const auto &doc = p.doc;
    setDoc(v, doc,
           {{"description", doc ? doc->description : std::nullopt},
            {"ifdescription", doc ? doc->ifdescription : std::nullopt}});
    setProperties(v, p.properties);
    v.addExtras(p.extras);
    return v;
}

Value targetValue(const RtcTargetEnvironment &t)
{
    Value v;
    v.set(s("langVersion"), t.langVersion);
    v.set(s("os"), t.os);
    v.set(s("other"), t.other);
    v.set(s("cpuOther"), t.cpuOther);
    if (!t.osVersions.isEmpty())
        v.set(s("osVersions"), Value::stringList(t.osVersions));
    if (!t.cpus.isEmpty())
        v.set(s("cpus"), Value::stringList(t.cpus));
    if (!t.libraries.isEmpty()) {
        Value libraries = Value::sequence();
        for (const RtcLibrary &library : t.libraries) {
            Value l;
            l.setRequired(s("name"), library.name, library.missing);
            l.set(s("version"), library.version);
            l.set(s("other"), library.other);
            l.addExtras(library.extras);
            libraries.items.push_back(l);
        }
        v.set(s("libraries"), libraries);
    }
    v.addExtras(t.extras);
    return v;
}

Value languageValue(const RtcLanguage &l)
{
    Value v;
    v.setRequired(s("kind"), l.kind, l.missing);
    if (!l.targets.isEmpty()) {
        Value targets = Value::sequence();
        for (const RtcTargetEnvironment &target : l.targets)
            targets.items.push_back(targetValue(target));
        v.set(s("rtcExt::targets"), targets);
    }
    setProperties(v, l.properties);
    v.addExtras(l.extras);
    return v;
}

template<typename T, typename F>
void setList(Value &value, const char *key, const QList<T> &items, F convert)
{
    if (items.isEmpty())
        return;
    Value list = Value::sequence();
    for (const T &item : items)
        list.items.push_back(convert(item));
    value.set(s(key), list);
}

Value profileValue(const RtcProfile &p)
{
    Value v;
    v.setRequired(s("id"), p.id, p.missing);
    v.set(s("version"), Value::string(RtcProfile::CurrentVersion));
    if (!(p.missing.contains(s("BasicInfo")) && p.basicInfo == RtcBasicInfo()))
        v.set(s("basicInfo"), basicInfoValue(p.basicInfo));
    if (!p.missing.contains(s("Actions")) || p.actions != RtcActions())
        v.set(s("actions"), actionsValue(p.actions));
    if (p.hasConfigurationSet || !p.configurations.isEmpty()
        || !p.configurationSetExtras.isEmpty()) {
        Value set;
        Value list = Value::sequence();
        for (const RtcConfiguration &c : p.configurations)
            list.items.push_back(configurationValue(c));
        set.set(s("configuration"), list);
        set.addExtras(p.configurationSetExtras);
        v.set(s("configurationSet"), set);
    }
    setList(v, "dataPorts", p.dataPorts, dataPortValue);
    setList(v, "servicePorts", p.servicePorts, servicePortValue);
    setList(v, "parameters", p.parameters, [](const RtcParameter &parameter) {
        Value item;
        item.setRequired(s("name"), parameter.name, parameter.missing);
        item.set(s("defaultValue"), parameter.defaultValue);
        item.addExtras(parameter.extras);
        return item;
    });
    if (p.language)
        v.set(s("language"), languageValue(*p.language));
    v.addExtras(p.extras);
    return v;
}

} // namespace

QByteArray writeRtcYaml(const RtcProfile &profile)
{
    Value root;
    root.set(s("rtcProfile"), profileValue(profile));
    return emitDocument(root);
}

} // namespace Profile
