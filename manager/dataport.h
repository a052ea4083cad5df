// SPDX-License-Identifier: MIT
#pragma once

#include "corbautil.h"
#include "portbase.h"
#include "ringbuffer.h"

// The standard data types come first: repositoryId<T>() finds their Any operators by ordinary lookup.
#include <BasicDataType.hh>
#include <ExtendedDataTypes.hh>
#include <InterfaceDataTypes.hh>
#include <RTC.hh>

#include <string>

namespace Runtime {

/**
 * What data ports share: the OpenRTM port profile properties and the check of a connector profile
 * (`dataport.interface_type` corba_cdr, `dataflow_type` push|pull, `subscription_type`, `data_type`).
 */
class DataPortBase : public PortBase
{
public:
    /// @p portType is DataInPort or DataOutPort; @p dataType the repository id of the sample type.
    DataPortBase(const std::string &name, const std::string &portType, const std::string &dataType);
    const std::string &dataType() const { return m_dataType; }

protected:
    /// Empty when the profile fits this port; else why not. @p pull tells the data flow.
    std::string checkProfile(const Properties &connectorProperties, bool *pull) const;
    /**
     * An OutPort's connections may name an `outport.marshaling_type` other than plain `cdr`: the
     * port's user serializers make those bytes (the Python runtime's OutPorts); typed C++ OutPorts
     * write plain CDR. (InPorts are not checked here: the SDK refuses for its typed ones.)
     */
    void setUserSerializers(bool enabled) { m_userSerializers = enabled; }
    /// Besides the duplicate check, OpenRTM-aist's limit on connections: an InPort takes
    /// `dataport.inport.fan_in`, an OutPort `dataport.outport.fan_out` of them (the port's own
    /// `fan_in` / `fan_out` first; 100 when neither says).
    RTC::ReturnCode_t admit(const RTC::ConnectorProfile &profile) override;

    /// Offers @p reference in @p profile as OpenRTM's corba_cdr interface type does: its IOR under
    /// `dataport.corba_cdr.<end>_ior` and the reference itself under `<end>_ref` (@p end is
    /// `inport` or `outport`).
    template<typename Reference>
    static void offerInterface(RTC::ConnectorProfile &profile, const std::string &end,
                               Reference reference)
    {
        const std::string key = "dataport.corba_cdr." + end;
        CORBA::String_var ior = theOrb()->object_to_string(reference);
        nvSet(profile.properties, key + "_ior", std::string(ior.in()));
        const CORBA::ULong n = profile.properties.length();
        profile.properties.length(n + 1);
        profile.properties[n].name = (key + "_ref").c_str();
        profile.properties[n].value <<= reference;
    }

    /// The peer's interface that `dataport.corba_cdr.<end>_ior` of @p connectorProperties names;
    /// nil when the key is missing or names no object.
    template<typename Interface>
    static typename Interface::_ptr_type peerInterface(const Properties &connectorProperties,
                                                       const std::string &end)
    {
        const std::string ior = connectorProperties.value("dataport.corba_cdr." + end + "_ior");
        if (ior.empty())
            return Interface::_nil();
        try {
            CORBA::Object_var object = theOrb()->string_to_object(ior.c_str());
            return Interface::_unchecked_narrow(object);
        } catch (const CORBA::Exception &) {
            return Interface::_nil();
        }
    }

private:
    std::string m_dataType;
    bool m_input;
    bool m_userSerializers = false;
};

/// A connection's marshaling type for one side (`inport`, `outport`): the side's own, else the
/// connection's, else plain `cdr`.
std::string marshalingType(const Properties &connectorProperties, const std::string &side);

/**
 * Marshals @p value as CDR in the given byte order into this thread's stream, which is kept
 * between calls (a large sample does not regrow a buffer each time). The view is valid until the
 * thread marshals again.
 */
template <typename T>
CdrView marshalView(const T &value, bool littleEndian)
{
    thread_local cdrMemoryStream stream;
    stream.rewindPtrs();
    stream.setByteSwapFlag(littleEndian);
    value >>= stream;
    return {static_cast<const unsigned char *>(stream.bufPtr()), size_t(stream.bufSize())};
}

/// Marshals @p value as CDR in the given byte order.
template <typename T>
CdrBytes marshal(const T &value, bool littleEndian)
{
    return marshalView(value, littleEndian).bytes();
}

/**
 * A CDR stream reading received bytes. omniORB's own check of a sequence length multiplies element
 * size and count in 32 bits, so a length near 2^32 / size passes it and a put of a few bytes makes
 * the sequence allocate gigabytes; the check here is done in 64 bits.
 */
class CdrInputStream : public cdrMemoryStream
{
public:
    explicit CdrInputStream(const CdrView &data)
        : cdrMemoryStream(const_cast<unsigned char *>(data.data), data.size)
    {
    }
    CORBA::Boolean checkInputOverrun(CORBA::ULong itemSize, CORBA::ULong count,
                                     omni::alignment_t align = omni::ALIGN_1) override
    {
        const omni::ptr_arith_t start = omni::align_to(omni::ptr_arith_t(pd_inb_mkr), align);
        const omni::ptr_arith_t end = omni::ptr_arith_t(pd_inb_end);
        return start <= end && uint64_t(itemSize) * count <= end - start
               && cdrMemoryStream::checkInputOverrun(itemSize, count, align);
    }
};

/// Unmarshals @p data into @p value; false when the bytes do not hold a T.
template <typename T>
bool unmarshal(const CdrView &data, bool littleEndian, T *value)
{
    try {
        CdrInputStream stream(data);
        stream.setByteSwapFlag(littleEndian);
        *value <<= stream;
        return true;
    } catch (const CORBA::Exception &) {
        return false;
    }
}

template <typename T>
bool unmarshal(const CdrBytes &data, bool littleEndian, T *value)
{
    return unmarshal(CdrView::of(data), littleEndian, value);
}

/// Repository id of an IDL type, taken from its TypeCode (declare its Any operators before this header for user types).
template <typename T>
std::string repositoryId()
{
    CORBA::Any any;
    any <<= T();
    CORBA::TypeCode_var type = any.type();
    return type->id();
}

} // namespace Runtime
