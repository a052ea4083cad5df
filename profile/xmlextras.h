// SPDX-License-Identifier: MIT
#pragma once

#include "xmlnode.h"

namespace Profile {

/**
 * What a file had on an element that the typed model does not know: attributes, and child elements
 * with the position they stood at among their siblings. Writers put them back in place, so that
 * future extensions survive a load/edit/save cycle.
 */
struct XmlExtras
{
    struct Child
    {
        int position = 0; ///< index among the parent's children in the source
        XmlNode node;
        bool operator==(const Child &other) const
        {
            return position == other.position && node == other.node;
        }
    };

    QList<XmlAttribute> attributes;
    std::vector<Child> children;
    /// The element's xsi:type in the file (namespace URI, local name). Like a source location it
    /// describes where the data came from: not compared, not counted by isEmpty(). Writers keep
    /// it where they would write no type, or a type the file's narrower one can stand for.
    QString xsiTypeNamespace;
    QString xsiTypeName;

    bool isEmpty() const { return attributes.isEmpty() && children.empty(); }
    bool hasXsiType(const QString &ns, const QString &localName) const
    {
        return xsiTypeNamespace == ns && xsiTypeName == localName;
    }
    bool operator==(const XmlExtras &other) const;
    bool operator!=(const XmlExtras &other) const { return !(*this == other); }

    /// Adds the attributes to `node` and inserts the children at their recorded positions; gives
    /// `node` the file's xsi:type when it has none.
    void applyTo(XmlNode &node) const;
};

/**
 * Reads the typed content of one XmlNode and remembers what was taken, so that the rest can be
 * kept as XmlExtras. Reports missing required attributes as diagnostics at the element.
 *
 * Attribute look-up matches namespace URI and local name; as a courtesy to hand-written files an
 * unqualified attribute of the same local name is accepted too.
 */
class NodeReader
{
public:
    NodeReader(const XmlNode &node, const QString &fileName, Diagnostics *diagnostics);

    const XmlNode &node() const { return m_node; }
    SourceLocation location() const { return m_node.location; }

    /// The attribute's value, or nothing when absent.
    std::optional<QString> attribute(const QString &ns, const QString &name);
    /// Like attribute(), but tries each legacy spelling in turn after the schema one.
    std::optional<QString> attribute(const QString &ns, const QString &name,
                                     const QStringList &legacyNames);
    /// The value of a required attribute; an error diagnostic and an empty string when absent.
    QString required(const QString &ns, const QString &name);
    QString required(const QString &ns, const QString &name, const QStringList &legacyNames);

    /// All children with this name (in document order), marked as consumed.
    std::vector<const XmlNode *> children(const QString &ns, const QString &name);
    /// The first child with this name, or null; later duplicates are left as extras.
    const XmlNode *child(const QString &ns, const QString &name);

    /// Everything not consumed so far.
    XmlExtras extras() const;

    void warn(const QString &message) const;
    void error(const QString &message) const;
    const QString &fileName() const { return m_fileName; }
    Diagnostics *diagnostics() const { return m_diagnostics; }

private:
    int findAttribute(const QString &ns, const QString &name) const;

    const XmlNode &m_node;
    QString m_fileName;
    Diagnostics *m_diagnostics;
    std::vector<bool> m_attributeUsed;
    std::vector<bool> m_childUsed;
};

/// Parses an xs:boolean the way the reference tools write it: true|false|1|0 (case-insensitive).
std::optional<bool> parseBoolean(const QString &text);
QString booleanText(bool value);

} // namespace Profile
