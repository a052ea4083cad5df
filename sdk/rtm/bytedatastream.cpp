// SPDX-License-Identifier: MIT
#include <rtm/ByteDataStreamBase.h>
#include <rtm/CORBA_CdrMemoryStream.h>

#include <algorithm>
#include <cstring>

// The serializer registry's one instance lives in this library: every module that registers or
// looks up serializers reaches the same one.
template class coil::GlobalFactory<::RTC::ByteDataStreamBase>;

namespace RTC {

ByteDataStreamBase::ByteDataStreamBase() = default;
ByteDataStreamBase::~ByteDataStreamBase() = default;

void ByteDataStreamBase::init(const coil::Properties &) { }

void ByteDataStreamBase::isLittleEndian(bool) { }

CORBA_CdrMemoryStream::CORBA_CdrMemoryStream()
    : m_endian(true)
{
    m_cdr.setByteSwapFlag(m_endian);
}

CORBA_CdrMemoryStream::CORBA_CdrMemoryStream(const CORBA_CdrMemoryStream &rhs)
    : m_cdr(rhs.m_cdr)
    , m_endian(rhs.m_endian)
{ }

CORBA_CdrMemoryStream &CORBA_CdrMemoryStream::operator=(const CORBA_CdrMemoryStream &rhs)
{
    if (this != &rhs) {
        m_cdr = rhs.m_cdr;
        m_endian = rhs.m_endian;
    }
    return *this;
}

void CORBA_CdrMemoryStream::setEndian(bool little_endian)
{
    m_endian = little_endian;
    m_cdr.rewindPtrs();
    // omniORB's flag names the stream's byte order and swaps where it differs from the host's.
    m_cdr.setByteSwapFlag(little_endian);
}

const unsigned char *CORBA_CdrMemoryStream::getBuffer()
{
    return static_cast<const unsigned char *>(m_cdr.bufPtr());
}

unsigned long CORBA_CdrMemoryStream::getCdrDataLength() const
{
    return m_cdr.bufSize();
}

cdrMemoryStream &CORBA_CdrMemoryStream::getCdr()
{
    return m_cdr;
}

void CORBA_CdrMemoryStream::writeCdrData(const unsigned char *buffer, unsigned long length)
{
    m_cdr.rewindPtrs();
    m_cdr.put_octet_array(buffer, CORBA::ULong(length));
}

void CORBA_CdrMemoryStream::readCdrData(unsigned char *buffer, unsigned long length) const
{
    const unsigned long available = m_cdr.bufSize();
    std::memcpy(buffer, m_cdr.bufPtr(), std::min(length, available));
}

} // namespace RTC
