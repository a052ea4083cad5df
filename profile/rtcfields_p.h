// SPDX-License-Identifier: MIT
#pragma once
// Internal to the rtprofile library: the field table of each RTC Profile element, walked by the
// XML and YAML readers and writers (rtcxml*.cpp, rtcyaml*.cpp). Adding a field to an element means
// adding its row here.
//
// Row order is the order the readers look fields up in and the XML writer writes them (the
// schema's); the YAML writer sorts keys by their local name, as RTC Builder does. The YAML keys
// are those RTC Builder writes, the legacy ones those older files have.
//
// The RTC walkers differ from the RTS ones in how they treat a required field: a missing one is
// a warning, its name is recorded in the element's `missing` list, and the writers leave it out
// again while it is still empty.

#include "fieldtable_p.h"
#include "namespaces.h"
#include "rtcprofile.h"
#include "rtcxmlinternal.h"

namespace Profile::Fields {

/// The field table of an RTC Profile element: `static constexpr auto fields`, a tuple of rows.
template<typename T> struct RtcElement;

// The parts with walker code of their own (see Special).
struct RtcProfileVersion; ///< read as it is, always written as RtcProfile::CurrentVersion
struct RtcConfigurationSet; ///< the rtc:ConfigurationSet wrapper of RtcProfile::configurations
struct RtcActionStatuses; ///< rtc:OnInitialize … rtc:OnModeChanged, one per RtcAction
struct RtcConstraintTree; ///< rtc:Constraint, a recursive tree (rtcxmlconstraint.cpp)

template<typename Owner> constexpr auto rtcProperties(RtcProperties Owner::*member)
{
    return list(member, Ns::RtcExt, "Properties", "rtcExt::properties")
        .withYamlLegacyKeys("properties");
}

template<typename Owner, typename Doc> constexpr auto rtcDoc(std::optional<Doc> Owner::*member)
{
    return optionalElement(member, Ns::RtcDoc, "Doc", "rtcDoc::doc").withYamlLegacyKeys("doc");
}

template<typename Owner> constexpr auto rtcComment(std::optional<QString> Owner::*member)
{
    return text(member, Ns::RtcExt, "comment", "rtcExt::comment").withYamlLegacyKeys("comment");
}

/// 0.2+ writes rtcExt:variableName; the 0.1 templates wrote varname in either namespace.
template<typename Owner> constexpr auto rtcVariableName(std::optional<QString> Owner::*member)
{
    return text(member, Ns::RtcExt, "variableName", "rtcExt::variableName")
        .withXmlLegacyName("varname", Ns::Rtc)
        .withYamlLegacyKeys("variableName", "varname");
}

template<typename Owner> constexpr auto rtcPosition(QString Owner::*member)
{
    return text(member, Ns::RtcExt, "position", "rtcExt::position")
        .withYamlLegacyKeys("position")
        .normalizedBy(&RtcXml::normalizedPosition);
}

/// An rtcDoc attribute, which the dialect's YAML keys spell without prefix.
template<typename Owner>
constexpr auto docText(std::optional<QString> Owner::*member, const char *name)
{
    return text(member, Ns::RtcDoc, name, name);
}

template<> struct RtcElement<RtcProperty>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtcProperty::name, Ns::RtcExt, "name", "name"),
                          text(&RtcProperty::value, Ns::RtcExt, "value", "value"));
};

template<> struct RtcElement<RtcBasicDoc>
{
    static constexpr auto fields = std::make_tuple(
        docText(&RtcBasicDoc::description, "description"), docText(&RtcBasicDoc::inout, "inout"),
        docText(&RtcBasicDoc::algorithm, "algorithm"), docText(&RtcBasicDoc::creator, "creator"),
        docText(&RtcBasicDoc::license, "license"), docText(&RtcBasicDoc::reference, "reference"));
};

