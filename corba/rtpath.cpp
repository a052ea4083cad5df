// SPDX-License-Identifier: MIT
#include "rtpath.h"

#include <QRegularExpression>

namespace Corba {

namespace {

bool fail(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return false;
}

struct HostPort
{
    QString host;
    QString port;
    bool hasPort = false;
};

// `host`, `host:port`, `[v6 address]` or `[v6 address]:port`.
HostPort splitHostPort(const QString &text)
{
    if (text.startsWith(QLatin1Char('['))) {
        const qsizetype close = text.indexOf(QLatin1Char(']'));
        if (close > 0) {
            const QString rest = text.mid(close + 1);
            return {text.mid(1, close - 1), rest.startsWith(QLatin1Char(':')) ? rest.mid(1) : rest,
                    !rest.isEmpty()};
        }
    }
    const qsizetype colon = text.lastIndexOf(QLatin1Char(':'));
    if (colon < 0)
        return {text, QString(), false};
    return {text.left(colon), text.mid(colon + 1), true};
}

// Control characters, spaces and U+FFFD (what invalid UTF-8 decodes to) have no place in a corbaloc
// URL: its object key escapes them as %xx. The 1-based position of the first one, or 0.
qsizetype badCorbalocCharacter(const QString &text)
{
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        if (c.unicode() <= 0x20 || c.unicode() == 0x7f || c == QChar::ReplacementCharacter)
            return i + 1;
    }
    return 0;
}

// A host name, an IPv4 address or a bracketed IPv6 address, as corbaloc's iiop addresses take.
bool isValidHost(const QString &host, bool bracketed)
{
    static const QRegularExpression name(QStringLiteral("^[A-Za-z0-9_]([A-Za-z0-9._-]*[A-Za-z0-9_])?$"));
    static const QRegularExpression ipv6(QStringLiteral("^[0-9A-Fa-f:.]+(%[A-Za-z0-9._-]+)?$"));
    return (bracketed ? ipv6 : name).match(host).hasMatch();
}

// GIOP's major.minor before '@'.
bool isValidGiopVersion(const QString &version)
{
    static const QRegularExpression pattern(QStringLiteral("^[0-9]+\\.[0-9]+$"));
    return pattern.match(version).hasMatch();
}

// `host` or `host:port` with a port in 1…65535.
bool isValidHostPort(const QString &address)
{
    const HostPort split = splitHostPort(address);
    if (!isValidHost(split.host, address.startsWith(QLatin1Char('['))))
        return false;
    if (!split.hasPort)
        return true;
    bool ok = false;
    const int port = split.port.toInt(&ok);
    return ok && port > 0 && port < 65536;
}

// Appends the elements of `text` to `elements`, applying '.' and '..' as a shell does.
bool appendElements(QStringList &elements, const QString &text, QString *error)
{
    for (const QString &element : text.split(QLatin1Char('/'), Qt::SkipEmptyParts)) {
        if (element == QLatin1String("."))
            continue;
        if (element == QLatin1String("..")) {
            if (!elements.isEmpty())
                elements.removeLast();
            continue;
        }
        if (element.trimmed().isEmpty())
            return fail(error, QStringLiteral("empty path element"));
        elements.append(element);
    }
    return true;
}

// The ':port' suffix belongs to the last element unless that element is the name server itself,
// whose ':' separates host and port.
bool splitPort(RtPath &path, QString *error)
{
    if (path.elements.size() < 2)
        return true;
    QString &last = path.elements.last();
    const int colon = last.indexOf(QLatin1Char(':'));
    if (colon < 0)
        return true;
    path.port = last.mid(colon + 1);
    last.truncate(colon);
    if (last.isEmpty() || path.port.isEmpty())
        return fail(error, QStringLiteral("empty object or port name"));
    return true;
}

} // namespace

QString RtPath::nameServiceAddress() const
{
    QString address = server();
    if (!address.contains(QLatin1Char(':')))
        address += QStringLiteral(":2809");
    return QStringLiteral("corbaloc:iiop:%1/NameService").arg(address);
}

RtPath RtPath::withoutPort() const
{
    RtPath copy = *this;
    copy.port.clear();
    return copy;
}

QString RtPath::toString() const
{
    if (isDirect())
        return corbaloc;
    QString text = QLatin1Char('/') + elements.join(QLatin1Char('/'));
    if (!port.isEmpty())
        text += QLatin1Char(':') + port;
    return text;
}

