// SPDX-License-Identifier: MIT
#pragma once
// Internal to the rtprofile library: the field table of each RTS Profile element. The XML reader
// and writer (rtsxml*.cpp) and the YAML reader and writer (rtsyaml*.cpp) all walk these tables;
// adding a field to an element means adding its row here.
//
// Row order is the YAML key order and the order readers look fields up in. The XML writer puts
// the rts attributes before the rtsExt ones (the extension types add theirs after the base
// type's) and child rows marked firstInXml() before the others, as the schema wants.
//
// Every element also has `extras`, `yamlExtras` and `location`, which the walkers fill
// themselves. The RTS YAML reader knows legacy keys (withYamlLegacyKeys) on scalar rows only, and
// tries them before the schema's key.

#include "fieldtable_p.h"
#include "namespaces.h"
#include "rtsprofile.h"

namespace Profile::Fields {

/// The field table of an RTS Profile element: `static constexpr auto fields`, a tuple of rows.
template<typename T> struct RtsElement;

/// rtsprofile writes the direction in lower case; the schema's values are upper case.
inline QString normalizedDirection(const QString &text)
{
    const QString upper = text.trimmed().toUpper();
    return RtsLocation::directions().contains(upper) ? upper : text;
}

template<typename Owner> constexpr auto properties(RtsProperties Owner::*member)
{
    return list(member, Ns::RtsExt, "Properties", "rtsExt::properties");
}

template<typename Owner, typename Member>
constexpr auto targetComponents(Member Owner::*member, const char *xmlName, const char *yamlKey)
{
    return list(member, Ns::Rts, xmlName, yamlKey).withXsiType(Ns::RtsExt, "target_component_ext");
}

/// What target_port and target_executioncontext add to target_component comes after its fields.
inline constexpr auto targetComponentFields = std::make_tuple(
    text(&RtsTargetComponent::componentId, Ns::Rts, "componentId", "componentId"),
    text(&RtsTargetComponent::instanceName, Ns::Rts, "instanceName", "instanceName"),
    properties(&RtsTargetComponent::properties));

/// The fields data-port and service-port connectors share, before their own.
inline constexpr auto connectorFields = std::make_tuple(
    text(&RtsPortConnector::connectorId, Ns::Rts, "connectorId", "connectorId"),
    text(&RtsPortConnector::name, Ns::Rts, "name", "name"),
    text(&RtsPortConnector::comment, Ns::RtsExt, "comment", "rtsExt::comment"),
    boolean(&RtsPortConnector::visible, Ns::RtsExt, "visible", "rtsExt::visible"));

/// A connector end; the YAML message reads "the connector lacks 'sourceDataPort'".
constexpr auto connectorEnd(RtsTargetPort RtsPortConnector::*member, const char *name)
{
    return element(member, Ns::Rts, name, name)
        .withXsiType(Ns::RtsExt, "target_port_ext")
        .missingInYaml(QT_TRANSLATE_NOOP("Profile::RtsYaml", "the connector lacks '%1'"));
}

template<> struct RtsElement<RtsProperty>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtsProperty::name, Ns::RtsExt, "name", "name"),
                          text(&RtsProperty::value, Ns::RtsExt, "value", "value"));
};

template<> struct RtsElement<RtsTargetComponent>
{
    static constexpr auto fields = targetComponentFields;
};

template<> struct RtsElement<RtsTargetPort>
{
    static constexpr auto fields = std::tuple_cat(
        targetComponentFields,
        std::make_tuple(text(&RtsTargetPort::portName, Ns::Rts, "portName", "portName")));
};

template<> struct RtsElement<RtsTargetExecutionContext>
{
    static constexpr auto fields = std::tuple_cat(
        targetComponentFields,
        std::make_tuple(text(&RtsTargetExecutionContext::id, Ns::Rts, "id", "id")));
};

template<> struct RtsElement<RtsPort>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtsPort::name, Ns::Rts, "name", "name"),
                          text(&RtsPort::comment, Ns::RtsExt, "comment", "rtsExt::comment"),
                          boolean(&RtsPort::visible, Ns::RtsExt, "visible", "rtsExt::visible"),
                          properties(&RtsPort::properties));
};

template<> struct RtsElement<RtsConfigurationData>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtsConfigurationData::name, Ns::Rts, "name", "name"),
                          text(&RtsConfigurationData::data, Ns::Rts, "data", "data"));
};

template<> struct RtsElement<RtsConfigurationSet>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtsConfigurationSet::id, Ns::Rts, "id", "id"),
        list(&RtsConfigurationSet::data, Ns::Rts, "ConfigurationData", "configurationData"));
};

