// SPDX-License-Identifier: MIT
// Marshalled sample streams: what data connectors read samples into and write them from.
#ifndef RTC_BYTEDATASTREAMBASE_H
#define RTC_BYTEDATASTREAMBASE_H

#include <coil/Properties.h>

namespace RTC {
/// A sample in marshalled form with its byte order.
class ByteDataStreamBase
{
public:
    ByteDataStreamBase();
    virtual ~ByteDataStreamBase();
    virtual void init(const coil::Properties &prop);
    /// Replaces the stream's bytes with @p length bytes from @p buffer.
    virtual void writeData(const unsigned char *buffer, unsigned long length) = 0;
    /// Copies up to @p length of the stream's bytes into @p buffer.
    virtual void readData(unsigned char *buffer, unsigned long length) const = 0;
    virtual unsigned long getDataLength() const = 0;
    /// Sets the byte order the stream's bytes are in.
    virtual void isLittleEndian(bool little_endian);
};

/// A stream that turns samples of @p DataType into bytes and back.
template<typename DataType> class ByteDataStream : public ByteDataStreamBase
{
public:
    ByteDataStream() = default;
    ~ByteDataStream() override = default;
    virtual bool serialize(const DataType &data) = 0;
    virtual bool deserialize(DataType &data) = 0;
};
} // namespace RTC

#endif // RTC_BYTEDATASTREAMBASE_H
