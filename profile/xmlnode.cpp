// SPDX-License-Identifier: MIT
#include "xmlnode.h"
#include "namespaces.h"

#include <QCoreApplication>
#include <algorithm>
#include <unordered_map>
#include <QHash>
#include <QStringDecoder>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

namespace Profile {

bool XmlAttribute::operator==(const XmlAttribute &other) const
{
    return namespaceUri == other.namespaceUri && name == other.name && value == other.value;
}

XmlNode::XmlNode(const QString &ns, const QString &localName)
    : namespaceUri(ns)
    , name(localName)
{
}

bool XmlNode::is(const QString &ns, const QString &localName) const
{
    return namespaceUri == ns && name == localName;
}

const XmlAttribute *XmlNode::attribute(const QString &ns, const QString &localName) const
{
    for (const XmlAttribute &a : attributes) {
        if (a.namespaceUri == ns && a.name == localName)
            return &a;
    }
    return nullptr;
}

void XmlNode::setAttribute(const QString &ns, const QString &localName, const QString &value)
{
    for (XmlAttribute &a : attributes) {
        if (a.namespaceUri == ns && a.name == localName) {
            a.value = value;
            return;
        }
    }
    attributes.append(XmlAttribute{ns, Ns::preferredPrefix(ns), localName, value});
}

void XmlNode::setAttribute(const QString &ns, const QString &localName,
                           const std::optional<QString> &value)
{
    if (value)
        setAttribute(ns, localName, *value);
}

void XmlNode::setXsiType(const QString &ns, const QString &localName)
{
    xsiTypeNamespace = ns;
    xsiTypeName = localName;
}

XmlNode &XmlNode::addChild(const QString &ns, const QString &localName)
{
    children.emplace_back(ns, localName);
    children.back().prefix = Ns::preferredPrefix(ns);
    return children.back();
}

XmlNode &XmlNode::addChild(XmlNode node)
{
    children.push_back(std::move(node));
    return children.back();
}

bool XmlNode::operator==(const XmlNode &other) const
{
    return namespaceUri == other.namespaceUri && name == other.name
        && xsiTypeNamespace == other.xsiTypeNamespace && xsiTypeName == other.xsiTypeName
        && attributes == other.attributes && children == other.children && text == other.text;
}

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::Xml", text);
}

