// SPDX-License-Identifier: MIT
#include "rtcxml.h"
#include "rtcxmlinternal.h"
#include "rtcyaml.h"
#include "rtcyamlinternal.h"

#include <QCoreApplication>
#include <QStringDecoder>

namespace Profile {

using namespace RtcYaml;

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::RtcYaml", text);
}

/// How many schema children the XML writer gives the element of `value` (which has no extras
/// yet): unknown YAML keys kept as elements go after them.
template<typename T> int schemaChildren(const T &value)
{
    XmlNode node;
    RtcXml::writeFields(node, value);
    return int(node.children.size());
}

/// Records a required part the mapping lacks (under its XML name) and warns about it.
void missingKey(const MapReader &m, const char *key, const QString &schemaName, RtcMissing &missing)
{
    missing.append(schemaName);
    m.context().warn(m.node().Mark(),
                     tr("the required key '%1' is missing").arg(QLatin1String(key)));
}

/// Top-level keys beside `rtcProfile:` have no place in the model; say so instead of dropping
/// them silently.
void warnAboutOtherTopLevelKeys(const YAML::Node &document, Context &context)
{
    for (const auto &entry : document) {
        if (entry.first.IsScalar() && entry.first.Scalar() != "rtcProfile") {
            context.warn(entry.first.Mark(),
                         tr("the top-level key '%1' is not part of an RTC Profile and is not kept")
                             .arg(fromStd(entry.first.Scalar())));
        }
    }
}

/// Reads RTC Builder's YAML, one function per model struct.
class Reader
{
public:
    explicit Reader(Context &context)
        : m_context(context)
    { }

    RtcProfile profile(const YAML::Node &node);

private:
    MapReader reader(const YAML::Node &node) { return MapReader(node, m_context); }
    RtcProperties properties(MapReader &m);
    std::optional<RtcConstraint> constraint(MapReader &m, int depth);
    RtcConstraint constraintOf(const YAML::Node &node, int depth);
    void readUnit(const YAML::Node &node, RtcConstraint &c, int depth);
    void readOperator(const YAML::Node &node, RtcConstraint &c, int depth);
    QString date(MapReader &m, const char *key, RtcMissing &missing);

    RtcBasicInfo basicInfo(const YAML::Node &node);
    RtcActions actions(const YAML::Node &node);
    RtcActionStatus actionStatus(const YAML::Node &node);
    void configurationSet(const YAML::Node &node, RtcProfile &profile);
    RtcConfiguration configuration(const YAML::Node &node);
    RtcDataPort dataPort(const YAML::Node &node);
    RtcEvent event(const YAML::Node &node);
    RtcServicePort servicePort(const YAML::Node &node);
    RtcServiceInterface serviceInterface(const YAML::Node &node);
    RtcLanguage language(const YAML::Node &node);
    RtcTargetEnvironment target(const YAML::Node &node);

    template<typename Doc, typename Fill>
    void doc(MapReader &m, std::optional<Doc> &target, Fill fill)
    {
        const auto node = m.map({"rtcDoc::doc", "doc"});
        if (!node)
            return;
        MapReader d = reader(*node);
        Doc result;
        result.location = d.location();
        fill(d, result);
        result.extras = d.extras(0);
        target = result;
    }

    Context &m_context;
};

RtcProperties Reader::properties(MapReader &m)
{
    RtcProperties result;
    for (const YAML::Node &item : m.list({"rtcExt::properties", "properties"})) {
        MapReader p = reader(item);
        RtcProperty property;
        property.location = p.location();
        property.name = p.required({"name"}, property.missing);
        property.value = p.scalar({"value"});
        property.extras = p.extras(0);
        result.append(property);
    }
    return result;
}

QString Reader::date(MapReader &m, const char *key, RtcMissing &missing)
{
    const auto node = m.take({key});
    if (!node || node->IsNull()) {
        missing.append(QLatin1String(key));
        m_context.warn(m.node().Mark(),
                       tr("the required key '%1' is missing").arg(QLatin1String(key)));
        return {};
    }
    return readDate(*node, m_context).value_or(QString());
}

