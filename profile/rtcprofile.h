// SPDX-License-Identifier: MIT
#pragma once

#include "rtccommon.h"
#include "rtcconstraint.h"
#include "rtcports.h"

#include <array>

namespace Profile {

/// `rtcDoc:Doc` of the basic information (`rtcDoc:doc_basic`).
struct RtcBasicDoc
{
    std::optional<QString> description;
    std::optional<QString> inout;
    std::optional<QString> algorithm;
    std::optional<QString> creator;
    std::optional<QString> license;
    std::optional<QString> reference;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcBasicDoc &other) const;
    bool operator!=(const RtcBasicDoc &other) const { return !(*this == other); }
};

/// `rtc:BasicInfo` (+ `rtcDoc:basic_info_doc`, `rtcExt:basic_info_ext`).
struct RtcBasicInfo
{
    QString name;
    QString componentType; ///< STATIC | UNIQUE | COMMUTATIVE (rtcComponentTypes())
    QString activityType; ///< PERIODIC | SPORADIC | EVENTDRIVEN (rtcActivityTypes())
    QString componentKind; ///< DataFlowComponent, FiniteStateMachineComponent …
    std::optional<QString> rtcType;
    QString category;
    std::optional<QString> description;
    std::optional<QString> executionRate; ///< xs:double text (Hz)
    QString executionType; ///< PeriodicExecutionContext, ExtTrigExecutionContext …
    std::optional<QString> maxInstances; ///< xs:integer text; 0 = unlimited
    QString vendor;
    QString version;
    std::optional<QString> abstractText; ///< `rtc:abstract`
    std::optional<QString> hardwareProfile;
    QString creationDate; ///< xs:dateTime text
    QString updateDate; ///< xs:dateTime text
    std::optional<RtcBasicDoc> doc;

    // rtcExt:basic_info_ext
    QStringList versionUpLogs; ///< `rtcExt:VersionUpLogs` (old files: `VersionUpLog`)
    RtcProperties properties;
    std::optional<QString> comment;
    std::optional<QString> saveProject;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    /// executionRate as a number; nothing when absent or not a number.
    std::optional<double> executionRateValue() const;
    /// maxInstances as a number; nothing when absent or not an integer.
    std::optional<qint64> maxInstancesValue() const;

    bool operator==(const RtcBasicInfo &other) const;
    bool operator!=(const RtcBasicInfo &other) const { return !(*this == other); }
};

/// The 14 component actions, in schema order.
enum class RtcAction {
    OnInitialize,
    OnFinalize,
    OnStartup,
    OnShutdown,
    OnActivated,
    OnDeactivated,
    OnAborting,
    OnError,
    OnReset,
    OnExecute,
    OnStateUpdate,
    OnRateChanged,
    OnAction,
    OnModeChanged
};
inline constexpr int RtcActionCount = 14;

/// The XML element name, e.g. "OnExecute".
QString rtcActionElementName(RtcAction action);
/// The YAML key / callback name, e.g. "onExecute".
QString rtcActionKey(RtcAction action);
/// All actions in schema order.
const std::array<RtcAction, RtcActionCount> &rtcAllActions();

/// `rtcDoc:Doc` of an action (`rtcDoc:doc_action`).
struct RtcActionDoc
{
    std::optional<QString> description;
    std::optional<QString> preCondition;
    std::optional<QString> postCondition;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcActionDoc &other) const;
    bool operator!=(const RtcActionDoc &other) const { return !(*this == other); }
};

/// `rtc:OnXxx @implemented` (+ `rtcDoc:action_status_doc`).
struct RtcActionStatus
{
    /// xs:boolean: readers turn 1/0 into true/false and keep any other text as it was.
    QString implemented = QStringLiteral("false");
    std::optional<RtcActionDoc> doc;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    /// The boolean meaning of `implemented` (false when it is not a boolean).
    bool isImplemented() const;
    void setImplemented(bool value);

    bool operator==(const RtcActionStatus &other) const;
    bool operator!=(const RtcActionStatus &other) const { return !(*this == other); }
};

/// `rtc:Actions`: one optional entry per action (absent = the file has no element for it).
struct RtcActions
{
    std::array<std::optional<RtcActionStatus>, RtcActionCount> status;

    XmlExtras extras;
    SourceLocation location;

    std::optional<RtcActionStatus> &operator[](RtcAction action)
    {
        return status[std::size_t(action)];
    }
    const std::optional<RtcActionStatus> &operator[](RtcAction action) const
    {
        return status[std::size_t(action)];
    }
    /// True when the action is present and implemented.
    bool isImplemented(RtcAction action) const;
    /// Sets `implemented`, adding the entry if needed.
    void setImplemented(RtcAction action, bool value);

    bool operator==(const RtcActions &other) const;
    bool operator!=(const RtcActions &other) const { return !(*this == other); }
};

/// `rtcDoc:Doc` of a configuration parameter (`rtcDoc:doc_configuration`).
struct RtcConfigurationDoc
{
    std::optional<QString> dataname;
    std::optional<QString> defaultValue;
    std::optional<QString> description;
    std::optional<QString> unit;
    std::optional<QString> range;
    std::optional<QString> constraint;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcConfigurationDoc &other) const;
    bool operator!=(const RtcConfigurationDoc &other) const { return !(*this == other); }
};

