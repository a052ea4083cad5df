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

    /**
     * Makes this a port of OpenRTM-aist-Python's CSP channels (CSPInPort, CSPOutPort): it takes
     * connections of `dataport.interface_type` csp_channel and `dataflow_type` duplex only, of any
     * data type, between ports of this process, and carries no samples itself: the Python runtime
     * hands them from port to port.
     */
    void setCspChannel();
    /// PortBase::connect() without a channel's process mark that @p connector_profile may carry
    /// from an earlier connection (a saved system's), which would name a process gone.
    RTC::ReturnCode_t connect(RTC::ConnectorProfile &connector_profile) override;

protected:
    /**
     * The port's own connector settings (`dataport.buffer.length`, …), under those of each
     * connector profile: OpenRTM's port properties (rtc.conf's `port.inport.<name>.*`). None here.
     */
    virtual Properties connectorDefaults() const { return {}; }
    /// @p profile's properties over connectorDefaults().
    Properties connectorProperties(const RTC::ConnectorProfile &profile) const;
    /// How a connection's samples travel.
    enum class Flow : uint8_t {
        Push,   ///< the OutPort sends them to the InPort's interface
        Pull,   ///< the InPort asks the OutPort's interface
        Channel ///< a CSP channel in this process (setCspChannel())
    };
    /// Empty when the profile fits this port; else why not. @p flow tells the data flow.
    std::string checkProfile(const Properties &connectorProperties, Flow *flow) const;
    /// checkProfile() of @p profile's properties @p p; a refusal goes to refused().
    bool fits(const RTC::ConnectorProfile &profile, const Properties &p, Flow *flow) const;
    /**
     * A channel joins ports of one process: the first port to publish writes this process's mark
     * into @p profile, the others check it (checkChannel()).
     */
    RTC::ReturnCode_t joinChannel(RTC::ConnectorProfile &profile) const;
    /// RTC_OK when @p profile bears this process's mark; else BAD_PARAMETER (refused()).
    RTC::ReturnCode_t checkChannel(const RTC::ConnectorProfile &profile) const;
    /// Tells that connector @p profile was refused for @p problem: on standard error, with the
    /// port's name (the SDK's ports write it to the component's log).
    virtual void refused(const RTC::ConnectorProfile &profile, const std::string &problem) const;
    /**
     * A connection may name a marshaling type other than plain `cdr` for this port's side
     * (`outport.marshaling_type`, `inport.marshaling_type`) only when the port has user serializers
     * that make or read those bytes (the Python runtime's ports); typed C++ ports write and read
     * plain CDR and refuse such a connection.
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
    bool m_cspChannel = false;
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