RtcProfile Reader::profile(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcProfile p;
    p.location = m.location();
    p.id = m.required({"id"}, p.missing);
    p.version = m.required({"version"}, p.missing);
    if (const auto info = m.map({"basicInfo"}))
        p.basicInfo = basicInfo(*info);
    else
        missingKey(m, "basicInfo", QStringLiteral("BasicInfo"), p.missing);
    if (const auto actionsNode = m.map({"actions"}))
        p.actions = actions(*actionsNode);
    else
        missingKey(m, "actions", QStringLiteral("Actions"), p.missing);
    if (const auto set = m.map({"configurationSet"}))
        configurationSet(*set, p);
    for (const YAML::Node &item : m.list({"dataPorts"}))
        p.dataPorts.append(dataPort(item));
    for (const YAML::Node &item : m.list({"servicePorts"}))
        p.servicePorts.append(servicePort(item));
    for (const YAML::Node &item : m.list({"parameters"})) {
        MapReader pm = reader(item);
        RtcParameter parameter;
        parameter.location = pm.location();
        parameter.name = pm.required({"name"}, parameter.missing);
        parameter.defaultValue = pm.scalar({"defaultValue"});
        parameter.extras = pm.extras(0);
        p.parameters.append(parameter);
    }
    if (const auto lang = m.map({"language"}))
        p.language = language(*lang);
    p.extras = m.extras(int(rtcProfileToXml(p).children.size()));
    return p;
}

RtcBasicInfo Reader::basicInfo(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcBasicInfo b;
    b.location = m.location();
    b.name = m.required({"name"}, b.missing);
    b.componentType = m.required({"componentType"}, b.missing);
    b.activityType = m.required({"activityType"}, b.missing);
    b.componentKind = m.required({"componentKind"}, b.missing);
    b.rtcType = m.scalar({"rtcType"});
    b.category = m.required({"category"}, b.missing);
    b.description = m.scalar({"description"});
    b.executionRate = m.scalar({"executionRate"});
    b.executionType = m.required({"executionType"}, b.missing);
    b.maxInstances = m.scalar({"maxInstances"});
    b.vendor = m.required({"vendor"}, b.missing);
    b.version = m.required({"version"}, b.missing);
    b.abstractText = m.scalar({"abstract"});
    b.hardwareProfile = m.scalar({"hardwareProfile"});
    b.creationDate = date(m, "creationDate", b.missing);
    b.updateDate = date(m, "updateDate", b.missing);
    b.comment = m.scalar({"rtcExt::comment", "comment"});
    b.saveProject = m.scalar({"rtcExt::saveProject", "saveProject"});
    doc(m, b.doc, [](MapReader &d, RtcBasicDoc &r) {
        r.description = d.scalar({"description"});
        r.inout = d.scalar({"inout"});
        r.algorithm = d.scalar({"algorithm"});
        r.creator = d.scalar({"creator"});
        r.license = d.scalar({"license"});
        r.reference = d.scalar({"reference"});
    });
    b.versionUpLogs = m.scalarList({"rtcExt::versionUpLogs", "versionUpLogs", "versionUpLog"});
    b.properties = properties(m);
    b.extras = m.extras(schemaChildren(b));
    return b;
}

RtcActions Reader::actions(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcActions a;
    a.location = m.location();
    for (RtcAction action : rtcAllActions()) {
        const QByteArray key = rtcActionKey(action).toLatin1();
        if (const auto status = m.map({key.constData()}))
            a[action] = actionStatus(*status);
    }
    a.extras = m.extras(schemaChildren(a));
    return a;
}

RtcActionStatus Reader::actionStatus(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcActionStatus a;
    a.location = m.location();
    // EMF leaves out attributes at their default, so a missing `implemented` means false.
    a.implemented
        = RtcXml::normalizedBoolean(m.scalar({"implemented"}).value_or(QStringLiteral("false")));
    doc(m, a.doc, [](MapReader &d, RtcActionDoc &r) {
        r.description = d.scalar({"description"});
        r.preCondition = d.scalar({"preCondition"});
        r.postCondition = d.scalar({"postCondition"});
    });
    a.extras = m.extras(schemaChildren(a));
    return a;
}

void Reader::configurationSet(const YAML::Node &node, RtcProfile &profile)
{
    MapReader m = reader(node);
    profile.configurationSetLocation = m.location();
    for (const YAML::Node &item : m.list({"configuration"}))
        profile.configurations.append(configuration(item));
    profile.hasConfigurationSet = profile.configurations.isEmpty();
    profile.configurationSetExtras
        = m.extras(int(RtcXml::configurationSetToXml(profile).children.size()));
}

