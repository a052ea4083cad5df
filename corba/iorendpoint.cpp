// SPDX-License-Identifier: MIT
#include "iorendpoint.h"

#include <QByteArray>

#include <optional>

namespace Corba {

namespace {

// A bounds-checked reader of a CDR encapsulation (CORBA 3.0 §15.3); every read fails softly.
class CdrReader
{
public:
    explicit CdrReader(QByteArray data)
        : m_data(std::move(data))
    {
        // The first octet of an encapsulation is its byte order (1 = little endian).
        const auto order = octet();
        m_little = order && *order == 1;
    }

    std::optional<quint8> octet()
    {
        if (m_pos >= m_data.size())
            return std::nullopt;
        return quint8(m_data.at(m_pos++));
    }
    std::optional<quint32> ulong()
    {
        align(4);
        return number(4);
    }
    std::optional<quint16> ushort()
    {
        align(2);
        const auto value = number(2);
        return value ? std::optional<quint16>(quint16(*value)) : std::nullopt;
    }
    std::optional<QByteArray> bytes()
    {
        const auto length = ulong();
        if (!length || *length > quint32(m_data.size() - m_pos))
            return std::nullopt;
        const QByteArray result = m_data.mid(m_pos, int(*length));
        m_pos += int(*length);
        return result;
    }
    bool skip(int count)
    {
        if (count > m_data.size() - m_pos)
            return false;
        m_pos += count;
        return true;
    }

private:
    void align(int n) { m_pos = (m_pos + n - 1) / n * n; }
    std::optional<quint32> number(int size)
    {
        if (m_pos + size > m_data.size())
            return std::nullopt;
        quint32 value = 0;
        for (int i = 0; i < size; ++i) {
            const quint32 byte = quint8(m_data.at(m_pos + (m_little ? size - 1 - i : i)));
            value = (value << 8) | byte;
        }
        m_pos += size;
        return value;
    }

    QByteArray m_data;
    int m_pos = 0;
    bool m_little = false;
};

// The port of a TAG_SSL_SEC_TRANS component (CORBA Security, SSLIOP): its encapsulation holds the
// association options the target supports and requires, then the port.
std::optional<quint16> sslPort(const QByteArray &component)
{
    CdrReader reader(component);
    if (!reader.ushort() || !reader.ushort())
        return std::nullopt;
    return reader.ushort();
}

QString iiopEndpoint(const QByteArray &profile)
{
    CdrReader reader(profile);
    const auto major = reader.octet();
    const auto minor = reader.octet();
    const auto host = reader.bytes();
    auto port = reader.ushort();
    if (!major || !minor || !host || !port)
        return {};
    // A TLS-only server publishes port 0 and its TLS port in a component (IIOP 1.1 and later).
    constexpr quint32 tagSslSecTrans = 20;
    if (*port == 0 && (*major > 1 || *minor >= 1) && reader.bytes()) {
        const auto components = reader.ulong();
        for (quint32 i = 0; components && i < *components && i < 64; ++i) {
            const auto tag = reader.ulong();
            const auto data = reader.bytes();
            if (!tag || !data)
                break;
            if (*tag == tagSslSecTrans) {
                port = sslPort(*data);
                break;
            }
        }
        if (!port)
            return {};
    }
    QByteArray name = *host;
    if (name.endsWith('\0'))
        name.chop(1);
    return QString::fromLatin1(name) + QLatin1Char(':') + QString::number(*port);
}

} // namespace

QString iorEndpoint(const QString &ior)
{
    if (!ior.startsWith(QLatin1String("IOR:"), Qt::CaseInsensitive))
        return {};
    const QByteArray data = QByteArray::fromHex(ior.mid(4).toLatin1());
    CdrReader reader(data);
    if (!reader.bytes()) // repository id
        return {};
    const auto profiles = reader.ulong();
    if (!profiles)
        return {};
    constexpr quint32 tagInternetIop = 0;
    for (quint32 i = 0; i < *profiles && i < 64; ++i) {
        const auto tag = reader.ulong();
        const auto body = reader.bytes();
        if (!tag || !body)
            return {};
        if (*tag == tagInternetIop)
            return iiopEndpoint(*body);
    }
    return {};
}

} // namespace Corba