template<> struct RtsElement<RtsExecutionContext>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtsExecutionContext::id, Ns::Rts, "id", "id"),
        text(&RtsExecutionContext::kind, Ns::Rts, "kind", "kind"),
        number(&RtsExecutionContext::rate, Ns::Rts, "rate", "rate"),
        targetComponents(&RtsExecutionContext::participants, "Participants", "participants"),
        properties(&RtsExecutionContext::properties));
};

template<> struct RtsElement<RtsParticipant>
{
    static constexpr auto fields = std::make_tuple(
        element(&RtsParticipant::participant, Ns::Rts, "Participant", "participant")
            .withXsiType(Ns::RtsExt, "target_component_ext")
            .missingInYaml(
                QT_TRANSLATE_NOOP("Profile::RtsYaml", "a participant lacks its '%1' mapping")));
};

template<> struct RtsElement<RtsLocation>
{
    static constexpr auto fields
        = std::make_tuple(number(&RtsLocation::x, Ns::RtsExt, "x", "x"),
                          number(&RtsLocation::y, Ns::RtsExt, "y", "y"),
                          number(&RtsLocation::height, Ns::RtsExt, "height", "height"),
                          number(&RtsLocation::width, Ns::RtsExt, "width", "width"),
                          text(&RtsLocation::direction, Ns::RtsExt, "direction", "direction")
                              .normalizedBy(&normalizedDirection));
};

template<> struct RtsElement<RtsComponent>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtsComponent::id, Ns::Rts, "id", "id"),
        text(&RtsComponent::pathUri, Ns::Rts, "pathUri", "pathUri"),
        text(&RtsComponent::instanceName, Ns::Rts, "instanceName", "instanceName"),
        text(&RtsComponent::activeConfigurationSet, Ns::Rts, "activeConfigurationSet",
             "activeConfigurationSet"),
        text(&RtsComponent::compositeType, Ns::Rts, "compositeType", "compositeType"),
        boolean(&RtsComponent::isRequired, Ns::Rts, "isRequired", "isRequired"),
        text(&RtsComponent::comment, Ns::RtsExt, "comment", "rtsExt::comment"),
        boolean(&RtsComponent::visible, Ns::RtsExt, "visible", "rtsExt::visible"),
        list(&RtsComponent::dataPorts, Ns::Rts, "DataPorts", "dataPorts")
            .withXsiType(Ns::RtsExt, "dataport_ext"),
        list(&RtsComponent::servicePorts, Ns::Rts, "ServicePorts", "servicePorts")
            .withXsiType(Ns::RtsExt, "serviceport_ext"),
        list(&RtsComponent::configurationSets, Ns::Rts, "ConfigurationSets", "configurationSets"),
        list(&RtsComponent::executionContexts, Ns::Rts, "ExecutionContexts", "executionContexts")
            .withXsiType(Ns::RtsExt, "execution_context_ext"),
        list(&RtsComponent::participants, Ns::Rts, "Participants", "participants"),
        optionalElement(&RtsComponent::layout, Ns::RtsExt, "Location", "rtsExt::location"),
        properties(&RtsComponent::properties));
};

template<> struct RtsElement<RtsGroup>
{
    static constexpr auto fields = std::make_tuple(
        // rtsprofile writes groupID (a converted YAML file may carry it too).
        text(&RtsGroup::groupId, Ns::Rts, "groupId", "groupId")
            .withXmlLegacyName("groupID")
            .withYamlLegacyKeys("groupID"),
        targetComponents(&RtsGroup::members, "Members", "members"));
};

template<> struct RtsElement<RtsDataPortConnector>
{
    static constexpr auto fields = std::tuple_cat(
        connectorFields,
        std::make_tuple(
            text(&RtsDataPortConnector::dataType, Ns::Rts, "dataType", "dataType"),
            text(&RtsDataPortConnector::interfaceType, Ns::Rts, "interfaceType", "interfaceType"),
            text(&RtsDataPortConnector::dataflowType, Ns::Rts, "dataflowType", "dataflowType"),
            text(&RtsDataPortConnector::subscriptionType, Ns::Rts, "subscriptionType",
                 "subscriptionType"),
            number(&RtsDataPortConnector::pushInterval, Ns::Rts, "pushInterval", "pushInterval"),
            connectorEnd(&RtsPortConnector::source, "sourceDataPort"),
            connectorEnd(&RtsPortConnector::target, "targetDataPort"),
            properties(&RtsPortConnector::properties)));
};