RtcConfiguration Reader::configuration(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcConfiguration c;
    c.location = m.location();
    c.name = m.required({"name"}, c.missing);
    c.type = m.required({"type"}, c.missing);
    c.defaultValue = m.required({"defaultValue"}, c.missing);
    c.unit = m.scalar({"unit"});
    c.variableName = m.scalar({"rtcExt::variableName", "variableName", "varname"});
    c.comment = m.scalar({"rtcExt::comment", "comment"});
    c.constraint = constraint(m, 0);
    doc(m, c.doc, [](MapReader &d, RtcConfigurationDoc &r) {
        r.dataname = d.scalar({"dataname"});
        r.defaultValue = d.scalar({"defaultValue"});
        r.description = d.scalar({"description"});
        r.unit = d.scalar({"unit"});
        r.range = d.scalar({"range"});
        r.constraint = d.scalar({"constraint"});
    });
    c.properties = properties(m);
    c.extras = m.extras(schemaChildren(c));
    return c;
}

RtcDataPort Reader::dataPort(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcDataPort p;
    p.location = m.location();
    p.portType = m.required({"portType"}, p.missing);
    p.name = m.required({"name"}, p.missing);
    p.type = m.required({"type"}, p.missing);
    p.idlFile = m.scalar({"idlFile"});
    p.interfaceType = m.scalar({"interfaceType"});
    p.dataflowType = m.scalar({"dataflowType"});
    p.subscriptionType = m.scalar({"subscriptionType", "subscriprionType"});
    p.unit = m.scalar({"unit"});
    p.position
        = RtcXml::normalizedPosition(m.required({"rtcExt::position", "position"}, p.missing));
    p.variableName = m.scalar({"rtcExt::variableName", "variableName", "varname"});
    p.comment = m.scalar({"rtcExt::comment", "comment"});
    p.constraint = constraint(m, 0);
    for (const YAML::Node &item : m.list({"event", "events"}))
        p.events.append(event(item));
    doc(m, p.doc, [](MapReader &d, RtcDataPortDoc &r) {
        r.description = d.scalar({"description"});
        r.type = d.scalar({"type"});
        r.number = d.scalar({"number"});
        r.semantics = d.scalar({"semantics"});
        r.unit = d.scalar({"unit"});
        r.occerrence = d.scalar({"occerrence"});
        r.operation = d.scalar({"operation"});
    });
    p.properties = properties(m);
    p.extras = m.extras(schemaChildren(p));
    return p;
}

RtcEvent Reader::event(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcEvent e;
    e.location = m.location();
    e.name = m.required({"name"}, e.missing);
    e.condition = m.scalar({"condition"});
    e.source = m.required({"source"}, e.missing);
    e.target = m.required({"target"}, e.missing);
    e.type = m.scalar({"type"});
    doc(m, e.doc, [](MapReader &d, RtcEventDoc &r) {
        r.description = d.scalar({"description"});
        r.type = d.scalar({"type"});
        r.number = d.scalar({"number"});
        r.semantics = d.scalar({"semantics"});
        r.unit = d.scalar({"unit"});
        r.operation = d.scalar({"operation"});
    });
    e.extras = m.extras(schemaChildren(e));
    return e;
}

RtcServicePort Reader::servicePort(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcServicePort p;
    p.location = m.location();
    p.name = m.required({"name"}, p.missing);
    p.position
        = RtcXml::normalizedPosition(m.required({"rtcExt::position", "position"}, p.missing));
    p.comment = m.scalar({"rtcExt::comment", "comment"});
    for (const YAML::Node &item : m.list({"serviceInterface", "serviceInterfaces"}))
        p.interfaces.append(serviceInterface(item));
    for (const YAML::Node &item : m.list({"transMethods"})) {
        MapReader t = reader(item);
        RtcTransMethod method;
        method.location = t.location();
        method.kind = t.required({"kind"}, method.missing);
        method.extras = t.extras(0);
        p.transMethods.append(method);
    }
    doc(m, p.doc, [](MapReader &d, RtcServicePortDoc &r) {
        r.description = d.scalar({"description"});
        r.ifdescription = d.scalar({"ifdescription"});
    });
    p.properties = properties(m);
    p.extras = m.extras(schemaChildren(p));
    return p;
}

