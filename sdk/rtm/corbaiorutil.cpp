// SPDX-License-Identifier: MIT
#include <rtm/CORBA_IORUtil.h>

#include <omniORB4/cdrStream.h>

#include <cstring>
#include <iomanip>
#include <sstream>

namespace CORBA_IORUtil {

namespace {

const char iorPrefix[] = "IOR:";

int hexDigit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

std::string hexOf(const CORBA::Octet *data, CORBA::ULong length)
{
    std::ostringstream text;
    text << std::hex << std::setfill('0');
    for (CORBA::ULong i = 0; i < length; ++i)
        text << std::setw(2) << unsigned(data[i]);
    return text.str();
}

// Printable bytes as they are, others as %xx (how omniORB's catior shows object keys).
std::string keyText(const _CORBA_Unbounded_Sequence_Octet &key)
{
    std::ostringstream text;
    for (CORBA::ULong i = 0; i < key.length(); ++i) {
        const unsigned char c = key[i];
        if (c >= 0x20 && c < 0x7f && c != '%')
            text << char(c);
        else
            text << '%' << std::hex << std::setw(2) << std::setfill('0') << unsigned(c) << std::dec;
    }
    return text.str();
}

void formatComponents(std::ostringstream &out, const IOP::MultipleComponentProfile &components)
{
    for (CORBA::ULong i = 0; i < components.length(); ++i) {
        const IOP::TaggedComponent &component = components[i];
        const char *name = IOP::ComponentIDtoName(component.tag);
        out << "    Component: " << (name ? name : "unknown tag") << " (" << component.tag << "), "
            << component.component_data.length() << " octets";
        if (component.tag == IOP::TAG_ALTERNATE_IIOP_ADDRESS) {
            std::vector<IIOP::Address> alternate;
            IOP::MultipleComponentProfile one;
            one.length(1);
            one[0] = component;
            extractAddrs(one, alternate);
            for (const IIOP::Address &address : alternate)
                out << ": " << static_cast<const char *>(address.host) << ':' << address.port;
        }
        out << '\n';
    }
}

} // namespace

bool toIOR(const char *iorstr, IOP::IOR &ior)
{
    if (!iorstr || std::strncmp(iorstr, iorPrefix, sizeof(iorPrefix) - 1) != 0)
        return false;
    const char *hex = iorstr + sizeof(iorPrefix) - 1;
    const size_t digits = std::strlen(hex);
    if (digits < 2 || digits % 2 != 0)
        return false;
    CORBA::OctetSeq octets;
    octets.length(CORBA::ULong(digits / 2));
    for (CORBA::ULong i = 0; i < octets.length(); ++i) {
        const int high = hexDigit(hex[2 * i]);
        const int low = hexDigit(hex[2 * i + 1]);
        if (high < 0 || low < 0)
            return false;
        octets[i] = CORBA::Octet(high * 16 + low);
    }
    try {
        // A stringified IOR is a CDR encapsulation: its first octet gives the byte order.
        cdrEncapsulationStream stream(octets.get_buffer(), octets.length());
        ior.type_id = IOP::IOR::unmarshaltype_id(stream);
        ior.profiles <<= stream;
    } catch (const CORBA::SystemException &) {
        return false;
    }
    return true;
}

bool toString(IOP::IOR &ior, std::string &iorstr)
{
    cdrEncapsulationStream stream(CORBA::ULong(0), true);
    ior >>= stream;
    iorstr
        = iorPrefix + hexOf(static_cast<const CORBA::Octet *>(stream.bufPtr()), stream.bufSize());
    return true;
}

bool replaceEndpoint(std::string &iorstr, const std::string &endpoint)
{
    IOP::IOR ior;
    if (!toIOR(iorstr.c_str(), ior))
        return false;
    for (CORBA::ULong i = 0; i < ior.profiles.length(); ++i) {
        if (ior.profiles[i].tag != IOP::TAG_INTERNET_IOP)
            continue;
        IIOP::ProfileBody body;
        IIOP::unmarshalProfile(ior.profiles[i], body);
        body.address.host = CORBA::string_dup(endpoint.c_str());
        IOP::TaggedProfile encoded;
        IIOP::encodeProfile(body, encoded);
        ior.profiles[i] = encoded;
    }
    return toString(ior, iorstr);
}

std::string formatIORinfo(const char *iorstr)
{
    IOP::IOR ior;
    if (!toIOR(iorstr, ior))
        return "IOR is invalid\n";
    std::ostringstream out;
    out << "IOR information\n";
    out << "  Type ID: " << static_cast<const char *>(ior.type_id) << '\n';
    out << "  Profiles: " << ior.profiles.length() << '\n';
    for (CORBA::ULong i = 0; i < ior.profiles.length(); ++i) {
        const IOP::TaggedProfile &profile = ior.profiles[i];
        if (profile.tag == IOP::TAG_INTERNET_IOP) {
            IIOP::ProfileBody body;
            IIOP::unmarshalProfile(profile, body);
            out << "  IIOP profile " << int(body.version.major) << '.' << int(body.version.minor)
                << '\n'
                << "    Address: " << static_cast<const char *>(body.address.host) << ':'
                << body.address.port << '\n'
                << "    Object key: \"" << keyText(body.object_key) << "\"\n";
            formatComponents(out, body.components);
        } else if (profile.tag == IOP::TAG_MULTIPLE_COMPONENTS) {
            IOP::MultipleComponentProfile components;
            IIOP::unmarshalMultiComponentProfile(profile, components);
            out << "  Multiple components profile\n";
            formatComponents(out, components);
        } else {
            out << "  Profile of unknown tag " << profile.tag << ", "
                << profile.profile_data.length() << " octets\n";
        }
    }
    return out.str();
}

std::vector<IIOP::Address> getEndpoints(IOP::IOR &ior)
{
    std::vector<IIOP::Address> addresses;
    for (CORBA::ULong i = 0; i < ior.profiles.length(); ++i) {
        const IOP::TaggedProfile &profile = ior.profiles[i];
        if (profile.tag == IOP::TAG_INTERNET_IOP) {
            IIOP::ProfileBody body;
            IIOP::unmarshalProfile(profile, body);
            addresses.push_back(body.address);
            extractAddrs(body.components, addresses);
        } else if (profile.tag == IOP::TAG_MULTIPLE_COMPONENTS) {
            IOP::MultipleComponentProfile components;
            IIOP::unmarshalMultiComponentProfile(profile, components);
            extractAddrs(components, addresses);
        }
    }
    return addresses;
}

void extractAddrs(IOP::MultipleComponentProfile &comp, std::vector<IIOP::Address> &addr)
{
    for (CORBA::ULong i = 0; i < comp.length(); ++i) {
        if (comp[i].tag != IOP::TAG_ALTERNATE_IIOP_ADDRESS)
            continue;
        try {
            // The component data is an encapsulation holding one host and port.
            cdrEncapsulationStream stream(comp[i].component_data.get_buffer(),
                                          comp[i].component_data.length(), 1);
            IIOP::Address address;
            address <<= stream;
            addr.push_back(address);
        } catch (const CORBA::SystemException &) {
            // A malformed component carries no address.
        }
    }
}

} // namespace CORBA_IORUtil
