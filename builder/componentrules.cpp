// SPDX-License-Identifier: MIT
#include "componentrules.h"

#include "builderfieldrules.h"
#include "constraintsyntax.h"
#include "rtcvalidator.h"

#include <QCoreApplication>

namespace Builder {

namespace {

using namespace Profile;

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Builder::ComponentRules)
};

void add(FieldProblems &problems, const QString &field, const QString &message)
{
    if (!message.isEmpty() && !problems.contains(field))
        problems.insert(field, message);
}

/// Every port name of the component with what it belongs to, in list order.
struct NameUse
{
    Part part;
    int index;
    int interfaceIndex;
};

QString describe(const RtcProfile &profile, const NameUse &use)
{
    if (use.interfaceIndex >= 0) {
        const RtcServicePort &port = profile.servicePorts.at(use.index);
        return Text::tr("interface %1 of %2").arg(port.interfaces.at(use.interfaceIndex).name, port.name);
    }
    if (use.part == Part::Configuration)
        return Text::tr("configuration parameter %1").arg(profile.configurations.at(use.index).name);
    return Text::tr("%1 #%2").arg(partLabel(use.part)).arg(use.index + 1);
}

/// Port names of data and service ports share one name space.
QString duplicatePortName(const RtcProfile &profile, Part part, int index)
{
    const QString name = part == Part::DataPort ? profile.dataPorts.at(index).name
                                                : profile.servicePorts.at(index).name;
    if (name.isEmpty())
        return {};
    QList<NameUse> uses;
    for (int i = 0; i < profile.dataPorts.size(); ++i) {
        if (profile.dataPorts.at(i).name == name && !(part == Part::DataPort && i == index))
            uses.append({Part::DataPort, i, -1});
    }
    for (int i = 0; i < profile.servicePorts.size(); ++i) {
        if (profile.servicePorts.at(i).name == name && !(part == Part::ServicePort && i == index))
            uses.append({Part::ServicePort, i, -1});
    }
    if (uses.isEmpty())
        return {};
    return Text::tr("The port name '%1' is already used by %2.")
        .arg(name, describe(profile, uses.first()));
}

/// Variable names of ports, interfaces and parameters become members of one class.
QString duplicateVariable(const RtcProfile &profile, const QString &variable, const NameUse &self)
{
    if (variable.isEmpty())
        return {};
    const auto same = [&](const NameUse &use) {
        return use.part == self.part && use.index == self.index
            && use.interfaceIndex == self.interfaceIndex;
    };
    QList<NameUse> uses;
    for (int i = 0; i < profile.dataPorts.size(); ++i) {
        if (profile.dataPorts.at(i).variableName == variable)
            uses.append({Part::DataPort, i, -1});
    }
    for (int i = 0; i < profile.servicePorts.size(); ++i) {
        const auto &interfaces = profile.servicePorts.at(i).interfaces;
        for (int j = 0; j < interfaces.size(); ++j) {
            if (interfaces.at(j).variableName == variable)
                uses.append({Part::ServicePort, i, j});
        }
    }
    for (int i = 0; i < profile.configurations.size(); ++i) {
        if (profile.configurations.at(i).variableName == variable)
            uses.append({Part::Configuration, i, -1});
    }
    for (const NameUse &use : uses) {
        if (!same(use))
            return Text::tr("The variable name '%1' is already used by %2.")
                .arg(variable, describe(profile, use));
    }
    return {};
}

FieldProblems dataPortProblems(const RtcProfile &profile, int index)
{
    const RtcDataPort &port = profile.dataPorts.at(index);
    FieldProblems problems;
    add(problems, QStringLiteral("name"), FieldRules::componentNameProblem(port.name));
    add(problems, QStringLiteral("name"), duplicatePortName(profile, Part::DataPort, index));
    add(problems, QStringLiteral("type"), FieldRules::requiredProblem(port.type));
    add(problems, QStringLiteral("position"),
        FieldRules::enumerationProblem(port.position, rtcPositions()));
    const QString variable = port.variableName.value_or(QString());
    add(problems, QStringLiteral("variableName"), FieldRules::identifierProblem(variable));
    add(problems, QStringLiteral("variableName"),
        duplicateVariable(profile, variable, {Part::DataPort, index, -1}));
    return problems;
}

FieldProblems servicePortProblems(const RtcProfile &profile, int index)
{
    const RtcServicePort &port = profile.servicePorts.at(index);
    FieldProblems problems;
    add(problems, QStringLiteral("name"), FieldRules::componentNameProblem(port.name));
    add(problems, QStringLiteral("name"), duplicatePortName(profile, Part::ServicePort, index));
    add(problems, QStringLiteral("position"),
        FieldRules::enumerationProblem(port.position, rtcPositions()));
    return problems;
}

QString widgetProblem(const RtcConfiguration &configuration)
{
    const QString widget = configuration.widget().value_or(QString());
    if (widget.isEmpty())
        return {};
    const QString kind = widget.section(QLatin1Char('.'), 0, 0);
    if (!configurationWidgets().contains(kind))
        return FieldRules::enumerationProblem(kind, configurationWidgets());
    const QString step = widget.section(QLatin1Char('.'), 1);
    if (!step.isEmpty() && (kind == QLatin1String("slider") || kind == QLatin1String("spin"))) {
        const QString problem = FieldRules::nonNegativeNumberProblem(step);
        if (!problem.isEmpty())
            return Text::tr("The step of a %1 must be a number of 0 or more.").arg(kind);
    }
    if (kind == QLatin1String("radio")
        && !(configuration.constraint && isEnumerationConstraint(*configuration.constraint)))
        return Text::tr("A radio widget needs an enumeration constraint such as (a,b,c).");
    return {};
}

