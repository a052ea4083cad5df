// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "idlmodel.h"
#include "rtcprofile.h"
#include "targetlanguage.h"

#include <QVariantMap>

#include <optional>

namespace Codegen {

/**
 * Turns an RTC Profile and the parsed IDL into the render context of one target language.
 * Everything the templates print is decided here (names, C++/Python/Java types, module spec
 * lines, escaped literals, which callbacks are implemented); templates only loop and branch.
 *
 * Keys of the context (lists of maps unless noted; every list item has `first`/`last` flags):
 * - scalars: `name`, `nameUpper`, `description`, `version`, `vendor`, `category`, `componentType`,
 *   `activityType`, `componentKind`, `maxInstances`, `executionType`, `executionRate`,
 *   `languageKind`, `langType`, `cmakeVersion`, `creator`, `license`, `updateDate`
 * - `moduleSpec` {key, value, literalKey, literalValue}: the RTC module specification, in order
 * - `actions` {name, upperName, implemented (bool), description, docLines}: the 12 editable
 *   callbacks; `docLines` (strings) are the documentation comment lines of components, ports,
 *   interfaces, callbacks and configuration parameters (only the fields that are set)
 * - `inPorts`, `outPorts` {name, type, variable, nativeType, init, module, idlFile, description}
 * - `servicePorts` {name, variable, provided, required}; `providedInterfaces`,
 *   `requiredInterfaces` {portName, name, instanceName, variable, type, nativeType, className,
 *   idlBaseName, module, poaModule}
 * - `providedIdls` {idlBaseName, idlFileName, interfaces {name, type, nativeType, className,
 *   poaClass, module, poaModule, operations {name, returnType, parameters, parameterNames,
 *   returnStatement, signature, params {name, type, mode}}}}
 * - `providedInterfaceTypes`: the same interface maps, one per interface type (Java servants)
 * - `configurations` {name, type, nativeType, variable, defaultValue, literalDefault, init,
 *   holder, widget, constraint, unit, description}
 * - `projectIdls` {fileName, baseName}: non-standard IDL files copied into `idl/`
 * - `pythonModules` (strings): modules the Python code imports
 * - `vectorConvertHeaders` (C++): one empty item when a configuration parameter is a vector
 *   (the manifest renders VectorConvert.h once per item), else none
 * - C++ with EventPorts (`hasFsm`): `fsmFiles` (one empty item, renders <Name>Fsm.h/.cpp),
 *   `fsmNamespace`, `fsmMachineType`, `fsmInitialState` (the first event's source),
 *   `fsmEvents` {name, hasArgument, argumentType}: the machine's event protocol,
 *   `fsmGuards` {name, hasArgument, argumentType, conditions}: one per transition condition,
 *   `fsmStates` {name, handlers, declaredHandlers {event, target, hasArgument, argumentType,
 *   guard, hasGuard, opens, closes}}, `eventPorts` {name, literalName, variable, events {name,
 *   literalName}}; `actions` then has onExecute implemented with `runsFsm`
 * - flags: `hasInPorts`, `hasOutPorts`, `hasDataPorts`, `hasServicePorts`, `hasProvided`,
 *   `hasRequired`, `hasConfigurations`, `hasProjectIdls`, `hasVectorConfigurations` (C++)
 */
class ContextBuilder
{
public:
    ContextBuilder(const Profile::RtcProfile &profile, const IdlModel &idl);

    /// The context for `language`; nothing (plus errors in `diagnostics`) when a name cannot be
    /// used in that language or a service interface type is not declared in the IDL.
    std::optional<QVariantMap> build(TargetLanguage language,
                                     Profile::Diagnostics *diagnostics) const;

    /// The IDL files (as read by the parser) of the types the profile references that are not
    /// part of OpenRTM's own IDL set; the generator copies them into `idl/`.
    QStringList projectIdlFiles() const;

    /// True for the IDL files OpenRTM-aist installs itself (BasicDataType.idl …).
    static bool isStandardIdl(const QString &fileName);

private:
    QVariantMap basics(TargetLanguage language) const;
    QVariantList moduleSpec(TargetLanguage language) const;
    QVariantList actions() const;
    QVariantList dataPorts(TargetLanguage language, Profile::RtcPortType kind) const;
    QVariantList configurations(TargetLanguage language) const;
    /// One entry per Java holder class the `vector<T>` configuration parameters need.
    QVariantList javaVectorHolders() const;
    /// True when a configuration parameter is a `vector<T>`.
    bool hasVectorConfiguration() const;
    bool checkNames(TargetLanguage language, Profile::Diagnostics *diagnostics) const;
    bool addServices(TargetLanguage language, QVariantMap &context,
                     Profile::Diagnostics *diagnostics) const;
    /// The static FSM of the EventPorts (fsmcontext.cpp); refuses events whose names cannot
    /// name handlers or states.
    bool addFsm(TargetLanguage language, QVariantMap &context,
                Profile::Diagnostics *diagnostics) const;

    const Profile::RtcProfile &m_profile;
    const IdlModel &m_idl;
};

/// Appends `label: text` (just `text` when `label` is empty) to `lines` when `text` is not blank,
/// as one line that is safe inside `//`, `#` and `/* */` comments.
void appendDocLine(QStringList &lines, const QString &label, const std::optional<QString> &text);

/// `text` as the inside of a C, Java or Python string literal (`"` `\` and control characters
/// escaped).
QString escapeStringLiteral(const QString &text);

/// Sets `first` and `last` on every map of the list, so templates can place separators.
QVariantList markFirstLast(QVariantList items);

} // namespace Codegen