template<> struct RtsElement<RtsServicePortConnector>
{
    static constexpr auto fields = std::tuple_cat(
        connectorFields,
        std::make_tuple(
            text(&RtsServicePortConnector::transMethod, Ns::Rts, "transMethod", "transMethod"),
            connectorEnd(&RtsPortConnector::source, "sourceServicePort"),
            connectorEnd(&RtsPortConnector::target, "targetServicePort"),
            properties(&RtsPortConnector::properties)));
};

template<> struct RtsElement<RtsWaitTime>
{
    static constexpr auto fields
        = std::make_tuple(number(&RtsWaitTime::waitTime, Ns::Rts, "waitTime", "waitTime"));
};

template<> struct RtsElement<RtsPreceding>
{
    static constexpr auto fields = std::make_tuple(
        number(&RtsPreceding::timeout, Ns::Rts, "timeout", "timeout"),
        text(&RtsPreceding::sendingTiming, Ns::Rts, "sendingTiming", "sendingTiming"),
        list(&RtsPreceding::precedingComponents, Ns::Rts, "PrecedingComponents",
             "precedingComponents"));
};

template<> struct RtsElement<RtsCondition>
{
    static constexpr auto fields = std::make_tuple(
        number(&RtsCondition::sequence, Ns::Rts, "sequence", "sequence"),
        element(&RtsCondition::targetComponent, Ns::Rts, "TargetComponent", "targetComponent")
            .missingInYaml(
                QT_TRANSLATE_NOOP("Profile::RtsYaml", "a message-sequence target lacks '%1'")),
        // YAML: `condition: {waitTime: {…}}` or `{preceding: {…}}`; the schema's choice comes
        // before TargetComponent in XML.
        yamlGroup(
            "condition",
            optionalElement(&RtsCondition::waitTime, Ns::Rts, "WaitTime", "waitTime").firstInXml(),
            optionalElement(&RtsCondition::preceding, Ns::Rts, "Preceding", "preceding")
                .firstInXml()),
        properties(&RtsCondition::properties));
};

template<> struct RtsElement<RtsMessageSequence>
{
    static constexpr auto fields
        = std::make_tuple(list(&RtsMessageSequence::targets, Ns::Rts, "targets", "targets")
                              .withXsiType(Ns::RtsExt, "condition_ext"));
};

template<> struct RtsElement<RtsSystemPath>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtsSystemPath::path, Ns::RtsExt, "path", "path"));
};

template<> struct RtsElement<RtsProfile>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtsProfile::id, Ns::Rts, "id", "id"),
        text(&RtsProfile::version, Ns::Rts, "version", "version"),
        text(&RtsProfile::abstract, Ns::Rts, "abstract", "abstract"),
        date(&RtsProfile::creationDate, Ns::Rts, "creationDate", "creationDate"),
        date(&RtsProfile::updateDate, Ns::Rts, "updateDate", "updateDate"),
        text(&RtsProfile::comment, Ns::RtsExt, "comment", "rtsExt::comment"),
        list(&RtsProfile::components, Ns::Rts, "Components", "components")
            .withXsiType(Ns::RtsExt, "component_ext"),
        list(&RtsProfile::groups, Ns::Rts, "Groups", "groups"),
        list(&RtsProfile::dataPortConnectors, Ns::Rts, "DataPortConnectors", "dataPortConnectors")
            .withXsiType(Ns::RtsExt, "dataport_connector_ext"),
        list(&RtsProfile::servicePortConnectors, Ns::Rts, "ServicePortConnectors",
             "servicePortConnectors")
            .withXsiType(Ns::RtsExt, "serviceport_connector_ext"),
        // The message sequences, in schema order; a second block of one kind stays in the extras.
        optionalElement(&RtsProfile::startUp, Ns::Rts, "StartUp", "startUp"),
        optionalElement(&RtsProfile::shutDown, Ns::Rts, "ShutDown", "shutDown"),
        optionalElement(&RtsProfile::activation, Ns::Rts, "Activation", "activation"),
        optionalElement(&RtsProfile::deactivation, Ns::Rts, "Deactivation", "deactivation"),
        optionalElement(&RtsProfile::resetting, Ns::Rts, "Resetting", "resetting"),
        optionalElement(&RtsProfile::initializing, Ns::Rts, "Initializing", "initializing"),
        optionalElement(&RtsProfile::finalizing, Ns::Rts, "Finalizing", "finalizing"),
        textList(&RtsProfile::versionUpLogs, Ns::RtsExt, "VersionUpLogs", "rtsExt::versionUpLogs")
            .withXmlLegacyName("VersionUpLog"),
        properties(&RtsProfile::properties),
        list(&RtsProfile::systems, Ns::RtsExt, "Systems", "rtsExt::systems"));
};

} // namespace Profile::Fields
