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

/// Reads an `rtc:Constraint` element (recursively).
RtcConstraint readConstraint(const XmlNode &node, const ReadContext &context);
/// The `rtc:Constraint` element for a tree.
XmlNode constraintToXml(const RtcConstraint &constraint);

} // namespace Profile::RtcXml

namespace Profile::RtcXml {

/// Gives `node` the attributes, child elements and extras the writer gives an element of this
/// type (its name and xsi:type are the caller's). The YAML reader uses it to learn how many
/// schema children an element gets, so that unknown YAML keys kept as extra elements land after
/// them.
template<typename T> void writeFields(XmlNode &node, const T &item);
/// The `rtc:ConfigurationSet` element of a profile.
XmlNode configurationSetToXml(const RtcProfile &profile);

} // namespace Profile::RtcXml