/// Finds the first byte that is not valid UTF-8 and reports its line and column.
bool checkUtf8(const QByteArray &data, const QString &fileName, Diagnostics *diagnostics,
               QString *decoded)
{
    QStringDecoder decoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    *decoded = decoder.decode(data);
    if (!decoder.hasError())
        return true;
    // Find the offending line by decoding line by line.
    int line = 1;
    qsizetype start = 0;
    while (start <= data.size()) {
        qsizetype end = data.indexOf('\n', start);
        if (end < 0)
            end = data.size();
        QStringDecoder lineDecoder(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
        const QByteArray chunk = data.mid(start, end - start);
        const QString text = lineDecoder.decode(chunk);
        if (lineDecoder.hasError()) {
            const int column = int(text.indexOf(QChar::ReplacementCharacter)) + 1;
            if (diagnostics)
                diagnostics->append(Diagnostic::error(fileName, line, qMax(column, 1),
                                                      tr("invalid UTF-8 byte sequence")));
            return false;
        }
        ++line;
        start = end + 1;
    }
    if (diagnostics)
        diagnostics->append(Diagnostic::error(fileName, 0, 0, tr("invalid UTF-8 byte sequence")));
    return false;
}

bool declaresOtherEncoding(const QByteArray &data)
{
    if (!data.startsWith("<?xml"))
        return false;
    const qsizetype end = data.indexOf("?>");
    const QByteArray decl = data.left(end < 0 ? 200 : end).toLower();
    const qsizetype pos = decl.indexOf("encoding");
    if (pos < 0)
        return false;
    return !decl.mid(pos).contains("utf-8") && !decl.mid(pos).contains("utf8");
}

/// Namespace scopes, so that `xsi:type="p:name"` values can be resolved to URIs.
class PrefixScopes
{
public:
    void push(const QXmlStreamNamespaceDeclarations &declarations)
    {
        QHash<QString, QString> scope;
        for (const QXmlStreamNamespaceDeclaration &d : declarations)
            scope.insert(d.prefix().toString(), d.namespaceUri().toString());
        m_scopes.push_back(std::move(scope));
    }
    void pop() { m_scopes.pop_back(); }
    QString resolve(const QString &prefix) const
    {
        for (auto it = m_scopes.crbegin(); it != m_scopes.crend(); ++it) {
            const auto found = it->constFind(prefix);
            if (found != it->cend())
                return *found;
        }
        return {};
    }

private:
    std::vector<QHash<QString, QString>> m_scopes;
};

/// Element and attribute names, namespace URIs and short values repeat thousands of times in a
/// large system file; sharing one QString per distinct text saves most of the parser's allocations.
class StringPool
{
public:
    QString intern(QStringView text)
    {
        if (text.size() > MaxInternedLength)
            return text.toString();
        const auto found = m_strings.find(text);
        if (found != m_strings.end())
            return found->second;
        QString owned = text.toString();
        // The key views the value's characters, which stay put when the QString is moved.
        const QStringView key(owned);
        return m_strings.emplace(key, std::move(owned)).first->second;
    }

private:
    static constexpr qsizetype MaxInternedLength = 64;
    struct Hash
    {
        std::size_t operator()(QStringView view) const { return qHash(view); }
    };
    std::unordered_map<QStringView, QString, Hash> m_strings;
};

class Parser
{
public:
    /// Parses decoded text; element positions are then exact (the '<' of the start tag).
    Parser(const QString &text, const QString &fileName, Diagnostics *diagnostics,
           const XmlLimits &limits)
        : m_reader(text)
        , m_text(text)
        , m_fileName(fileName)
        , m_diagnostics(diagnostics)
        , m_limits(limits)
    {
        m_reader.setNamespaceProcessing(true);
        m_lineStarts.push_back(0);
        for (qsizetype i = 0; i < text.size(); ++i) {
            if (text.at(i) == QLatin1Char('\n'))
                m_lineStarts.push_back(i + 1);
        }
    }

    /// Parses bytes in an encoding other than UTF-8; positions are where start tags end.
    Parser(const QByteArray &data, const QString &fileName, Diagnostics *diagnostics,
           const XmlLimits &limits)
        : m_reader(data)
        , m_fileName(fileName)
        , m_diagnostics(diagnostics)
        , m_limits(limits)
    {
        m_reader.setNamespaceProcessing(true);
    }

    std::optional<XmlNode> run()
    {
        while (!m_reader.atEnd()) {
            m_reader.readNext();
            if (m_reader.isStartElement()) {
                XmlNode root;
                if (!readElement(root, 1))
                    return std::nullopt;
                // Anything but whitespace, comments and PIs after the root is an error.
                while (!m_reader.atEnd()) {
                    m_reader.readNext();
                    if (m_reader.isStartElement()) {
                        fail(tr("extra content after the root element"));
                        return std::nullopt;
                    }
                }
                if (m_reader.hasError()) {
                    failFromReader();
                    return std::nullopt;
                }
                return root;
            }
        }
        if (m_reader.hasError()
            && m_reader.error() != QXmlStreamReader::PrematureEndOfDocumentError)
            failFromReader();
        else
            fail(tr("no root element (empty file?)"));
        return std::nullopt;
    }

private:
    bool readElement(XmlNode &node, int depth)
    {
        if (depth > m_limits.maxDepth) {
            fail(tr("elements nested deeper than %1 levels").arg(m_limits.maxDepth));
            return false;
        }
        m_scopes.push(m_reader.namespaceDeclarations());
        node.namespaceUri = m_pool.intern(m_reader.namespaceUri());
        node.prefix = m_pool.intern(m_reader.prefix());
        node.name = m_pool.intern(m_reader.name());
        node.location = startTagLocation();
        const QXmlStreamAttributes attributes = m_reader.attributes();
        node.attributes.reserve(attributes.size());
        for (const QXmlStreamAttribute &a : attributes) {
            if (a.namespaceUri() == Ns::Xsi && a.name() == QLatin1String("type")) {
                const QString value = a.value().toString().trimmed();
                const qsizetype colon = value.indexOf(QLatin1Char(':'));
                const QString prefix = colon < 0 ? QString() : value.left(colon);
                node.xsiTypeNamespace = m_scopes.resolve(prefix);
                node.xsiTypeName = colon < 0 ? value : value.mid(colon + 1);
                continue;
            }
            node.attributes.append(XmlAttribute{m_pool.intern(a.namespaceUri()),
                                                m_pool.intern(a.prefix()), m_pool.intern(a.name()),
                                                m_pool.intern(a.value())});
        }
        QString text;
        while (!m_reader.atEnd()) {
            switch (m_reader.readNext()) {
            case QXmlStreamReader::StartElement: {
                node.children.emplace_back();
                if (!readElement(node.children.back(), depth + 1))
                    return false;
                break;
            }
            case QXmlStreamReader::Characters:
                // Indentation between child elements carries nothing; skip it cheaply.
                if (!node.children.empty() && m_reader.isWhitespace())
                    break;
                text += m_reader.text();
                break;
            case QXmlStreamReader::EndElement:
                if (!text.trimmed().isEmpty() || node.children.empty())
                    node.text = node.children.empty() ? text : text.trimmed();
                m_scopes.pop();
                return true;
            default:
                break;
            }
        }
        failFromReader();
        return false;
    }

    /// QXmlStreamReader reports where a start tag ends; users want where it begins.
    SourceLocation startTagLocation() const
    {
        if (m_lineStarts.empty())
            return SourceLocation{int(m_reader.lineNumber()), int(m_reader.columnNumber()) + 1};
        const qsizetype end = qMin<qsizetype>(m_reader.characterOffset(), m_text.size());
        const qsizetype lt = m_text.lastIndexOf(QLatin1Char('<'), qMax<qsizetype>(end - 1, 0));
        const qsizetype offset = lt < 0 ? end : lt;
        const auto next = std::upper_bound(m_lineStarts.cbegin(), m_lineStarts.cend(), offset);
        const auto line = int(next - m_lineStarts.cbegin());
        return SourceLocation{line, int(offset - *(next - 1)) + 1};
    }

    void failFromReader()
    {
        QString message = m_reader.errorString();
        if (m_reader.error() == QXmlStreamReader::PrematureEndOfDocumentError || message.isEmpty())
            message = tr("unexpected end of file (truncated?)");
        fail(message);
    }

    void fail(const QString &message)
    {
        if (m_diagnostics) {
            // The reader counts columns from 0 at the start of a line; people count from 1.
            m_diagnostics->append(Diagnostic::error(m_fileName, int(m_reader.lineNumber()),
                                                    int(m_reader.columnNumber()) + 1, message));
        }
    }

    QXmlStreamReader m_reader;
    QString m_text;
    std::vector<qsizetype> m_lineStarts;
    QString m_fileName;
    Diagnostics *m_diagnostics;
    XmlLimits m_limits;
    PrefixScopes m_scopes;
    StringPool m_pool;
};

void collectNamespaces(const XmlNode &node, QList<QPair<QString, QString>> &out)
{
    auto add = [&out](const QString &uri, const QString &prefixHint) {
        if (uri.isEmpty())
            return;
        for (const auto &entry : out) {
            if (entry.first == uri)
                return;
        }
        QString prefix = Ns::preferredPrefix(uri);
        if (prefix.isEmpty())
            prefix = prefixHint;
        for (const auto &entry : out) {
            if (entry.second == prefix)
                prefix.clear(); // clash: let the writer invent one
        }
        if (prefix.isEmpty())
            prefix = QStringLiteral("ns%1").arg(out.size() + 1);
        out.append({uri, prefix});
    };
    add(node.namespaceUri, node.prefix);
    if (!node.xsiTypeName.isEmpty()) {
        add(Ns::Xsi, QStringLiteral("xsi"));
        add(node.xsiTypeNamespace, QString());
    }
    for (const XmlAttribute &a : node.attributes)
        add(a.namespaceUri, a.prefix);
    for (const XmlNode &child : node.children)
        collectNamespaces(child, out);
}

bool isXmlChar(char32_t c)
{
    return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD)
        || (c >= 0x10000 && c <= 0x10FFFF);
}