template<> struct RtcElement<RtcBasicInfo>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtcBasicInfo::name, Ns::Rtc, "name", "name"),
        text(&RtcBasicInfo::componentType, Ns::Rtc, "componentType", "componentType"),
        text(&RtcBasicInfo::activityType, Ns::Rtc, "activityType", "activityType"),
        text(&RtcBasicInfo::componentKind, Ns::Rtc, "componentKind", "componentKind"),
        text(&RtcBasicInfo::rtcType, Ns::Rtc, "rtcType", "rtcType"),
        text(&RtcBasicInfo::category, Ns::Rtc, "category", "category"),
        text(&RtcBasicInfo::description, Ns::Rtc, "description", "description"),
        number(&RtcBasicInfo::executionRate, Ns::Rtc, "executionRate", "executionRate"),
        text(&RtcBasicInfo::executionType, Ns::Rtc, "executionType", "executionType"),
        number(&RtcBasicInfo::maxInstances, Ns::Rtc, "maxInstances", "maxInstances"),
        text(&RtcBasicInfo::vendor, Ns::Rtc, "vendor", "vendor"),
        text(&RtcBasicInfo::version, Ns::Rtc, "version", "version"),
        text(&RtcBasicInfo::abstractText, Ns::Rtc, "abstract", "abstract"),
        text(&RtcBasicInfo::hardwareProfile, Ns::Rtc, "hardwareProfile", "hardwareProfile"),
        date(&RtcBasicInfo::creationDate, Ns::Rtc, "creationDate", "creationDate"),
        date(&RtcBasicInfo::updateDate, Ns::Rtc, "updateDate", "updateDate"),
        rtcComment(&RtcBasicInfo::comment),
        text(&RtcBasicInfo::saveProject, Ns::RtcExt, "saveProject", "rtcExt::saveProject")
            .withYamlLegacyKeys("saveProject"),
        rtcDoc(&RtcBasicInfo::doc),
        // Old EMF-era files spell the element VersionUpLog.
        textList(&RtcBasicInfo::versionUpLogs, Ns::RtcExt, "VersionUpLogs", "rtcExt::versionUpLogs")
            .withXmlLegacyName("VersionUpLog")
            .withYamlLegacyKeys("versionUpLogs", "versionUpLog"),
        rtcProperties(&RtcBasicInfo::properties));
};

template<> struct RtcElement<RtcActionDoc>
{
    static constexpr auto fields
        = std::make_tuple(docText(&RtcActionDoc::description, "description"),
                          docText(&RtcActionDoc::preCondition, "preCondition"),
                          docText(&RtcActionDoc::postCondition, "postCondition"));
};

template<> struct RtcElement<RtcActionStatus>
{
    static constexpr auto fields = std::make_tuple(
        // EMF leaves out attributes at their default, so a YAML file without it means false.
        boolean(&RtcActionStatus::implemented, Ns::Rtc, "implemented", "implemented")
            .withYamlDefault("false"),
        rtcDoc(&RtcActionStatus::doc));
};

template<> struct RtcElement<RtcActions>
{
    static constexpr auto fields = std::make_tuple(special<RtcActionStatuses>());
};

template<> struct RtcElement<RtcConfigurationDoc>
{
    static constexpr auto fields = std::make_tuple(
        docText(&RtcConfigurationDoc::dataname, "dataname"),
        docText(&RtcConfigurationDoc::defaultValue, "defaultValue"),
        docText(&RtcConfigurationDoc::description, "description"),
        docText(&RtcConfigurationDoc::unit, "unit"), docText(&RtcConfigurationDoc::range, "range"),
        docText(&RtcConfigurationDoc::constraint, "constraint"));
};

template<> struct RtcElement<RtcConfiguration>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtcConfiguration::name, Ns::Rtc, "name", "name"),
        text(&RtcConfiguration::type, Ns::Rtc, "type", "type"),
        text(&RtcConfiguration::defaultValue, Ns::Rtc, "defaultValue", "defaultValue"),
        text(&RtcConfiguration::unit, Ns::Rtc, "unit", "unit"),
        rtcVariableName(&RtcConfiguration::variableName), rtcComment(&RtcConfiguration::comment),
        special<RtcConstraintTree>(), rtcDoc(&RtcConfiguration::doc),
        rtcProperties(&RtcConfiguration::properties));
};

template<> struct RtcElement<RtcDataPortDoc>
{
    static constexpr auto fields = std::make_tuple(
        docText(&RtcDataPortDoc::description, "description"),
        docText(&RtcDataPortDoc::type, "type"), docText(&RtcDataPortDoc::number, "number"),
        docText(&RtcDataPortDoc::semantics, "semantics"), docText(&RtcDataPortDoc::unit, "unit"),
        docText(&RtcDataPortDoc::occerrence, "occerrence"),
        docText(&RtcDataPortDoc::operation, "operation"));
};

