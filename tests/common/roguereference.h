// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QtEndian>

namespace LiveTest {

/// Appends @p value to @p cdr as a little-endian CDR unsigned long, aligned from the start of @p cdr.
inline void appendCdrULong(QByteArray &cdr, quint32 value)
{
    while (cdr.size() % 4)
        cdr.append('\0');
    const quint32 little = qToLittleEndian(value);
    cdr.append(reinterpret_cast<const char *>(&little), sizeof little);
}

/**
 * Appends to the little-endian CDR stream @p cdr (aligned from its start: an encapsulation after its
 * byte order octet, or a whole GIOP message) an object reference whose one IIOP profile does not
 * decode: its host name claims almost 4 GiB and @p padding bytes follow. omniORB 4.2.5 lost such a
 * reference, with its padding, each time it read one.
 */
inline void appendUndecodableReference(QByteArray &cdr, int padding)
{
    const QByteArray type("IDL:omg.org/RTC/LightweightRTObject:1.0");
    appendCdrULong(cdr, quint32(type.size() + 1));
    cdr.append(type).append('\0');
    appendCdrULong(cdr, 1); // one profile
    appendCdrULong(cdr, 0); // TAG_INTERNET_IOP
    QByteArray body("\1\1\2", 3); // little endian, IIOP 1.2
    appendCdrULong(body, 0xfffffff0u); // the host name's length
    body.append(QByteArray(padding, 'x'));
    appendCdrULong(cdr, quint32(body.size()));
    cdr.append(body);
}

/// The same reference as text (`IOR:` and the hex of its encapsulation).
inline QByteArray undecodableReference(int padding)
{
    QByteArray cdr(1, '\1'); // little endian
    appendUndecodableReference(cdr, padding);
    return "IOR:" + cdr.toHex();
}

/// The resident memory of process @p pid in KiB, -1 when unknown.
inline qint64 residentKiB(qint64 pid)
{
    QFile file(QStringLiteral("/proc/%1/status").arg(pid));
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : file.readAll().split('\n')) {
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toLongLong();
    }
    return -1;
}

} // namespace LiveTest