FieldProblems configurationProblems(const RtcProfile &profile, int index)
{
    const RtcConfiguration &configuration = profile.configurations.at(index);
    FieldProblems problems;
    add(problems, QStringLiteral("name"), FieldRules::componentNameProblem(configuration.name));
    for (int i = 0; i < profile.configurations.size(); ++i) {
        if (i != index && !configuration.name.isEmpty()
            && profile.configurations.at(i).name == configuration.name) {
            add(problems, QStringLiteral("name"),
                Text::tr("The parameter name '%1' is already used by parameter #%2.")
                    .arg(configuration.name)
                    .arg(i + 1));
        }
    }
    add(problems, QStringLiteral("type"), FieldRules::requiredProblem(configuration.type));
    add(problems, QStringLiteral("defaultValue"),
        FieldRules::requiredProblem(configuration.defaultValue));
    const QString variable = configuration.variableName.value_or(QString());
    add(problems, QStringLiteral("variableName"), FieldRules::identifierProblem(variable));
    add(problems, QStringLiteral("variableName"),
        duplicateVariable(profile, variable, {Part::Configuration, index, -1}));
    add(problems, QStringLiteral("widget"), widgetProblem(configuration));
    return problems;
}

} // namespace

FieldProblems itemProblems(const RtcProfile &profile, Part part, int index)
{
    switch (part) {
    case Part::DataPort:
        return dataPortProblems(profile, index);
    case Part::ServicePort:
        return servicePortProblems(profile, index);
    case Part::Configuration:
        break;
    }
    return configurationProblems(profile, index);
}

FieldProblems interfaceProblems(const RtcProfile &profile, int portIndex, int interfaceIndex)
{
    const RtcServicePort &port = profile.servicePorts.at(portIndex);
    const RtcServiceInterface &interface = port.interfaces.at(interfaceIndex);
    FieldProblems problems;
    add(problems, QStringLiteral("name"), FieldRules::componentNameProblem(interface.name));
    for (int i = 0; i < port.interfaces.size(); ++i) {
        if (i != interfaceIndex && !interface.name.isEmpty()
            && port.interfaces.at(i).name == interface.name) {
            add(problems, QStringLiteral("name"),
                Text::tr("The interface name '%1' is already used in this port.").arg(interface.name));
        }
    }
    add(problems, QStringLiteral("direction"),
        FieldRules::enumerationProblem(interface.direction, rtcDirections()));
    add(problems, QStringLiteral("type"), FieldRules::requiredProblem(interface.type));
    const QString variable = interface.variableName.value_or(QString());
    add(problems, QStringLiteral("variableName"), FieldRules::identifierProblem(variable));
    add(problems, QStringLiteral("variableName"),
        duplicateVariable(profile, variable, {Part::ServicePort, portIndex, interfaceIndex}));
    return problems;
}

QString compositePortsProblem(const RtcProfile &profile)
{
    if (!profile.basicInfo.category.startsWith(QLatin1String("composite.")))
        return {};
    if (profile.dataPorts.isEmpty() && profile.servicePorts.isEmpty())
        return {};
    return Text::tr("A composite component (category '%1') may have no ports.")
        .arg(profile.basicInfo.category);
}

const QStringList &configurationWidgets()
{
    static const QStringList widgets {
        QStringLiteral("text"),  QStringLiteral("slider"),   QStringLiteral("spin"),
        QStringLiteral("radio"), QStringLiteral("checkbox"), QStringLiteral("ordered_list"),
    };
    return widgets;
}

Diagnostics generationProblems(const RtcProfile &profile)
{
    Diagnostics result;
    for (const Diagnostic &d : validateRtcProfile(profile, QString())) {
        if (d.severity == Diagnostic::Severity::Error)
            result.append(d);
    }
    const auto report = [&](const QString &object, const FieldProblems &problems) {
        for (auto it = problems.cbegin(); it != problems.cend(); ++it) {
            Diagnostic d = Diagnostic::error(QString(), 0, 0, it.value());
            d.object = object;
            if (!result.contains(d))
                result.append(d);
        }
    };
    if (const QString composite = compositePortsProblem(profile); !composite.isEmpty())
        report(Text::tr("component"), {{QStringLiteral("category"), composite}});
    for (Part part : {Part::DataPort, Part::ServicePort, Part::Configuration}) {
        const int count = part == Part::DataPort ? profile.dataPorts.size()
            : part == Part::ServicePort          ? profile.servicePorts.size()
                                                 : profile.configurations.size();
        for (int i = 0; i < count; ++i)
            report(Text::tr("%1 #%2").arg(partLabel(part)).arg(i + 1), itemProblems(profile, part, i));
    }
    for (int p = 0; p < profile.servicePorts.size(); ++p) {
        for (int i = 0; i < profile.servicePorts.at(p).interfaces.size(); ++i)
            report(Text::tr("interface %1 of %2")
                       .arg(profile.servicePorts.at(p).interfaces.at(i).name,
                            profile.servicePorts.at(p).name),
                   interfaceProblems(profile, p, i));
    }
    return result;
}

} // namespace Builder