template<> struct RtcElement<RtcEventDoc>
{
    static constexpr auto fields = std::make_tuple(
        docText(&RtcEventDoc::description, "description"), docText(&RtcEventDoc::type, "type"),
        docText(&RtcEventDoc::number, "number"), docText(&RtcEventDoc::semantics, "semantics"),
        docText(&RtcEventDoc::unit, "unit"), docText(&RtcEventDoc::operation, "operation"));
};

template<> struct RtcElement<RtcEvent>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtcEvent::name, Ns::Rtc, "name", "name"),
                          text(&RtcEvent::condition, Ns::Rtc, "condition", "condition"),
                          text(&RtcEvent::source, Ns::Rtc, "source", "source"),
                          text(&RtcEvent::target, Ns::Rtc, "target", "target"),
                          text(&RtcEvent::type, Ns::Rtc, "type", "type"), rtcDoc(&RtcEvent::doc));
};

template<> struct RtcElement<RtcDataPort>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtcDataPort::portType, Ns::Rtc, "portType", "portType"),
        text(&RtcDataPort::name, Ns::Rtc, "name", "name"),
        text(&RtcDataPort::type, Ns::Rtc, "type", "type"),
        text(&RtcDataPort::idlFile, Ns::Rtc, "idlFile", "idlFile"),
        text(&RtcDataPort::interfaceType, Ns::Rtc, "interfaceType", "interfaceType"),
        text(&RtcDataPort::dataflowType, Ns::Rtc, "dataflowType", "dataflowType"),
        text(&RtcDataPort::subscriptionType, Ns::Rtc, "subscriptionType", "subscriptionType")
            .withXmlLegacyName("subscriprionType")
            .withYamlLegacyKeys("subscriprionType"),
        text(&RtcDataPort::unit, Ns::Rtc, "unit", "unit"), rtcPosition(&RtcDataPort::position),
        rtcVariableName(&RtcDataPort::variableName), rtcComment(&RtcDataPort::comment),
        special<RtcConstraintTree>(),
        list(&RtcDataPort::events, Ns::Rtc, "Event", "event")
            .withXsiType(Ns::RtcDoc, "event_doc")
            .withYamlLegacyKeys("events"),
        rtcDoc(&RtcDataPort::doc), rtcProperties(&RtcDataPort::properties));
};

template<> struct RtcElement<RtcServiceInterfaceDoc>
{
    static constexpr auto fields
        = std::make_tuple(docText(&RtcServiceInterfaceDoc::description, "description"),
                          docText(&RtcServiceInterfaceDoc::docArgument, "docArgument"),
                          docText(&RtcServiceInterfaceDoc::docReturn, "docReturn"),
                          docText(&RtcServiceInterfaceDoc::docException, "docException"),
                          docText(&RtcServiceInterfaceDoc::docPreCondition, "docPreCondition"),
                          docText(&RtcServiceInterfaceDoc::docPostCondition, "docPostCondition"));
};

template<> struct RtcElement<RtcServiceInterface>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtcServiceInterface::name, Ns::Rtc, "name", "name"),
        text(&RtcServiceInterface::direction, Ns::Rtc, "direction", "direction"),
        text(&RtcServiceInterface::instanceName, Ns::Rtc, "instanceName", "instanceName"),
        text(&RtcServiceInterface::idlFile, Ns::Rtc, "idlFile", "idlFile"),
        text(&RtcServiceInterface::type, Ns::Rtc, "type", "type"),
        text(&RtcServiceInterface::path, Ns::Rtc, "path", "path"),
        rtcVariableName(&RtcServiceInterface::variableName),
        rtcComment(&RtcServiceInterface::comment), rtcDoc(&RtcServiceInterface::doc),
        rtcProperties(&RtcServiceInterface::properties));
};

template<> struct RtcElement<RtcTransMethod>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtcTransMethod::kind, Ns::Rtc, "kind", "kind"));
};