/// @p text with every character XML 1.0 cannot carry (lone surrogates, most control characters)
/// replaced by U+FFFD, which may stand in names too. A file read in a declared encoding may decode
/// to such characters, in values and names, and QXmlStreamWriter given one stops writing
/// well-formed XML.
QString xmlSafe(const QString &text)
{
    QString result;
    const qsizetype size = text.size();
    for (qsizetype i = 0; i < size; ++i) {
        const QChar c = text.at(i);
        const bool pair = c.isHighSurrogate() && i + 1 < size && text.at(i + 1).isLowSurrogate();
        const char32_t code = pair ? QChar::surrogateToUcs4(c, text.at(i + 1)) : c.unicode();
        const bool ok = !c.isSurrogate() || pair ? isXmlChar(code) : false;
        if (ok && result.isNull()) {
            i += pair ? 1 : 0;
            continue; // nothing replaced so far: the text is copied only when needed
        }
        if (result.isNull())
            result = text.left(i);
        if (ok) {
            result.append(c);
            if (pair)
                result.append(text.at(++i));
        } else {
            result.append(QChar::ReplacementCharacter);
            i += pair ? 1 : 0;
        }
    }
    return result.isNull() ? text : result;
}

// A namespace URI as QXmlStreamWriter needs it: it writes namespace declarations as given, without
// escaping (a URI with '<', '&' or '"' made a file that does not read back), and takes the URI as the
// key of its declarations, so every use passes the same escaped text.
QString namespaceText(const QString &uri)
{
    return xmlSafe(uri)
        .toHtmlEscaped()
        .replace(QLatin1Char('\t'), QLatin1String("&#9;"))
        .replace(QLatin1Char('\n'), QLatin1String("&#10;"))
        .replace(QLatin1Char('\r'), QLatin1String("&#13;"));
}

