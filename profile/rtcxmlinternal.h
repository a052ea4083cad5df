// SPDX-License-Identifier: MIT
#pragma once

// Helpers shared by the RTC Profile XML reader and writer (and the YAML code, which stores
// unknown keys as XML extras). Not part of the library's public interface.

#include "rtcprofile.h"
#include "xmlextras.h"

namespace Profile::RtcXml {

/// Where diagnostics of one read go.
struct ReadContext
{
    QString fileName;
    Diagnostics *diagnostics = nullptr;
};

/// A required attribute; when absent: a warning, the name recorded in `missing`, "".
QString requiredAttribute(NodeReader &reader, const QString &ns, const QString &name,
                          RtcMissing &missing, const QStringList &legacyNames = {});
/// Records a missing required child element (warning + `missing`).
void reportMissingChild(const NodeReader &reader, const QString &name, RtcMissing &missing);
/// The text of a simple-content element; warns when it carries attributes or children.
QString simpleText(const XmlNode &node, const ReadContext &context);
/// An xs:boolean as "true"/"false" when it is one (1 and 0 included); other text as it is.
QString normalizedBoolean(const QString &value);
/// An `rtcExt:position` value in the schema's upper case when it is one of the known ones.
QString normalizedPosition(const QString &value);

/// Writes a required attribute unless it is empty and the source lacked it.
void setRequired(XmlNode &node, const QString &ns, const QString &name, const QString &value,
                 const RtcMissing &missing);
/// A leaf element with text.
XmlNode textElement(const QString &ns, const QString &name, const QString &text);

RtcProperty readProperty(const XmlNode &node, const ReadContext &context);
XmlNode propertyToXml(const RtcProperty &property);

/// Reads an `rtc:Constraint` element (recursively).
RtcConstraint readConstraint(const XmlNode &node, const ReadContext &context);
/// The `rtc:Constraint` element for a tree.
XmlNode constraintToXml(const RtcConstraint &constraint);

} // namespace Profile::RtcXml

namespace Profile::RtcXml {

// Element builders of the writer, one per model struct (extras applied). The YAML reader uses
// them to learn how many schema children an element gets, so that unknown YAML keys kept as
// extra elements land after them.
XmlNode toXml(const RtcBasicInfo &info);
XmlNode toXml(const RtcActions &actions);
XmlNode toXml(RtcAction action, const RtcActionStatus &status);
XmlNode toXml(const RtcActionDoc &doc);
XmlNode toXml(const RtcBasicDoc &doc);
XmlNode toXml(const RtcConfiguration &configuration);
XmlNode toXml(const RtcConfigurationDoc &doc);
XmlNode toXml(const RtcDataPort &port);
XmlNode toXml(const RtcDataPortDoc &doc);
XmlNode toXml(const RtcEvent &event);
XmlNode toXml(const RtcEventDoc &doc);
XmlNode toXml(const RtcServicePort &port);
XmlNode toXml(const RtcServicePortDoc &doc);
XmlNode toXml(const RtcServiceInterface &interface);
XmlNode toXml(const RtcServiceInterfaceDoc &doc);
XmlNode toXml(const RtcTransMethod &method);
XmlNode toXml(const RtcLanguage &language);
XmlNode toXml(const RtcTargetEnvironment &target);
XmlNode toXml(const RtcLibrary &library);
XmlNode toXml(const RtcParameter &parameter);
/// The `rtc:ConfigurationSet` element of a profile.
XmlNode configurationSetToXml(const RtcProfile &profile);

} // namespace Profile::RtcXml