template<> struct RtcElement<RtcServicePortDoc>
{
    static constexpr auto fields
        = std::make_tuple(docText(&RtcServicePortDoc::description, "description"),
                          docText(&RtcServicePortDoc::ifdescription, "ifdescription"));
};

template<> struct RtcElement<RtcServicePort>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtcServicePort::name, Ns::Rtc, "name", "name"),
        rtcPosition(&RtcServicePort::position), rtcComment(&RtcServicePort::comment),
        list(&RtcServicePort::interfaces, Ns::Rtc, "ServiceInterface", "serviceInterface")
            .withXsiType(Ns::RtcExt, "serviceinterface_ext")
            .withYamlLegacyKeys("serviceInterfaces"),
        list(&RtcServicePort::transMethods, Ns::Rtc, "TransMethods", "transMethods"),
        rtcDoc(&RtcServicePort::doc), rtcProperties(&RtcServicePort::properties));
};

template<> struct RtcElement<RtcLibrary>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtcLibrary::name, Ns::RtcExt, "name", "name"),
                          text(&RtcLibrary::version, Ns::RtcExt, "version", "version"),
                          text(&RtcLibrary::other, Ns::RtcExt, "other", "other"));
};

// RTC Builder writes the target environment's keys without the rtcExt prefix; some files have it.
template<> struct RtcElement<RtcTargetEnvironment>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtcTargetEnvironment::langVersion, Ns::RtcExt, "langVersion", "langVersion")
            .withYamlLegacyKeys("rtcExt::langVersion"),
        text(&RtcTargetEnvironment::os, Ns::RtcExt, "os", "os").withYamlLegacyKeys("rtcExt::os"),
        text(&RtcTargetEnvironment::other, Ns::RtcExt, "other", "other")
            .withYamlLegacyKeys("rtcExt::other"),
        text(&RtcTargetEnvironment::cpuOther, Ns::RtcExt, "cpuOther", "cpuOther")
            .withYamlLegacyKeys("rtcExt::cpuOther"),
        textList(&RtcTargetEnvironment::osVersions, Ns::RtcExt, "osVersions", "osVersions")
            .withYamlLegacyKeys("rtcExt::osVersions"),
        textList(&RtcTargetEnvironment::cpus, Ns::RtcExt, "cpus", "cpus")
            .withYamlLegacyKeys("rtcExt::cpus"),
        list(&RtcTargetEnvironment::libraries, Ns::RtcExt, "libraries", "libraries")
            .withYamlLegacyKeys("rtcExt::libraries"));
};

template<> struct RtcElement<RtcLanguage>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtcLanguage::kind, Ns::Rtc, "kind", "kind"),
                          list(&RtcLanguage::targets, Ns::RtcExt, "targets", "rtcExt::targets")
                              .withYamlLegacyKeys("targets"),
                          rtcProperties(&RtcLanguage::properties));
};

template<> struct RtcElement<RtcParameter>
{
    static constexpr auto fields = std::make_tuple(
        text(&RtcParameter::name, Ns::Rtc, "name", "name"),
        text(&RtcParameter::defaultValue, Ns::Rtc, "defaultValue", "defaultValue"));
};

template<> struct RtcElement<RtcProfile>
{
    static constexpr auto fields
        = std::make_tuple(text(&RtcProfile::id, Ns::Rtc, "id", "id"), special<RtcProfileVersion>(),
                          element(&RtcProfile::basicInfo, Ns::Rtc, "BasicInfo", "basicInfo")
                              .withXsiType(Ns::RtcExt, "basic_info_ext"),
                          element(&RtcProfile::actions, Ns::Rtc, "Actions", "actions"),
                          special<RtcConfigurationSet>(),
                          list(&RtcProfile::dataPorts, Ns::Rtc, "DataPorts", "dataPorts")
                              .withXsiType(Ns::RtcExt, "dataport_ext"),
                          list(&RtcProfile::servicePorts, Ns::Rtc, "ServicePorts", "servicePorts")
                              .withXsiType(Ns::RtcExt, "serviceport_ext"),
                          list(&RtcProfile::parameters, Ns::Rtc, "Parameters", "parameters"),
                          optionalElement(&RtcProfile::language, Ns::Rtc, "Language", "language")
                              .withXsiType(Ns::RtcExt, "language_ext"));
};

} // namespace Profile::Fields
