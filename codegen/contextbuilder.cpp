// SPDX-License-Identifier: MIT
#include "contextbuilder.h"

#include "constraintsyntax.h"
#include "idltypecategory.h"
#include "javatypemapping.h"

#include <QRegularExpression>

#include <algorithm>

using namespace Profile;

namespace Codegen {

namespace {

// The callbacks RTC Builder lets the user switch on; OnAction/OnModeChanged are FSM-only and
// only kept from files.
const QList<RtcAction> &editableActions()
{
    static const QList<RtcAction> list
        = {RtcAction::OnInitialize, RtcAction::OnFinalize,    RtcAction::OnStartup,
           RtcAction::OnShutdown,   RtcAction::OnActivated,   RtcAction::OnDeactivated,
           RtcAction::OnAborting,   RtcAction::OnError,       RtcAction::OnReset,
           RtcAction::OnExecute,    RtcAction::OnStateUpdate, RtcAction::OnRateChanged};
    return list;
}

/// One line of text for a `//` or `#` comment: generated comments must not end early.
QString commentText(const std::optional<QString> &text)
{
    QString line = text.value_or(QString()).simplified();
    return line.replace(QLatin1String("*/"), QLatin1String("* /"));
}

QStringList dataPortDocLines(const RtcDataPort &port)
{
    QStringList lines;
    if (!port.doc)
        return lines;
    appendDocLine(lines, QStringLiteral("- Type"), port.doc->type);
    appendDocLine(lines, QStringLiteral("- Number"), port.doc->number);
    appendDocLine(lines, QStringLiteral("- Semantics"), port.doc->semantics);
    appendDocLine(lines, QStringLiteral("- Unit"), port.doc->unit);
    appendDocLine(lines, QStringLiteral("- Frequency"), port.doc->occerrence);
    appendDocLine(lines, QStringLiteral("- Operation Cycle"), port.doc->operation);
    return lines;
}

QStringList configurationDocLines(const RtcConfiguration &config)
{
    QStringList lines;
    const RtcConfigurationDoc doc = config.doc.value_or(RtcConfigurationDoc());
    appendDocLine(lines, QStringLiteral("- Unit"),
                  config.unit && !config.unit->isEmpty() ? config.unit : doc.unit);
    appendDocLine(lines, QStringLiteral("- Range"), doc.range);
    return lines;
}

QString dataVariable(const RtcDataPort &port)
{
    // RTC Builder writes an empty variableName when the user left it blank.
    return port.variableName && !port.variableName->trimmed().isEmpty() ? *port.variableName
                                                                        : port.name;
}

QString configVariable(const RtcConfiguration &config)
{
    return config.variableName && !config.variableName->isEmpty() ? *config.variableName
                                                                  : config.name;
}

/// The element type of `vector<T>` / `std::vector<T>` configuration types, or nothing.
std::optional<QString> vectorElementType(const QString &type)
{
    static const QRegularExpression vector(QStringLiteral("^(?:std::)?vector\\s*<\\s*(.+?)\\s*>$"));
    const QRegularExpressionMatch match = vector.match(type.trimmed());
    if (!match.hasMatch())
        return std::nullopt;
    return match.captured(1);
}

QString cxxConfigType(const QString &type)
{
    // RTC Builder users write `vector<double>`; OpenRTM binds std::vector parameters.
    if (const std::optional<QString> element = vectorElementType(type))
        return QStringLiteral("std::vector<%1>").arg(cxxConfigType(*element));
    return type == QLatin1String("string") ? QStringLiteral("std::string") : type;
}

bool isIntegerType(const QString &type)
{
    return type == QLatin1String("short") || type == QLatin1String("int")
        || type == QLatin1String("long");
}

bool isFloatType(const QString &type)
{
    return type == QLatin1String("float") || type == QLatin1String("double");
}

QString pythonConfigInit(const QString &type)
{
    // OpenRTM_aist.stringTo converts a list parameter element by element to the type of the
    // first element of the initial value: `[[0.0]]` binds a list of floats.
    if (const std::optional<QString> element = vectorElementType(type))
        return QStringLiteral("[%1]").arg(pythonConfigInit(*element));
    if (isIntegerType(type))
        return QStringLiteral("[0]");
    if (isFloatType(type))
        return QStringLiteral("[0.0]");
    return QStringLiteral("['']");
}

/// The element of a `vector<T>` configuration type as Java holds it: the boxed class and the
/// expression turning one comma-separated `item` into one.
struct JavaVectorElement
{
    QString boxed;
    QString parse;
};

std::optional<JavaVectorElement> javaVectorElement(const QString &type)
{
    const std::optional<QString> element = vectorElementType(type);
    static const QHash<QString, QString> boxes
        = {{QStringLiteral("short"), QStringLiteral("Short")},
           {QStringLiteral("int"), QStringLiteral("Integer")},
           {QStringLiteral("long"), QStringLiteral("Long")},
           {QStringLiteral("float"), QStringLiteral("Float")},
           {QStringLiteral("double"), QStringLiteral("Double")},
           {QStringLiteral("string"), QStringLiteral("String")}};
    if (!element || !boxes.contains(*element))
        return std::nullopt;
    const QString boxed = boxes.value(*element);
    // OpenRTM's C++ stringTo splits vectors at ',' and trims the items; Java does the same.
    return JavaVectorElement {boxed, boxed == QLatin1String("String")
                                  ? QStringLiteral("item.trim()")
                                  : QStringLiteral("%1.valueOf(item.trim())").arg(boxed)};
}

QString javaConfigHolder(const QString &type)
{
    // OpenRTM-aist Java's jp.go.aist.rtm.RTC.util has holders of single values only, so a
    // vector parameter gets a holder class generated with the project.
    if (const std::optional<JavaVectorElement> element = javaVectorElement(type))
        return element->boxed + QStringLiteral("VectorHolder");
    static const QHash<QString, QString> holders
        = {{QStringLiteral("short"), QStringLiteral("ShortHolder")},
           {QStringLiteral("int"), QStringLiteral("IntegerHolder")},
           {QStringLiteral("long"), QStringLiteral("LongHolder")},
           {QStringLiteral("float"), QStringLiteral("FloatHolder")},
           {QStringLiteral("double"), QStringLiteral("DoubleHolder")}};
    return holders.value(type, QStringLiteral("StringHolder"));
}

QString javaStructInit(const IdlModel &idl, const QString &scopedName, int depth);

QString javaMemberInit(const IdlModel &idl, const IdlType &type, int depth)
{
    const IdlType resolved = idl.resolve(type);
    if (resolved.kind == IdlType::Kind::Named && idl.structs.contains(resolved.name))
        return javaStructInit(idl, resolved.name, depth + 1);
    if (resolved.kind == IdlType::Kind::Named && idl.enums.contains(resolved.name))
        return javaTypeName(idl, resolved) + QStringLiteral(".from_int(0)");
    return javaDefaultValue(idl, type);
}

// Java data port variables must hold a complete value before the first write: nested structs
// are constructed member by member, as RTC Builder does.
QString javaStructInit(const IdlModel &idl, const QString &scopedName, int depth)
{
    const QString javaName = javaTypeName(idl, IdlType::named(scopedName));
    const auto it = idl.structs.constFind(scopedName);
    if (it == idl.structs.cend() || depth > 16)
        return QStringLiteral("new %1()").arg(javaName);
    QStringList arguments;
    for (const IdlMember &member : it->members)
        arguments << javaMemberInit(idl, member.type, depth);
    return QStringLiteral("new %1(%2)").arg(javaName, arguments.join(QStringLiteral(", ")));
}

QStringList componentDocLines(const RtcBasicDoc &doc)
{
    QStringList lines;
    appendDocLine(lines, QString(), doc.description);
    appendDocLine(lines, QStringLiteral("In/Out"), doc.inout);
    appendDocLine(lines, QStringLiteral("Algorithm"), doc.algorithm);
    appendDocLine(lines, QStringLiteral("Reference"), doc.reference);
    return lines;
}

QString firstModule(const QString &scopedName)
{
    const int split = scopedName.indexOf(QLatin1String("::"));
    return split < 0 ? QString() : scopedName.left(split);
}

/// `1.0.0` from a version like `1.0.0-beta`; CMake's project() only takes numbers.
QString cmakeVersion(const QString &version)
{
    static const QRegularExpression numbers(QStringLiteral("^\\d+(\\.\\d+){0,3}"));
    const QRegularExpressionMatch match = numbers.match(version.trimmed());
    return match.hasMatch() ? match.captured(0) : QStringLiteral("1.0.0");
}

QVariantMap specLine(const QString &key, const QString &value)
{
    return {{QStringLiteral("key"), key},
            {QStringLiteral("value"), value},
            {QStringLiteral("literalKey"), escapeStringLiteral(key)},
            {QStringLiteral("literalValue"), escapeStringLiteral(value)}};
}

Diagnostic nameError(const QString &what, const QString &name, TargetLanguage language)
{
    Diagnostic d = Diagnostic::error(
        QString(), 0, 0,
        QStringLiteral("%1 '%2' cannot be used in %3 code (only letters, digits and '_'; a "
                       "component name must also not start with a digit or '__' nor be a "
                       "reserved word)")
            .arg(what, name, targetLanguageProfileName(language)));
    d.object = name;
    return d;
}

} // namespace

void appendDocLine(QStringList &lines, const QString &label, const std::optional<QString> &text)
{
    const QString line = commentText(text);
    if (!line.isEmpty())
        lines << (label.isEmpty() ? line : label + QStringLiteral(": ") + line);
}

QString escapeStringLiteral(const QString &text)
{
    QString out;
    out.reserve(text.size());
    for (const QChar c : text) {
        switch (c.unicode()) {
        case '\\':
            out += QLatin1String("\\\\");
            break;
        case '"':
            out += QLatin1String("\\\"");
            break;
        case '\n':
            out += QLatin1String("\\n");
            break;
        case '\r':
            out += QLatin1String("\\r");
            break;
        case '\t':
            out += QLatin1String("\\t");
            break;
        default:
            if (c.unicode() < 0x20)
                out += QStringLiteral("\\%1").arg(c.unicode(), 3, 8, QLatin1Char('0'));
            else
                out += c;
        }
    }
    return out;
}

QVariantList markFirstLast(QVariantList items)
{
    for (int i = 0; i < items.size(); ++i) {
        QVariantMap map = items.at(i).toMap();
        map.insert(QStringLiteral("first"), i == 0);
        map.insert(QStringLiteral("last"), i == items.size() - 1);
        items[i] = map;
    }
    return items;
}

ContextBuilder::ContextBuilder(const RtcProfile &profile, const IdlModel &idl)
    : m_profile(profile)
    , m_idl(idl)
{ }

std::optional<QVariantMap> ContextBuilder::build(TargetLanguage language,
                                                 Diagnostics *diagnostics) const
{
    Diagnostics problems;
    if (!checkNames(language, &problems)) {
        if (diagnostics)
            diagnostics->append(problems);
        return std::nullopt;
    }
    QVariantMap context = basics(language);
    context.insert(QStringLiteral("moduleSpec"), markFirstLast(moduleSpec(language)));
    context.insert(QStringLiteral("actions"), markFirstLast(actions()));
    const QVariantList in = dataPorts(language, RtcPortType::DataIn);
    const QVariantList out = dataPorts(language, RtcPortType::DataOut);
    context.insert(QStringLiteral("inPorts"), in);
    context.insert(QStringLiteral("outPorts"), out);
    context.insert(QStringLiteral("hasInPorts"), !in.isEmpty());
    context.insert(QStringLiteral("hasOutPorts"), !out.isEmpty());
    context.insert(QStringLiteral("hasDataPorts"), !in.isEmpty() || !out.isEmpty());
    const QVariantList configs = configurations(language);
    context.insert(QStringLiteral("configurations"), configs);
    context.insert(QStringLiteral("hasConfigurations"), !configs.isEmpty());
    if (language == TargetLanguage::Java)
        context.insert(QStringLiteral("javaVectorHolders"), javaVectorHolders());
    if (language == TargetLanguage::Cpp) {
        // OpenRTM-aist's coil cannot read std::vector parameters; the project brings the
        // stream extraction in a header of its own (VectorConvert.h), written only when needed.
        const bool vectors = hasVectorConfiguration();
        context.insert(QStringLiteral("hasVectorConfigurations"), vectors);
        context.insert(QStringLiteral("vectorConvertHeaders"),
                       vectors ? QVariantList {QVariantMap()} : QVariantList());
    }
    if (!addServices(language, context, &problems) || !addFsm(language, context, &problems)) {
        if (diagnostics)
            diagnostics->append(problems);
        return std::nullopt;
    }
    if (context.value(QStringLiteral("hasFsm")).toBool()) {
        // The machine takes queued events from onExecute, so a component with EventPorts has one.
        QVariantList list = context.value(QStringLiteral("actions")).toList();
        for (QVariant &item : list) {
            QVariantMap action = item.toMap();
            if (action.value(QStringLiteral("name")) == rtcActionKey(RtcAction::OnExecute)) {
                action.insert(QStringLiteral("implemented"), true);
                action.insert(QStringLiteral("runsFsm"), true);
            }
            item = action;
        }
        context.insert(QStringLiteral("actions"), list);
    }
    return context;
}

QVariantMap ContextBuilder::basics(TargetLanguage language) const
{
    const RtcBasicInfo &info = m_profile.basicInfo;
    const RtcBasicDoc doc = info.doc.value_or(RtcBasicDoc());
    return {
        {QStringLiteral("name"), info.name},
        {QStringLiteral("nameUpper"), info.name.toUpper()},
        {QStringLiteral("nameLower"), info.name.toLower()},
        {QStringLiteral("componentName"), info.name},
        {QStringLiteral("description"), commentText(info.description)},
        {QStringLiteral("version"), info.version},
        {QStringLiteral("vendor"), info.vendor},
        {QStringLiteral("category"), info.category},
        {QStringLiteral("componentType"), info.componentType},
        {QStringLiteral("activityType"), info.activityType},
        {QStringLiteral("componentKind"), info.componentKind},
        {QStringLiteral("maxInstances"), info.maxInstances.value_or(QStringLiteral("1"))},
        {QStringLiteral("executionType"), info.executionType},
        {QStringLiteral("executionRate"), info.executionRate.value_or(QStringLiteral("1000.0"))},
        {QStringLiteral("languageKind"), targetLanguageProfileName(language)},
        {QStringLiteral("langType"),
         language == TargetLanguage::Python ? QStringLiteral("SCRIPT") : QStringLiteral("compile")},
        {QStringLiteral("cmakeVersion"), cmakeVersion(info.version)},
        {QStringLiteral("creator"), commentText(doc.creator)},
        {QStringLiteral("docLines"), componentDocLines(doc)},
        {QStringLiteral("license"), commentText(doc.license)},
        {QStringLiteral("updateDate"), info.updateDate}};
}

QVariantList ContextBuilder::moduleSpec(TargetLanguage language) const
{
    const RtcBasicInfo &info = m_profile.basicInfo;
    QVariantList lines = {
        specLine(QStringLiteral("implementation_id"), info.name),
        specLine(QStringLiteral("type_name"), info.name),
        specLine(QStringLiteral("description"), info.description.value_or(QString())),
        specLine(QStringLiteral("version"), info.version),
        specLine(QStringLiteral("vendor"), info.vendor),
        specLine(QStringLiteral("category"), info.category),
        specLine(QStringLiteral("activity_type"), info.activityType),
        specLine(QStringLiteral("kind"), info.componentKind),
        specLine(QStringLiteral("max_instance"), info.maxInstances.value_or(QStringLiteral("1"))),
        specLine(QStringLiteral("language"), targetLanguageProfileName(language)),
        specLine(QStringLiteral("lang_type"),
                 language == TargetLanguage::Python ? QStringLiteral("SCRIPT")
                                                    : QStringLiteral("compile"))};
    // All defaults first, then widgets, constraints and types, as OpenRTM's tools read them.
    for (const RtcConfiguration &c : m_profile.configurations)
        lines << specLine(QStringLiteral("conf.default.") + c.name, c.defaultValue);
    for (const RtcConfiguration &c : m_profile.configurations) {
        if (const std::optional<QString> widget = c.widget())
            lines << specLine(QStringLiteral("conf.__widget__.") + c.name, *widget);
    }
    for (const RtcConfiguration &c : m_profile.configurations) {
        const QString constraint = constraintToString(c.constraint);
        if (!constraint.isEmpty())
            lines << specLine(QStringLiteral("conf.__constraints__.") + c.name, constraint);
    }
    for (const RtcConfiguration &c : m_profile.configurations)
        lines << specLine(QStringLiteral("conf.__type__.") + c.name, c.type);
    return lines;
}

QVariantList ContextBuilder::actions() const
{
    QVariantList list;
    for (const RtcAction action : editableActions()) {
        const std::optional<RtcActionStatus> &status = m_profile.actions[action];
        const bool implemented
            = action == RtcAction::OnInitialize || (status && status->isImplemented());
        const RtcActionDoc doc = status && status->doc ? *status->doc : RtcActionDoc();
        const std::optional<QString> description = doc.description;
        QStringList docLines;
        appendDocLine(docLines, QStringLiteral("@pre"), doc.preCondition);
        appendDocLine(docLines, QStringLiteral("@post"), doc.postCondition);
        // onInitialize and onFinalize are the only callbacks without an execution context id.
        const bool withEc = action != RtcAction::OnInitialize && action != RtcAction::OnFinalize;
        list << QVariantMap {
            {QStringLiteral("name"), rtcActionKey(action)},
            {QStringLiteral("upperName"), rtcActionElementName(action)},
            {QStringLiteral("implemented"), implemented},
            {QStringLiteral("isInitialize"), action == RtcAction::OnInitialize},
            {QStringLiteral("cxxParameters"),
             withEc ? QStringLiteral("RTC::UniqueId ec_id") : QString()},
            {QStringLiteral("cxxDefinitionParameters"),
             withEc ? QStringLiteral("RTC::UniqueId /*ec_id*/") : QString()},
            {QStringLiteral("pythonParameters"),
             withEc ? QStringLiteral("self, ec_id") : QStringLiteral("self")},
            {QStringLiteral("javaParameters"), withEc ? QStringLiteral("int ec_id") : QString()},
            {QStringLiteral("javaArguments"), withEc ? QStringLiteral("ec_id") : QString()},
            {QStringLiteral("description"), commentText(description)},
            {QStringLiteral("docLines"), docLines}};
    }
    return list;
}

QVariantList ContextBuilder::dataPorts(TargetLanguage language, RtcPortType kind) const
{
    QVariantList list;
    for (const RtcDataPort &port : m_profile.dataPorts) {
        if (port.kind() != kind)
            continue;
        QString native = port.type;
        QString init;
        if (language == TargetLanguage::Python) {
            native.replace(QLatin1String("::"), QLatin1String("."));
            init = QStringLiteral("OpenRTM_aist.instantiateDataType(%1)").arg(native);
        } else if (language == TargetLanguage::Java) {
            native = javaTypeName(m_idl, IdlType::named(port.type));
            init = javaStructInit(m_idl, port.type, 0);
        }
        const std::optional<QString> description = port.doc ? port.doc->description : std::nullopt;
        list << QVariantMap {
            {QStringLiteral("name"), port.name},
            {QStringLiteral("literalName"), escapeStringLiteral(port.name)},
            {QStringLiteral("type"), port.type},
            {QStringLiteral("variable"), dataVariable(port)},
            {QStringLiteral("nativeType"), native},
            {QStringLiteral("init"), init},
            {QStringLiteral("module"), firstModule(port.type)},
            {QStringLiteral("idlFile"), port.idlFile.value_or(QString())},
            {QStringLiteral("docLines"), dataPortDocLines(port)},
            {QStringLiteral("hasDescription"), !commentText(description).isEmpty()},
            {QStringLiteral("description"), commentText(description)}};
    }
    return markFirstLast(list);
}

QVariantList ContextBuilder::configurations(TargetLanguage language) const
{
    QVariantList list;
    for (const RtcConfiguration &c : m_profile.configurations) {
        const QString native = language == TargetLanguage::Cpp ? cxxConfigType(c.type)
            : language == TargetLanguage::Java                 ? javaConfigHolder(c.type)
                                                               : c.type;
        const std::optional<QString> description = c.doc ? c.doc->description : std::nullopt;
        list << QVariantMap {
            {QStringLiteral("name"), c.name},
            {QStringLiteral("literalName"), escapeStringLiteral(c.name)},
            {QStringLiteral("type"), c.type},
            {QStringLiteral("nativeType"), native},
            {QStringLiteral("variable"), configVariable(c)},
            {QStringLiteral("defaultValue"), c.defaultValue},
            {QStringLiteral("literalDefault"), escapeStringLiteral(c.defaultValue)},
            {QStringLiteral("init"), pythonConfigInit(c.type)},
            {QStringLiteral("holder"), javaConfigHolder(c.type)},
            {QStringLiteral("widget"), c.widget().value_or(QStringLiteral("text"))},
            {QStringLiteral("constraint"), constraintToString(c.constraint)},
            {QStringLiteral("hasConstraint"), !constraintToString(c.constraint).isEmpty()},
            {QStringLiteral("hasWidget"), c.widget().has_value()},
            {QStringLiteral("unit"), commentText(c.unit)},
            {QStringLiteral("docLines"), configurationDocLines(c)},
            {QStringLiteral("hasDescription"), !commentText(description).isEmpty()},
            {QStringLiteral("description"), commentText(description)}};
    }
    return markFirstLast(list);
}

QVariantList ContextBuilder::javaVectorHolders() const
{
    QVariantList list;
    QStringList seen;
    for (const RtcConfiguration &c : m_profile.configurations) {
        const std::optional<JavaVectorElement> element = javaVectorElement(c.type);
        const QString holder = javaConfigHolder(c.type);
        if (!element || seen.contains(holder))
            continue;
        seen << holder;
        list << QVariantMap {{QStringLiteral("holderName"), holder},
                             {QStringLiteral("configType"), c.type},
                             {QStringLiteral("boxed"), element->boxed},
                             {QStringLiteral("parse"), element->parse}};
    }
    return list;
}

bool ContextBuilder::hasVectorConfiguration() const
{
    return std::any_of(
        m_profile.configurations.cbegin(), m_profile.configurations.cend(),
        [](const RtcConfiguration &c) { return vectorElementType(c.type).has_value(); });
}

bool ContextBuilder::checkNames(TargetLanguage language, Diagnostics *diagnostics) const
{
    const qsizetype before = diagnostics->size();
    // Port, interface and configuration variables are always used with a prefix (`m_`,
    // `self._`), so only their characters matter; the component name is used bare as class,
    // module and file name.
    auto check = [&](const QString &what, const QString &name) {
        if (!isIdentifierText(name))
            diagnostics->append(nameError(what, name, language));
    };
    if (!isValidIdentifier(language, m_profile.basicInfo.name))
        diagnostics->append(
            nameError(QStringLiteral("Component name"), m_profile.basicInfo.name, language));
    for (const RtcDataPort &port : m_profile.dataPorts)
        check(QStringLiteral("Data port variable"), dataVariable(port));
    for (const RtcServicePort &port : m_profile.servicePorts) {
        check(QStringLiteral("Service port name"), port.name);
        for (const RtcServiceInterface &iface : port.interfaces)
            check(QStringLiteral("Service interface variable"),
                  iface.variableName && !iface.variableName->isEmpty() ? *iface.variableName
                                                                       : iface.name);
    }
    for (const RtcConfiguration &c : m_profile.configurations)
        check(QStringLiteral("Configuration variable"), configVariable(c));
    return diagnostics->size() == before;
}

} // namespace Codegen
