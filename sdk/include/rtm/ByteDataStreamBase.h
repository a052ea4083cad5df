// SPDX-License-Identifier: MIT
// Serializers: objects that turn one data type into bytes and back, registered by
// "<repository id>:<marshaling type>" in a process-wide factory (OpenRTM-aist's ByteDataStream).
#ifndef RTC_BYTEDATASTREAMBASE_H
#define RTC_BYTEDATASTREAMBASE_H

#include <coil/Factory.h>
#include <coil/Properties.h>
#include <rtm/Typename.h>

#include <algorithm>
#include <string>
#include <vector>

namespace RTC
{
/// The byte side of a serializer: a buffer that is written, read and sized.
class ByteDataStreamBase
{
public:
    ByteDataStreamBase();
    virtual ~ByteDataStreamBase();
    /// Takes the connector's serializer options; the base takes none.
    virtual void init(const coil::Properties &prop);
    /// Replaces the buffer with `length` bytes from `buffer`.
    virtual void writeData(const unsigned char *buffer, unsigned long length) = 0;
    /// Copies `length` bytes of the buffer into `buffer`.
    virtual void readData(unsigned char *buffer, unsigned long length) const = 0;
    /// The number of bytes in the buffer.
    virtual unsigned long getDataLength() const = 0;
    /// Chooses the byte order of what serialize() writes; the base ignores it.
    virtual void isLittleEndian(bool little_endian);
};

/// A serializer of DataType.
template <typename DataType>
class ByteDataStream : public ByteDataStreamBase
{
public:
    ByteDataStream() {}
    ~ByteDataStream() override {}
    /// Writes `data` into the buffer; false when it cannot be encoded.
    virtual bool serialize(const DataType &data) = 0;
    /// Reads `data` from the buffer; false when the buffer holds no such value.
    virtual bool deserialize(DataType &data) = 0;
};

/// The process-wide registry of serializers.
typedef coil::GlobalFactory<ByteDataStreamBase> SerializerFactory;

/// The factory key of DataType's serializer for `marshalingtype` ("IDL:RTC/TimedLong:1.0:cdr").
template <class DataType>
std::string addDataTypeToMarshalingType(const std::string &marshalingtype)
{
    return std::string(::CORBA_Util::toRepositoryId<DataType>()) + ":" + marshalingtype;
}

/// Registers SerializerType as DataType's serializer for `marshalingtype`.
template <class DataType, class SerializerType>
void addSerializer(const std::string &marshalingtype)
{
    SerializerFactory::instance().addFactory(addDataTypeToMarshalingType<DataType>(marshalingtype),
                                             ::coil::Creator< ::RTC::ByteDataStreamBase, SerializerType>,
                                             ::coil::Destructor< ::RTC::ByteDataStreamBase, SerializerType>);
}

/// Unregisters DataType's serializer for `marshalingtype`.
template <class DataType>
void removeSerializer(const std::string &marshalingtype)
{
    SerializerFactory::instance().removeFactory(addDataTypeToMarshalingType<DataType>(marshalingtype));
}

/// A new serializer of DataType for `marshalingtype`, or nullptr; delete it through the factory.
template <class DataType>
::RTC::ByteDataStreamBase *createSerializer(const std::string &marshalingtype)
{
    return SerializerFactory::instance().createObject(addDataTypeToMarshalingType<DataType>(marshalingtype));
}

/// The marshaling types registered for DataType.
template <class DataType>
std::vector<std::string> getSerializerList()
{
    const std::string prefix = std::string(::CORBA_Util::toRepositoryId<DataType>()) + ":";
    std::vector<std::string> types;
    const std::vector<std::string> keys = SerializerFactory::instance().getIdentifiers();
    for (std::vector<std::string>::const_iterator key = keys.begin(); key != keys.end(); ++key) {
        if (key->compare(0, prefix.size(), prefix) == 0)
            types.push_back(key->substr(prefix.size()));
    }
    return types;
}
} // namespace RTC

EXTERN template class DLL_PLUGIN coil::GlobalFactory< ::RTC::ByteDataStreamBase>;

#endif // RTC_BYTEDATASTREAMBASE_H