/// `rtc:Configuration` (+ `rtcDoc:configuration_doc`, `rtcExt:configuration_ext`).
struct RtcConfiguration
{
    /// The property that holds the editor widget (`text`, `slider.<step>`, `spin`, `radio` …).
    static inline const QString WidgetProperty = QStringLiteral("__widget__");

    QString name;
    QString type; ///< short, int, long, float, double, string or any IDL type
    QString defaultValue;
    std::optional<QString> unit;
    std::optional<RtcConstraint> constraint;
    std::optional<RtcConfigurationDoc> doc;

    // rtcExt:configuration_ext
    std::optional<QString> variableName; ///< old files: `rtc:varname`
    std::optional<QString> comment;
    RtcProperties properties;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    /// The `__widget__` property, or nothing.
    std::optional<QString> widget() const;

    bool operator==(const RtcConfiguration &other) const;
    bool operator!=(const RtcConfiguration &other) const { return !(*this == other); }
};

/// `rtcExt:libraries @name @version? @other?`.
struct RtcLibrary
{
    QString name;
    std::optional<QString> version;
    std::optional<QString> other;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcLibrary &other) const;
    bool operator!=(const RtcLibrary &other) const { return !(*this == other); }
};

/// `rtcExt:targets` (`rtcExt:target_environment`): where the component is meant to run.
struct RtcTargetEnvironment
{
    std::optional<QString> langVersion;
    std::optional<QString> os;
    std::optional<QString> other;
    std::optional<QString> cpuOther;
    QStringList osVersions;
    QStringList cpus;
    QList<RtcLibrary> libraries;

    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcTargetEnvironment &other) const;
    bool operator!=(const RtcTargetEnvironment &other) const { return !(*this == other); }
};

/// `rtc:Language @kind` (+ `rtcExt:language_ext`). Old per-language children such as
/// `rtc:Java`/`rtc:Cxx` are kept in `extras`.
struct RtcLanguage
{
    QString kind; ///< C++, Python, Java …
    QList<RtcTargetEnvironment> targets;
    RtcProperties properties;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcLanguage &other) const;
    bool operator!=(const RtcLanguage &other) const { return !(*this == other); }
};

/// `rtc:Parameters @name @defaultValue?` (RTC Profile 0.2; kept and written back when present).
struct RtcParameter
{
    QString name;
    std::optional<QString> defaultValue;

    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    bool operator==(const RtcParameter &other) const;
    bool operator!=(const RtcParameter &other) const { return !(*this == other); }
};

/// The parts of a component id `RTC:vendor:category:name:version`.
struct RtcComponentId
{
    QString vendor;
    QString category;
    QString name;
    QString version;

    /// Splits an id; nothing when it does not have the form `RTC:v:c:n:ver` (five parts).
    static std::optional<RtcComponentId> parse(const QString &id);
    QString toString() const;
};

/**
 * An RTC Profile (`rtc:RtcProfile`, the RTC.xml of RTC Builder): what a component is, its
 * callbacks, configuration, ports and language.
 *
 * A plain value. Numbers, enumerations and booleans are kept as the file's text so that nothing
 * is lost; validateRtcProfile() reports bad ones. Content the model does not know travels in the
 * `extras` of the struct for the element it was found in; legacy spellings are mapped onto the
 * schema fields on reading.
 */
struct RtcProfile
{
    /// The RTC Profile version this project writes.
    static inline const QString CurrentVersion = QStringLiteral("0.3");

    QString id; ///< `RTC:vendor:category:name:version`
    /// The format version the file was read in ("0.3" current, "0.2", older "0.1"/"1.0"); the
    /// writers always write CurrentVersion.
    QString version;
    RtcBasicInfo basicInfo;
    RtcActions actions;

    /// `rtc:ConfigurationSet/rtc:Configuration*`.
    QList<RtcConfiguration> configurations;
    /// The file had an empty `rtc:ConfigurationSet` element (readers set it only then); the
    /// writers write the set when this is true or when there are configurations.
    bool hasConfigurationSet = false;
    XmlExtras configurationSetExtras;
    SourceLocation configurationSetLocation;

    QList<RtcDataPort> dataPorts;
    QList<RtcServicePort> servicePorts;
    QList<RtcParameter> parameters; ///< profile 0.2 `rtc:Parameters`
    std::optional<RtcLanguage> language;

    /// Required parts the source lacked: "id", "version", "BasicInfo", "Actions".
    RtcMissing missing;
    XmlExtras extras;
    SourceLocation location;

    /**
     * A new component with RTC Builder's defaults: ModuleName / ModuleDescription / Category /
     * 1.0.0 / VenderName, STATIC, PERIODIC, DataFlowComponent, PeriodicExecutionContext at
     * 1000.0 Hz, one instance, all 14 actions listed with onInitialize implemented, language
     * C++, both dates now.
     */
    static RtcProfile createDefault();

    /// `RTC:<vendor>:<category>:<name>:<version>` built from basicInfo.
    QString idFromBasicInfo() const;
    /// The data port called `name`, or null.
    const RtcDataPort *dataPort(const QString &name) const;
    /// The service port called `name`, or null.
    const RtcServicePort *servicePort(const QString &name) const;
    /// The configuration parameter called `name`, or null.
    const RtcConfiguration *configuration(const QString &name) const;

    bool operator==(const RtcProfile &other) const;
    bool operator!=(const RtcProfile &other) const { return !(*this == other); }
};

} // namespace Profile