std::optional<QString> RtPath::normaliseCorbaloc(const QString &text, QString *error)
{
    std::optional<Corbaloc> url = Corbaloc::parse(text);
    if (!url) {
        fail(error, QStringLiteral("not a corbaloc address: %1").arg(text));
        return std::nullopt;
    }
    if (const qsizetype position = badCorbalocCharacter(text)) {
        fail(error, QStringLiteral("character U+%1 at position %2 is not allowed in a corbaloc address")
                        .arg(text.at(position - 1).unicode(), 4, 16, QLatin1Char('0'))
                        .arg(position));
        return std::nullopt;
    }
    for (CorbalocAddress &address : url->addresses) {
        if (!address.isIiop()) {
            fail(error, QStringLiteral("unsupported corbaloc protocol: %1").arg(text));
            return std::nullopt;
        }
        if (address.hasVersion && !isValidGiopVersion(address.version)) {
            fail(error, QStringLiteral("bad GIOP version \"%1\" before '@' in %2").arg(address.version, text));
            return std::nullopt;
        }
        address.protocol = QStringLiteral("iiop");
        if (!address.hasPort())
            address.hostPort += QStringLiteral(":2810");
        if (!isValidHostPort(address.hostPort)) {
            fail(error, QStringLiteral("bad host or port in %1").arg(text));
            return std::nullopt;
        }
    }
    if (url->key.value_or(QString()).isEmpty())
        url->key = QStringLiteral("manager");
    return url->toString();
}

std::optional<RtPath> RtPath::parse(const QString &text, const QString &currentDirectory,
                                    QString *error)
{
    RtPath path;
    if (text.startsWith(QLatin1String("corbaloc:"))) {
        const auto address = normaliseCorbaloc(text, error);
        if (!address)
            return std::nullopt;
        path.corbaloc = *address;
        return path;
    }
    if (!text.startsWith(QLatin1Char('/'))) {
        const QString base = currentDirectory.isEmpty() ? QStringLiteral("/") : currentDirectory;
        if (!base.startsWith(QLatin1Char('/'))) {
            fail(error, QStringLiteral("current directory is not absolute: %1").arg(base));
            return std::nullopt;
        }
        if (!appendElements(path.elements, base, error))
            return std::nullopt;
    }
    if (!appendElements(path.elements, text, error) || !splitPort(path, error))
        return std::nullopt;
    if (!path.elements.isEmpty() && !isValidHostPort(path.server())) {
        fail(error, QStringLiteral("bad name server address: %1").arg(path.server()));
        return std::nullopt;
    }
    return path;
}

bool RtPath::operator==(const RtPath &other) const
{
    return elements == other.elements && port == other.port && corbaloc == other.corbaloc;
}

QString CorbalocAddress::host() const
{
    return splitHostPort(hostPort).host;
}

bool CorbalocAddress::hasPort() const
{
    return splitHostPort(hostPort).hasPort;
}

QString CorbalocAddress::toString() const
{
    return protocol + QLatin1Char(':')
        + (hasVersion ? version + QLatin1Char('@') : QString()) + hostPort;
}

QString Corbaloc::toString() const
{
    QStringList texts;
    for (const CorbalocAddress &address : addresses)
        texts << address.toString();
    return QStringLiteral("corbaloc:") + texts.join(QLatin1Char(','))
        + (key ? QLatin1Char('/') + *key : QString());
}

std::optional<Corbaloc> Corbaloc::parse(const QString &text)
{
    static const QLatin1String scheme("corbaloc:");
    if (!text.startsWith(scheme, Qt::CaseInsensitive))
        return std::nullopt;
    Corbaloc url;
    const qsizetype slash = text.indexOf(QLatin1Char('/'), scheme.size());
    if (slash >= 0)
        url.key = text.mid(slash + 1);
    const QString list = text.mid(scheme.size(), slash < 0 ? -1 : slash - scheme.size());
    for (const QString &item : list.split(QLatin1Char(','))) {
        CorbalocAddress address;
        const qsizetype colon = item.indexOf(QLatin1Char(':'));
        address.protocol = colon < 0 ? item : item.left(colon);
        QString rest = colon < 0 ? QString() : item.mid(colon + 1);
        const qsizetype at = address.isIiop() ? rest.indexOf(QLatin1Char('@')) : -1;
        if (at >= 0) {
            address.hasVersion = true;
            address.version = rest.left(at);
            rest.remove(0, at + 1);
        }
        address.hostPort = rest;
        url.addresses << address;
    }
    return url;
}

QString corbalocWithGiop12(const QString &reference)
{
    std::optional<Corbaloc> url = Corbaloc::parse(reference);
    if (!url)
        return reference;
    for (CorbalocAddress &address : url->addresses) {
        if (address.isIiop() && !address.hasVersion) {
            address.version = QStringLiteral("1.2");
            address.hasVersion = true;
        }
    }
    return url->toString();
}

QString corbalocOverTls(const QString &reference)
{
    std::optional<Corbaloc> url = Corbaloc::parse(reference);
    if (!url)
        return reference;
    for (CorbalocAddress &address : url->addresses) {
        if (address.isIiop()) {
            address.protocol = QStringLiteral("ssliop");
            address.hasVersion = false;
        }
    }
    return url->toString();
}

} // namespace Corba