RtcServiceInterface Reader::serviceInterface(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcServiceInterface i;
    i.location = m.location();
    i.name = m.required({"name"}, i.missing);
    i.direction = m.required({"direction"}, i.missing);
    i.instanceName = m.scalar({"instanceName"});
    i.idlFile = m.scalar({"idlFile"});
    i.type = m.required({"type"}, i.missing);
    i.path = m.scalar({"path"});
    i.variableName = m.scalar({"rtcExt::variableName", "variableName", "varname"});
    i.comment = m.scalar({"rtcExt::comment", "comment"});
    doc(m, i.doc, [](MapReader &d, RtcServiceInterfaceDoc &r) {
        r.description = d.scalar({"description"});
        r.docArgument = d.scalar({"docArgument"});
        r.docReturn = d.scalar({"docReturn"});
        r.docException = d.scalar({"docException"});
        r.docPreCondition = d.scalar({"docPreCondition"});
        r.docPostCondition = d.scalar({"docPostCondition"});
    });
    i.properties = properties(m);
    i.extras = m.extras(schemaChildren(i));
    return i;
}

RtcLanguage Reader::language(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcLanguage l;
    l.location = m.location();
    l.kind = m.required({"kind"}, l.missing);
    for (const YAML::Node &item : m.list({"rtcExt::targets", "targets"}))
        l.targets.append(target(item));
    l.properties = properties(m);
    l.extras = m.extras(schemaChildren(l));
    return l;
}

RtcTargetEnvironment Reader::target(const YAML::Node &node)
{
    MapReader m = reader(node);
    RtcTargetEnvironment t;
    t.location = m.location();
    t.langVersion = m.scalar({"langVersion", "rtcExt::langVersion"});
    t.os = m.scalar({"os", "rtcExt::os"});
    t.other = m.scalar({"other", "rtcExt::other"});
    t.cpuOther = m.scalar({"cpuOther", "rtcExt::cpuOther"});
    t.osVersions = m.scalarList({"osVersions", "rtcExt::osVersions"});
    t.cpus = m.scalarList({"cpus", "rtcExt::cpus"});
    for (const YAML::Node &item : m.list({"libraries", "rtcExt::libraries"})) {
        MapReader lm = reader(item);
        RtcLibrary library;
        library.location = lm.location();
        library.name = lm.required({"name"}, library.missing);
        library.version = lm.scalar({"version"});
        library.other = lm.scalar({"other"});
        library.extras = lm.extras(0);
        t.libraries.append(library);
    }
    t.extras = m.extras(schemaChildren(t));
    return t;
}

// ---- constraints

std::optional<RtcConstraint> Reader::constraint(MapReader &m, int depth)
{
    const auto node = m.map({"constraint"});
    if (!node)
        return std::nullopt;
    return constraintOf(*node, depth);
}

RtcConstraint Reader::constraintOf(const YAML::Node &node, int depth)
{
    RtcConstraint c;
    c.location = locationOf(node);
    if (depth > MaxDepth) {
        m_context.error(node.Mark(), tr("constraints nested deeper than %1 levels").arg(MaxDepth));
        return c;
    }
    MapReader m = reader(node);
    std::optional<YAML::Node> type;
    if ((type = m.map({"constraintHashType"})))
        c.kind = RtcConstraintKind::Hash;
    else if ((type = m.map({"constraintListType"})))
        c.kind = RtcConstraintKind::List;
    else if ((type = m.map({"constraintUnitType"})))
        c.kind = RtcConstraintKind::Unit;
    else
        c.kind = RtcConstraintKind::Empty;
    if (type && c.kind == RtcConstraintKind::Unit) {
        readUnit(*type, c, depth);
    } else if (type) {
        MapReader t = reader(*type);
        for (const YAML::Node &item : t.list({"constraint"}))
            c.members.push_back(constraintOf(item, depth + 1));
        c.typeExtras = t.extras(int(c.members.size()));
    }
    c.extras = m.extras(c.kind == RtcConstraintKind::Empty ? 0 : 1);
    return c;
}

void Reader::readUnit(const YAML::Node &node, RtcConstraint &c, int depth)
{
    MapReader m = reader(node);
    c.key = m.scalar({"key"});
    for (int i = int(RtcConstraintOperator::Not); i <= int(RtcConstraintOperator::Between); ++i) {
        const auto op = RtcConstraintOperator(i);
        QByteArray key = rtcConstraintOperatorElementName(op).toLatin1();
        key[0] = char(QChar::toLower(key[0]));
        if (const auto value = m.map({key.constData()})) {
            c.op = op;
            readOperator(*value, c, depth);
            break;
        }
    }
    c.typeExtras = m.extras(c.op == RtcConstraintOperator::None ? 0 : 1);
}

