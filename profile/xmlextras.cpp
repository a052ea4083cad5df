// SPDX-License-Identifier: MIT
#include "xmlextras.h"

#include <QCoreApplication>

namespace Profile {

namespace {
QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::Xml", text);
}
} // namespace

bool XmlExtras::operator==(const XmlExtras &other) const
{
    return attributes == other.attributes && children == other.children;
}

void XmlExtras::applyTo(XmlNode &node) const
{
    if (node.xsiTypeName.isEmpty() && !xsiTypeName.isEmpty())
        node.setXsiType(xsiTypeNamespace, xsiTypeName);
    for (const XmlAttribute &a : attributes) {
        if (!node.attribute(a.namespaceUri, a.name))
            node.attributes.append(a);
    }
    for (const Child &child : children) {
        const auto position = std::min<std::size_t>(std::max(child.position, 0), node.children.size());
        node.children.insert(node.children.begin() + qsizetype(position), child.node);
    }
}

NodeReader::NodeReader(const XmlNode &node, const QString &fileName, Diagnostics *diagnostics)
    : m_node(node)
    , m_fileName(fileName)
    , m_diagnostics(diagnostics)
    , m_attributeUsed(std::size_t(node.attributes.size()), false)
    , m_childUsed(node.children.size(), false)
{
}

int NodeReader::findAttribute(const QString &ns, const QString &name) const
{
    int unqualified = -1;
    for (int i = 0; i < m_node.attributes.size(); ++i) {
        const XmlAttribute &a = m_node.attributes.at(i);
        if (a.name != name || m_attributeUsed[std::size_t(i)])
            continue;
        if (a.namespaceUri == ns)
            return i;
        if (a.namespaceUri.isEmpty() && unqualified < 0)
            unqualified = i;
    }
    return unqualified;
}

std::optional<QString> NodeReader::attribute(const QString &ns, const QString &name)
{
    const int index = findAttribute(ns, name);
    if (index < 0)
        return std::nullopt;
    m_attributeUsed[std::size_t(index)] = true;
    return m_node.attributes.at(index).value;
}

std::optional<QString> NodeReader::attribute(const QString &ns, const QString &name,
                                             const QStringList &legacyNames)
{
    if (auto value = attribute(ns, name))
        return value;
    for (const QString &legacy : legacyNames) {
        if (auto value = attribute(ns, legacy))
            return value;
    }
    return std::nullopt;
}

QString NodeReader::required(const QString &ns, const QString &name)
{
    return required(ns, name, {});
}

QString NodeReader::required(const QString &ns, const QString &name, const QStringList &legacyNames)
{
    if (auto value = attribute(ns, name, legacyNames))
        return *value;
    error(tr("<%1> lacks the required attribute '%2'").arg(m_node.name, name));
    return {};
}

std::vector<const XmlNode *> NodeReader::children(const QString &ns, const QString &name)
{
    std::vector<const XmlNode *> result;
    for (std::size_t i = 0; i < m_node.children.size(); ++i) {
        if (!m_childUsed[i] && m_node.children[i].is(ns, name)) {
            m_childUsed[i] = true;
            result.push_back(&m_node.children[i]);
        }
    }
    return result;
}

const XmlNode *NodeReader::child(const QString &ns, const QString &name)
{
    for (std::size_t i = 0; i < m_node.children.size(); ++i) {
        if (!m_childUsed[i] && m_node.children[i].is(ns, name)) {
            m_childUsed[i] = true;
            return &m_node.children[i];
        }
    }
    return nullptr;
}

XmlExtras NodeReader::extras() const
{
    XmlExtras result;
    result.xsiTypeNamespace = m_node.xsiTypeNamespace;
    result.xsiTypeName = m_node.xsiTypeName;
    for (int i = 0; i < m_node.attributes.size(); ++i) {
        if (!m_attributeUsed[std::size_t(i)])
            result.attributes.append(m_node.attributes.at(i));
    }
    for (std::size_t i = 0; i < m_node.children.size(); ++i) {
        if (!m_childUsed[i])
            result.children.push_back(XmlExtras::Child{int(i), m_node.children[i]});
    }
    return result;
}

void NodeReader::warn(const QString &message) const
{
    if (m_diagnostics) {
        m_diagnostics->append(Diagnostic::warning(m_fileName, m_node.location.line,
                                                  m_node.location.column, message));
    }
}

void NodeReader::error(const QString &message) const
{
    if (m_diagnostics) {
        m_diagnostics->append(Diagnostic::error(m_fileName, m_node.location.line,
                                                m_node.location.column, message));
    }
}

std::optional<bool> parseBoolean(const QString &text)
{
    const QString t = text.trimmed().toLower();
    if (t == QLatin1String("true") || t == QLatin1String("1"))
        return true;
    if (t == QLatin1String("false") || t == QLatin1String("0"))
        return false;
    return std::nullopt;
}

QString booleanText(bool value)
{
    return value ? QStringLiteral("true") : QStringLiteral("false");
}

} // namespace Profile
