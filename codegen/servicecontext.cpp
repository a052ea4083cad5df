// SPDX-License-Identifier: MIT
// The service-port half of ContextBuilder: interfaces, operations with their per-language
// parameter mappings, and the IDL files the project needs.
#include "contextbuilder.h"

#include "cxxtypemapping.h"
#include "javatypemapping.h"

#include <QFileInfo>
#include <QSet>

using namespace Profile;

namespace Codegen {

namespace {

QString stripScope(QString type)
{
    type = type.trimmed();
    if (type.startsWith(QLatin1String("::")))
        type.remove(0, 2);
    return type;
}

/// The interface a profile names: by scoped name, or by its simple name when that is unique
/// (old profiles store `MyService` without the module).
const IdlInterface *findInterface(const IdlModel &idl, const QString &profileType)
{
    const QString type = stripScope(profileType);
    if (const auto it = idl.interfaces.constFind(type); it != idl.interfaces.cend() && it->defined)
        return &*it;
    const IdlInterface *found = nullptr;
    for (const IdlInterface &candidate : idl.interfaces) {
        if (!candidate.defined || !candidate.scopedName.endsWith(QLatin1String("::") + type))
            continue;
        if (found)
            return nullptr;
        found = &candidate;
    }
    return found;
}

QString simpleName(const QString &scopedName)
{
    const int split = scopedName.lastIndexOf(QLatin1String("::"));
    return split < 0 ? scopedName : scopedName.mid(split + 2);
}

QString scopeOf(const QString &scopedName)
{
    const int split = scopedName.lastIndexOf(QLatin1String("::"));
    return split < 0 ? QString() : scopedName.left(split);
}

QString dotted(QString scopedName)
{
    return scopedName.replace(QLatin1String("::"), QLatin1String("."));
}

/// omniidl's Python POA module: `A::B` → `A__POA.B`; the global scope → `_GlobalIDL__POA`.
QString pythonPoaModule(const QString &module)
{
    if (module.isEmpty())
        return QStringLiteral("_GlobalIDL__POA");
    QStringList parts = module.split(QLatin1String("::"));
    parts.first() += QStringLiteral("__POA");
    return parts.join(QLatin1Char('.'));
}

QString baseNameOf(const QString &file)
{
    return QFileInfo(file).completeBaseName();
}

QString interfaceVariable(const RtcServiceInterface &iface)
{
    return iface.variableName && !iface.variableName->isEmpty() ? *iface.variableName : iface.name;
}

/// The interface's documentation as comment lines (one line per field that is set).
QStringList interfaceDocLines(const RtcServiceInterface &iface)
{
    QStringList lines;
    if (!iface.doc)
        return lines;
    appendDocLine(lines, QString(), iface.doc->description);
    appendDocLine(lines, QStringLiteral("- Argument"), iface.doc->docArgument);
    appendDocLine(lines, QStringLiteral("- Return"), iface.doc->docReturn);
    appendDocLine(lines, QStringLiteral("- Exception"), iface.doc->docException);
    appendDocLine(lines, QStringLiteral("- PreCondition"), iface.doc->docPreCondition);
    appendDocLine(lines, QStringLiteral("- PostCondition"), iface.doc->docPostCondition);
    return lines;
}

/// `string echo(in string msg)`: the IDL declaration, for comments above generated bodies.
QString idlSignature(const IdlOperation &op)
{
    QStringList params;
    for (const IdlParameter &p : op.parameters)
        params << IdlParameter::modeName(p.mode) + QLatin1Char(' ') + p.type.toString()
                + QLatin1Char(' ') + p.name;
    return QStringLiteral("%1 %2(%3)")
        .arg(op.returnType.toString(), op.name, params.join(QStringLiteral(", ")));
}

/// An operation a servant implements; attributes give `_get_x`/`_set_x` in Python.
struct ServedOperation
{
    IdlOperation operation;
    QString pythonName;
};

QVariantMap operationContext(const IdlModel &idl, const ServedOperation &served,
                             TargetLanguage language)
{
    const IdlOperation &op = served.operation;
    QVariantList params;
    QStringList declared;
    QStringList pythonIn;
    QStringList pythonOut;
    if (!op.returnType.isVoid())
        pythonOut << QStringLiteral("result");
    for (const IdlParameter &p : op.parameters) {
        const QString name = mappedIdlName(language, p.name);
        const QString type = language == TargetLanguage::Java ? javaParameterType(idl, p)
                                                              : cxxParameterType(idl, p);
        declared << type + QLatin1Char(' ') + name;
        if (p.mode != IdlParameter::Mode::Out)
            pythonIn << name;
        if (p.mode != IdlParameter::Mode::In)
            pythonOut << name;
        params << QVariantMap {{QStringLiteral("name"), name},
                               {QStringLiteral("type"), type},
                               {QStringLiteral("mode"), IdlParameter::modeName(p.mode)}};
    }
    QString returnType;
    QString returnStatement;
    if (language == TargetLanguage::Java) {
        returnType
            = op.returnType.isVoid() ? QStringLiteral("void") : javaTypeName(idl, op.returnType);
        if (!op.returnType.isVoid())
            returnStatement
                = QStringLiteral("return %1;").arg(javaDefaultValue(idl, op.returnType));
    } else {
        returnType = cxxReturnType(idl, op.returnType);
        returnStatement = cxxReturnStatement(idl, op.returnType);
    }
    return {{QStringLiteral("name"), op.name},
            {QStringLiteral("pythonName"), served.pythonName},
            {QStringLiteral("idlSignature"), idlSignature(op)},
            {QStringLiteral("returnType"), returnType},
            {QStringLiteral("returnStatement"), returnStatement},
            {QStringLiteral("hasReturnStatement"), !returnStatement.isEmpty()},
            {QStringLiteral("parameters"), declared.join(QStringLiteral(", "))},
            {QStringLiteral("pythonParameters"),
             (QStringList {QStringLiteral("self")} + pythonIn).join(QStringLiteral(", "))},
            {QStringLiteral("pythonResults"), pythonOut.join(QStringLiteral(", "))},
            {QStringLiteral("hasPythonResults"), !pythonOut.isEmpty()},
            {QStringLiteral("params"), markFirstLast(params)}};
}

/// Attributes are served by a getter and (unless read-only) a setter operation.
QList<ServedOperation> servedOperations(const IdlModel &idl, const QString &scopedName)
{
    QList<ServedOperation> operations;
    for (const IdlAttribute &attribute : idl.allAttributes(scopedName)) {
        IdlOperation getter;
        getter.name = attribute.name;
        getter.returnType = attribute.type;
        operations << ServedOperation {getter, QStringLiteral("_get_") + attribute.name};
        if (attribute.readonly)
            continue;
        IdlOperation setter;
        setter.name = attribute.name;
        setter.returnType = IdlType::basic(QStringLiteral("void"));
        IdlParameter value;
        value.type = attribute.type;
        value.name = QStringLiteral("value");
        setter.parameters << value;
        operations << ServedOperation {setter, QStringLiteral("_set_") + attribute.name};
    }
    for (const IdlOperation &op : idl.allOperations(scopedName))
        operations << ServedOperation {op, op.name};
    return operations;
}

QVariantMap interfaceTypeContext(const IdlModel &idl, const IdlInterface &iface,
                                 TargetLanguage language)
{
    const QString simple = simpleName(iface.scopedName);
    const QString module = scopeOf(iface.scopedName);
    QVariantList operations;
    for (const ServedOperation &op : servedOperations(idl, iface.scopedName))
        operations << operationContext(idl, op, language);
    QString topModule = module.section(QLatin1String("::"), 0, 0);
    if (topModule.isEmpty() && language == TargetLanguage::Python)
        topModule = QStringLiteral("_GlobalIDL"); // where omniidl puts global declarations
    QString native = iface.scopedName;
    QString className = simple + QStringLiteral("SVC_impl");
    QString poaClass = QStringLiteral("POA_") + iface.scopedName;
    const QString poaModule = pythonPoaModule(module);
    if (language == TargetLanguage::Python) {
        native = dotted(iface.scopedName);
        className = simple + QStringLiteral("_i");
        poaClass = poaModule + QLatin1Char('.') + simple;
    } else if (language == TargetLanguage::Java) {
        native = dotted(iface.scopedName);
        poaClass = native + QStringLiteral("POA");
    }
    return {{QStringLiteral("type"), iface.scopedName},
            {QStringLiteral("simpleName"), simple},
            {QStringLiteral("nativeType"), native},
            {QStringLiteral("className"), className},
            {QStringLiteral("poaClass"), poaClass},
            {QStringLiteral("module"), topModule},
            {QStringLiteral("poaModule"), poaModule},
            {QStringLiteral("idlBaseName"), baseNameOf(iface.source.file)},
            {QStringLiteral("idlFileName"), QFileInfo(iface.source.file).fileName()},
            {QStringLiteral("operations"), markFirstLast(operations)}};
}

/// The `#include` argument for the stubs of a type declared in `file` (C++ only).
QString cxxStubInclude(const QString &file)
{
    const QString base = baseNameOf(file);
    return ContextBuilder::isStandardIdl(QFileInfo(file).fileName())
        ? QStringLiteral("<rtm/idl/%1Skel.h>").arg(base)
        : QStringLiteral("\"%1.hh\"").arg(base);
}

QString declaringFile(const IdlModel &idl, const QString &type)
{
    if (const std::optional<IdlDeclaration> declaration = idl.find(stripScope(type)))
        return declaration->source.file;
    return {};
}

void appendUnique(QStringList &list, const QString &value)
{
    if (!value.isEmpty() && !list.contains(value))
        list << value;
}

} // namespace

bool ContextBuilder::isStandardIdl(const QString &fileName)
{
    static const QSet<QString> names = {QStringLiteral("BasicDataType.idl"),
                                        QStringLiteral("ExtendedDataTypes.idl"),
                                        QStringLiteral("InterfaceDataTypes.idl"),
                                        QStringLiteral("CameraCommonInterface.idl"),
                                        QStringLiteral("ManipulatorCommonInterface_Common.idl"),
                                        QStringLiteral("ManipulatorCommonInterface_DataTypes.idl"),
                                        QStringLiteral("ManipulatorCommonInterface_Middle.idl"),
                                        QStringLiteral("RTC.idl"),
                                        QStringLiteral("SDOPackage.idl"),
                                        QStringLiteral("OpenRTM.idl"),
                                        QStringLiteral("DataPort.idl"),
                                        QStringLiteral("DataPort_OpenRTM.idl"),
                                        QStringLiteral("Manager.idl"),
                                        QStringLiteral("ComponentObserver.idl"),
                                        QStringLiteral("ExtendedFsmService.idl"),
                                        QStringLiteral("Logger.idl"),
                                        QStringLiteral("SharedMemory.idl"),
                                        QStringLiteral("IORProfile.idl")};
    return names.contains(QFileInfo(fileName).fileName());
}

QStringList ContextBuilder::projectIdlFiles() const
{
    QStringList files;
    auto consider = [&](const QString &file) {
        if (!file.isEmpty() && !isStandardIdl(file))
            appendUnique(files, file);
    };
    for (const RtcDataPort &port : m_profile.dataPorts)
        consider(declaringFile(m_idl, port.type));
    for (const RtcServicePort &port : m_profile.servicePorts) {
        for (const RtcServiceInterface &iface : port.interfaces) {
            if (const IdlInterface *found = findInterface(m_idl, iface.type))
                consider(found->source.file);
        }
    }
    return files;
}

bool ContextBuilder::addServices(TargetLanguage language, QVariantMap &context,
                                 Diagnostics *diagnostics) const
{
    QVariantList ports, provided, required, idlGroups, interfaceTypes;
    QStringList includes, pythonModules, seenTypes;
    for (const RtcDataPort &port : m_profile.dataPorts) {
        const QString file = declaringFile(m_idl, port.type);
        appendUnique(includes,
                     cxxStubInclude(file.isEmpty()
                                        ? port.idlFile.value_or(QStringLiteral("BasicDataType.idl"))
                                        : file));
        appendUnique(pythonModules, stripScope(port.type).section(QLatin1String("::"), 0, 0));
    }
    for (const RtcServicePort &port : m_profile.servicePorts) {
        QVariantList portInterfaces;
        for (const RtcServiceInterface &iface : port.interfaces) {
            const IdlInterface *type = findInterface(m_idl, iface.type);
            if (!type) {
                Diagnostic d = Diagnostic::error(
                    QString(), 0, 0,
                    QStringLiteral("service port '%1', interface '%2': type '%3' is not declared "
                                   "in any parsed IDL file")
                        .arg(port.name, iface.name, iface.type));
                d.object = iface.name;
                diagnostics->append(d);
                continue;
            }
            QVariantMap item = interfaceTypeContext(m_idl, *type, language);
            const bool isProvided = iface.kind() == RtcDirection::Provided;
            item.insert(QStringLiteral("portName"), port.name);
            item.insert(QStringLiteral("name"), iface.name);
            item.insert(QStringLiteral("instanceName"),
                        escapeStringLiteral(iface.instanceName && !iface.instanceName->isEmpty()
                                                ? *iface.instanceName
                                                : iface.name));
            item.insert(QStringLiteral("variable"), interfaceVariable(iface));
            item.insert(QStringLiteral("docLines"), interfaceDocLines(iface));
            item.insert(QStringLiteral("provided"), isProvided);
            item.insert(QStringLiteral("required"), !isProvided);
            portInterfaces << item;
            const QString module = item.value(QStringLiteral("module")).toString();
            appendUnique(pythonModules, module);
            if (!isProvided) {
                required << item;
                appendUnique(includes, cxxStubInclude(type->source.file));
                continue;
            }
            provided << item;
            appendUnique(pythonModules, item.value(QStringLiteral("poaModule")).toString());
            if (seenTypes.contains(type->scopedName))
                continue;
            seenTypes << type->scopedName;
            interfaceTypes << item;
            const QString base = item.value(QStringLiteral("idlBaseName")).toString();
            auto group = std::find_if(idlGroups.begin(), idlGroups.end(), [&](const QVariant &g) {
                return g.toMap().value(QStringLiteral("idlBaseName")) == base;
            });
            if (group == idlGroups.end()) {
                idlGroups << QVariantMap {
                    {QStringLiteral("idlBaseName"), base},
                    {QStringLiteral("idlGuard"), base.toUpper()},
                    {QStringLiteral("idlFileName"), item.value(QStringLiteral("idlFileName"))},
                    {QStringLiteral("interfaces"), QVariantList {}}};
                group = idlGroups.end() - 1;
            }
            QVariantMap g = group->toMap();
            g[QStringLiteral("interfaces")] = g.value(QStringLiteral("interfaces")).toList()
                << item;
            *group = g;
        }
        const RtcServicePortDoc portDoc = port.doc.value_or(RtcServicePortDoc());
        QStringList portDocLines;
        appendDocLine(portDocLines, QString(), portDoc.description);
        appendDocLine(portDocLines, QStringLiteral("Interface"), portDoc.ifdescription);
        ports << QVariantMap {{QStringLiteral("docLines"), portDocLines},
                              {QStringLiteral("name"), port.name},
                              {QStringLiteral("literalName"), escapeStringLiteral(port.name)},
                              {QStringLiteral("interfaces"), markFirstLast(portInterfaces)}};
    }
    if (hasErrors(*diagnostics))
        return false;
    QVariantList providedIncludes;
    for (const QVariant &g : std::as_const(idlGroups)) {
        QVariantMap map = g.toMap();
        map[QStringLiteral("interfaces")]
            = markFirstLast(map.value(QStringLiteral("interfaces")).toList());
        providedIncludes << map;
    }
    QVariantList projectIdls;
    for (const QString &file : projectIdlFiles())
        projectIdls << QVariantMap {{QStringLiteral("fileName"), QFileInfo(file).fileName()},
                                    {QStringLiteral("baseName"), baseNameOf(file)}};
    pythonModules.removeAll(QString());
    pythonModules.sort();
    context.insert(QStringLiteral("servicePorts"), markFirstLast(ports));
    context.insert(QStringLiteral("providedInterfaces"), markFirstLast(provided));
    context.insert(QStringLiteral("requiredInterfaces"), markFirstLast(required));
    context.insert(QStringLiteral("providedIdls"), markFirstLast(providedIncludes));
    context.insert(QStringLiteral("providedInterfaceTypes"), markFirstLast(interfaceTypes));
    context.insert(QStringLiteral("projectIdls"), markFirstLast(projectIdls));
    context.insert(QStringLiteral("cxxIncludes"), includes);
    context.insert(QStringLiteral("pythonModules"), pythonModules);
    context.insert(QStringLiteral("hasServicePorts"), !ports.isEmpty());
    context.insert(QStringLiteral("hasProvided"), !provided.isEmpty());
    context.insert(QStringLiteral("hasRequired"), !required.isEmpty());
    context.insert(QStringLiteral("hasProjectIdls"), !projectIdls.isEmpty());
    return true;
}

} // namespace Codegen
