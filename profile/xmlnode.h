// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>
#include <vector>

namespace Profile {

/// A namespace-qualified attribute as read from or written to a file.
struct XmlAttribute
{
    QString namespaceUri;
    QString prefix; ///< as written in the source; only a hint for writing
    QString name;   ///< local name
    QString value;

    /// Equal when namespace, local name and value are (the prefix is not data).
    bool operator==(const XmlAttribute &other) const;
    bool operator!=(const XmlAttribute &other) const { return !(*this == other); }
};

/// A source position (1-based line and column; 0 = unknown). Never part of equality.
struct SourceLocation
{
    int line = 0;
    int column = 0;
    bool isValid() const { return line > 0; }
};

/**
 * A generic element: the intermediate form between the typed profile models and the file.
 *
 * Readers turn a file into an XmlNode tree and map it to a model; writers build a tree from the model
 * and serialise it. Elements and attributes that a model does not know travel inside XmlExtras as
 * XmlNodes, which is what keeps unknown extensions in a file across load and save.
 */
struct XmlNode
{
    QString namespaceUri;
    QString prefix; ///< as written in the source; only a hint for writing
    QString name;   ///< local name
    /// Resolved `xsi:type` (kept out of `attributes`); empty when the element had none.
    QString xsiTypeNamespace;
    QString xsiTypeName;
    QList<XmlAttribute> attributes;
    std::vector<XmlNode> children;
    QString text; ///< character data; whitespace-only text is dropped
    SourceLocation location;

    XmlNode() = default;
    XmlNode(const QString &ns, const QString &localName);

    bool is(const QString &ns, const QString &localName) const;
    const XmlAttribute *attribute(const QString &ns, const QString &localName) const;
    void setAttribute(const QString &ns, const QString &localName, const QString &value);
    /// Sets the attribute only when the value is present.
    void setAttribute(const QString &ns, const QString &localName, const std::optional<QString> &value);
    void setXsiType(const QString &ns, const QString &localName);
    XmlNode &addChild(const QString &ns, const QString &localName);
    XmlNode &addChild(XmlNode node);

    /// Structural equality: names, attributes (in order), children, text; prefixes and locations aside.
    bool operator==(const XmlNode &other) const;
    bool operator!=(const XmlNode &other) const { return !(*this == other); }
};

/// Limits that keep hostile files from exhausting the stack or memory.
struct XmlLimits
{
    int maxDepth = 256;
    qint64 maxBytes = 512LL * 1024 * 1024;
};

/// Reads XML text into an XmlNode tree. On failure returns nothing and appends a
/// `FILE:LINE:COL` diagnostic; never throws.
std::optional<XmlNode> parseXml(const QByteArray &data, const QString &fileName,
                                Diagnostics *diagnostics, const XmlLimits &limits = {});

/// Writes a tree as indented UTF-8 XML with OpenRTP's prefixes declared on the root element.
QByteArray serializeXml(const XmlNode &root);

} // namespace Profile
