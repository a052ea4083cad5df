// SPDX-License-Identifier: MIT
#include "pyiorform.h"

#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <QtEndian>

#include <stdexcept>

namespace RtPython::IorForm {

namespace {

/// Reads an IOR's encapsulation: its byte order first, every later field aligned from its start.
class EncapsulationReader
{
public:
    explicit EncapsulationReader(QByteArray bytes)
        : m_bytes(std::move(bytes))
    {
        m_little = take(1).at(0) != 0;
    }

    quint32 ulong()
    {
        m_offset = (m_offset + 3) & ~qsizetype(3);
        const QByteArray field = take(4);
        const auto *data = reinterpret_cast<const uchar *>(field.constData());
        return m_little ? qFromLittleEndian<quint32>(data) : qFromBigEndian<quint32>(data);
    }

    QByteArray take(qsizetype size)
    {
        if (size < 0 || m_offset + size > m_bytes.size())
            throw std::runtime_error("the IOR ends before its fields do");
        const QByteArray field = m_bytes.mid(m_offset, size);
        m_offset += size;
        return field;
    }

private:
    QByteArray m_bytes;
    qsizetype m_offset = 0;
    bool m_little = false;
};

void appendUlong(QByteArray *bytes, quint32 value)
{
    while (bytes->size() % 4 != 0)
        bytes->append('\0');
    uchar field[4];
    qToLittleEndian(value, field);
    bytes->append(reinterpret_cast<const char *>(field), 4);
}

} // namespace

QJsonValue fromIor(const std::string &ior)
{
    if (ior.rfind("IOR:", 0) != 0)
        throw std::runtime_error("not a stringified IOR: " + ior.substr(0, 16));
    EncapsulationReader reader(QByteArray::fromHex(QByteArray::fromStdString(ior.substr(4))));
    QByteArray typeId = reader.take(reader.ulong());
    if (typeId.endsWith('\0'))
        typeId.chop(1);
    QJsonArray profiles;
    for (quint32 count = reader.ulong(); count > 0; --count) {
        const quint32 tag = reader.ulong();
        profiles.append(QJsonObject{{QStringLiteral("tag"), qint64(tag)},
                                    {QStringLiteral("data"), QString::fromLatin1(reader.take(reader.ulong()).toHex())}});
    }
    if (typeId.isEmpty() && profiles.isEmpty())
        return QJsonValue::Null;
    return QJsonObject{{QStringLiteral("type_id"), QString::fromUtf8(typeId)}, {QStringLiteral("profiles"), profiles}};
}

std::string toIor(const QJsonValue &reference)
{
    QByteArray bytes(1, '\1'); // little endian
    const QByteArray typeId = reference[QStringLiteral("type_id")].toString().toUtf8() + '\0';
    appendUlong(&bytes, quint32(typeId.size()));
    bytes.append(typeId);
    const QJsonArray profiles = reference[QStringLiteral("profiles")].toArray();
    appendUlong(&bytes, quint32(profiles.size()));
    for (const QJsonValue &profile : profiles) {
        appendUlong(&bytes, quint32(profile[QStringLiteral("tag")].toInteger()));
        const QByteArray data = QByteArray::fromHex(profile[QStringLiteral("data")].toString().toLatin1());
        appendUlong(&bytes, quint32(data.size()));
        bytes.append(data);
    }
    return "IOR:" + bytes.toHex().toStdString();
}

} // namespace RtPython::IorForm
