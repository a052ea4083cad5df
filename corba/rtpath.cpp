// SPDX-License-Identifier: MIT
#include "rtpath.h"

namespace Corba {

namespace {

bool fail(QString *error, const QString &message)
{
    if (error)
        *error = message;
    return false;
}

bool validHostPort(const QString &address)
{
    const int colon = address.lastIndexOf(QLatin1Char(':'));
    if (address.isEmpty() || colon == 0)
        return false;
    if (colon < 0)
        return true;
    bool ok = false;
    const int port = address.mid(colon + 1).toInt(&ok);
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
    if (!text.startsWith(QLatin1String("corbaloc:"))) {
        fail(error, QStringLiteral("not a corbaloc address: %1").arg(text));
        return std::nullopt;
    }
    QString rest = text.mid(9);
    if (rest.startsWith(QLatin1String("iiop:")))
        rest = rest.mid(5);
    else if (rest.startsWith(QLatin1Char(':')))
        rest = rest.mid(1);
    else {
        fail(error, QStringLiteral("unsupported corbaloc protocol: %1").arg(text));
        return std::nullopt;
    }
    const int slash = rest.indexOf(QLatin1Char('/'));
    QString address = slash < 0 ? rest : rest.left(slash);
    const QString key
        = slash < 0 || slash == rest.size() - 1 ? QStringLiteral("manager") : rest.mid(slash + 1);
    if (!address.contains(QLatin1Char(':')))
        address += QStringLiteral(":2810");
    if (!validHostPort(address)) {
        fail(error, QStringLiteral("bad host or port in %1").arg(text));
        return std::nullopt;
    }
    return QStringLiteral("corbaloc:iiop:%1/%2").arg(address, key);
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
    if (!path.elements.isEmpty() && !validHostPort(path.server())) {
        fail(error, QStringLiteral("bad name server address: %1").arg(path.server()));
        return std::nullopt;
    }
    return path;
}

bool RtPath::operator==(const RtPath &other) const
{
    return elements == other.elements && port == other.port && corbaloc == other.corbaloc;
}

QString corbalocWithGiop12(const QString &reference)
{
    static const QLatin1String scheme("corbaloc:");
    if (!reference.startsWith(scheme))
        return reference;
    const qsizetype slash = reference.indexOf(QLatin1Char('/'), scheme.size());
    const qsizetype end = slash < 0 ? reference.size() : slash;
    QStringList addresses = reference.mid(scheme.size(), end - scheme.size()).split(QLatin1Char(','));
    for (QString &address : addresses) {
        // `iiop:host:port` or `:host:port`, without a `version@` of their own
        if (address.contains(QLatin1Char('@')))
            continue;
        if (address.startsWith(QLatin1String("iiop:")))
            address.insert(5, QLatin1String("1.2@"));
        else if (address.startsWith(QLatin1Char(':')))
            address.insert(1, QLatin1String("1.2@"));
    }
    return scheme + addresses.join(QLatin1Char(',')) + reference.mid(end);
}

} // namespace Corba