void Reader::readOperator(const YAML::Node &node, RtcConstraint &c, int depth)
{
    MapReader m = reader(node);
    switch (c.op) {
    case RtcConstraintOperator::Not:
    case RtcConstraintOperator::And:
    case RtcConstraintOperator::Or:
        for (const YAML::Node &item : m.list({"constraint"}))
            c.members.push_back(constraintOf(item, depth + 1));
        break;
    case RtcConstraintOperator::IsNull:
        c.literal = m.required({"propertyIsNull"}, c.missing);
        break;
    case RtcConstraintOperator::Like:
        c.literal = m.required({"literal"}, c.missing, "Literal");
        c.wildCard = m.scalar({"wildCard"});
        c.singleChar = m.scalar({"singleChar"});
        c.escapeChar = m.scalar({"escapeChar"});
        break;
    case RtcConstraintOperator::Between:
        c.literal = m.required({"lowerBoundary"}, c.missing, "LowerBoundary");
        c.upperBoundary = m.required({"upperBoundary"}, c.missing, "UpperBoundary");
        break;
    default:
        c.literal = m.required({"literal"}, c.missing, "Literal");
        // EMF leaves out attributes at their default: no matchCase means false.
        c.matchCase
            = RtcXml::normalizedBoolean(m.scalar({"matchCase"}).value_or(QStringLiteral("false")));
        break;
    }
    RtcConstraint bare = c;
    bare.operatorExtras = {};
    bare.typeExtras = {};
    const XmlNode element = RtcXml::constraintToXml(bare);
    c.operatorExtras = m.extras(int(element.children.front().children.front().children.size()));
}

/// Finds the first byte that is not UTF-8 (yaml-cpp would accept it silently).
bool checkUtf8(const QByteArray &data, Context &context)
{
    int line = 0;
    qsizetype start = 0;
    while (start <= data.size()) {
        qsizetype end = data.indexOf('\n', start);
        if (end < 0)
            end = data.size();
        QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
        const QString text = decoder.decode(data.mid(start, end - start));
        if (decoder.hasError()) {
            YAML::Mark mark;
            mark.line = line;
            mark.column = int(qMax<qsizetype>(text.indexOf(QChar::ReplacementCharacter), 0));
            context.error(mark, tr("invalid UTF-8 byte sequence"));
            return false;
        }
        ++line;
        start = end + 1;
    }
    return true;
}

std::optional<YAML::Node> parse(const QByteArray &data, Context &context)
{
    try {
        return YAML::Load(data.toStdString());
    } catch (const YAML::Exception &e) {
        context.error(e.mark, tr("YAML syntax error: %1").arg(fromStd(e.msg)));
    } catch (const std::exception &e) {
        context.error(YAML::Mark::null_mark(),
                      tr("cannot read the YAML text: %1").arg(QString::fromLocal8Bit(e.what())));
    }
    return std::nullopt;
}

} // namespace

std::optional<RtcProfile> readRtcYaml(const QByteArray &data, const QString &fileName,
                                      Diagnostics *diagnostics)
{
    Context context(fileName, diagnostics);
    if (!checkUtf8(data, context))
        return std::nullopt;
    const std::optional<YAML::Node> document = parse(data, context);
    if (!document)
        return std::nullopt;
    if (!document->IsMap() || !(*document)["rtcProfile"]) {
        // An empty document has no position; the problem is then at its start.
        const YAML::Mark mark = document->Mark().is_null() ? YAML::Mark() : document->Mark();
        context.error(mark, tr("not an RTC Profile: expected a top-level 'rtcProfile:' mapping"));
        return std::nullopt;
    }
    try {
        warnAboutOtherTopLevelKeys(*document, context);
        RtcProfile profile = Reader(context).profile((*document)["rtcProfile"]);
        if (context.failed())
            return std::nullopt;
        return profile;
    } catch (const YAML::Exception &e) {
        context.error(e.mark, tr("cannot read the YAML text: %1").arg(fromStd(e.msg)));
    }
    return std::nullopt;
}

} // namespace Profile