void writeNode(QXmlStreamWriter &writer, const XmlNode &node,
               const QHash<QString, QString> &prefixes, bool isRoot,
               const QList<QPair<QString, QString>> &declarations)
{
    // Declared before the start tag, the prefixes go onto the root element itself; declared
    // after it, the writer would first invent a prefix of its own for the root's namespace.
    if (isRoot) {
        for (const auto &d : declarations)
            writer.writeNamespace(namespaceText(d.first), xmlSafe(d.second));
    }
    if (node.namespaceUri.isEmpty())
        writer.writeStartElement(xmlSafe(node.name));
    else
        writer.writeStartElement(namespaceText(node.namespaceUri), xmlSafe(node.name));
    if (!node.xsiTypeName.isEmpty()) {
        const QString prefix = prefixes.value(node.xsiTypeNamespace);
        writer.writeAttribute(Ns::Xsi, QStringLiteral("type"),
                              xmlSafe(prefix.isEmpty() ? node.xsiTypeName
                                                       : prefix + QLatin1Char(':') + node.xsiTypeName));
    }
    for (const XmlAttribute &a : node.attributes) {
        if (a.namespaceUri.isEmpty())
            writer.writeAttribute(xmlSafe(a.name), xmlSafe(a.value));
        else
            writer.writeAttribute(namespaceText(a.namespaceUri), xmlSafe(a.name), xmlSafe(a.value));
    }
    if (!node.text.isEmpty())
        writer.writeCharacters(xmlSafe(node.text));
    for (const XmlNode &child : node.children)
        writeNode(writer, child, prefixes, false, declarations);
    writer.writeEndElement();
}

} // namespace

std::optional<XmlNode> parseXml(const QByteArray &data, const QString &fileName,
                                Diagnostics *diagnostics, const XmlLimits &limits)
{
    if (data.size() > limits.maxBytes) {
        if (diagnostics) {
            diagnostics->append(Diagnostic::error(
                fileName, 0, 0, tr("file is larger than %1 bytes").arg(limits.maxBytes)));
        }
        return std::nullopt;
    }
    if (declaresOtherEncoding(data))
        return Parser(data, fileName, diagnostics, limits).run();
    QString text;
    if (!checkUtf8(data, fileName, diagnostics, &text))
        return std::nullopt;
    return Parser(text, fileName, diagnostics, limits).run();
}

QByteArray serializeXml(const XmlNode &root)
{
    QList<QPair<QString, QString>> declarations;
    // OpenRTP's usual order of declarations comes first, then whatever else the tree uses.
    collectNamespaces(root, declarations);
    QHash<QString, QString> prefixes;
    for (const auto &d : declarations)
        prefixes.insert(d.first, d.second);

    QByteArray out;
    QXmlStreamWriter writer(&out);
    writer.setAutoFormatting(true);
    writer.setAutoFormattingIndent(4);
    writer.writeStartDocument(QStringLiteral("1.0"), true);
    writeNode(writer, root, prefixes, true, declarations);
    writer.writeEndDocument();
    return out;
}

} // namespace Profile
