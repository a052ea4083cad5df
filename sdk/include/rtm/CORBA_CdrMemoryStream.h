// SPDX-License-Identifier: MIT
// CDR encoding of IDL data types in memory (omniORB's cdrMemoryStream), and the "cdr" serializer
// built on it.
#ifndef RTC_CORBA_CDRMEMORYSTREAM_H
#define RTC_CORBA_CDRMEMORYSTREAM_H

#include <rtm/ByteDataStreamBase.h>
#include <rtm/RTC.h>
#include <rtm/idl/DataPort_OpenRTMSkel.h>

#include <omniORB4/cdrStream.h>

namespace RTC
{
/// A CDR buffer: values are encoded into it in the chosen byte order and decoded from it.
class CORBA_CdrMemoryStream
{
public:
    CORBA_CdrMemoryStream();

    /// Replaces the buffer's content with `data` encoded; false when encoding fails.
    template <class ExDataType>
    bool serializeCDR(const ExDataType &data)
    {
        try {
            m_cdr.rewindPtrs();
            m_cdr.setByteSwapFlag(m_endian);
            data >>= m_cdr;
            return true;
        } catch (...) {
            return false;
        }
    }
    /// Decodes `data` from the buffer's content; false when it holds no such value.
    template <class ExDataType>
    bool deserializeCDR(ExDataType &data)
    {
        try {
            m_cdr.rewindInputPtr();
            data <<= m_cdr;
            return true;
        } catch (...) {
            return false;
        }
    }
    /// The byte order of the encoding (true: little-endian); empties the buffer.
    void setEndian(bool little_endian);
    /// The encoded bytes (getCdrDataLength() of them).
    const unsigned char *getBuffer();
    unsigned long getCdrDataLength() const;
    /// omniORB's stream itself.
    cdrMemoryStream &getCdr();
    /// Replaces the buffer's content with `length` encoded bytes from `buffer`.
    void writeCdrData(const unsigned char *buffer, unsigned long length);
    /// Copies `length` bytes of the content (at most getCdrDataLength()) into `buffer`.
    void readCdrData(unsigned char *buffer, unsigned long length) const;

    CORBA_CdrMemoryStream(const CORBA_CdrMemoryStream &rhs);
    CORBA_CdrMemoryStream &operator=(const CORBA_CdrMemoryStream &rhs);

protected:
    cdrMemoryStream m_cdr;
    bool m_endian;
};

/// OpenRTM-aist's "cdr" serializer of DataType.
template <class DataType>
class CORBA_CdrSerializer : public ByteDataStream<DataType>
{
public:
    CORBA_CdrSerializer() {}
    ~CORBA_CdrSerializer() override {}
    void init(const coil::Properties &) override {}
    void writeData(const unsigned char *buffer, unsigned long length) override
    {
        m_cdr.writeCdrData(buffer, length);
    }
    void readData(unsigned char *buffer, unsigned long length) const override
    {
        m_cdr.readCdrData(buffer, length);
    }
    unsigned long getDataLength() const override { return m_cdr.getCdrDataLength(); }
    bool serialize(const DataType &data) override { return m_cdr.serializeCDR(data); }
    bool deserialize(DataType &data) override { return m_cdr.deserializeCDR(data); }
    CORBA_CdrSerializer(const CORBA_CdrSerializer<DataType> &rhs)
        : ByteDataStream<DataType>()
        , m_cdr(rhs.m_cdr)
    {
    }
    CORBA_CdrSerializer<DataType> &operator=(const CORBA_CdrSerializer<DataType> &rhs)
    {
        m_cdr = rhs.m_cdr;
        return *this;
    }
    void isLittleEndian(bool little_endian) override { m_cdr.setEndian(little_endian); }

protected:
    CORBA_CdrMemoryStream m_cdr;
};
} // namespace RTC

/// Registers the "cdr" serializer of DataType.
template <class DataType>
void CdrMemoryStreamInit()
{
    ::RTC::addSerializer<DataType, ::RTC::CORBA_CdrSerializer<DataType> >("cdr");
}

#endif // RTC_CORBA_CDRMEMORYSTREAM_H
