// SPDX-License-Identifier: MIT
#include <rtm/CORBA_RTCUtil.h>

#include <cstdlib>
#include <utility>

namespace CORBA_RTCUtil {

namespace {

bool startsWith(const std::string &text, const std::string &prefix)
{
    return text.compare(0, prefix.size(), prefix) == 0;
}

// Endpoint spellings of omniORB, TAO and OpenRTM-aist's configuration, and what they are in
// corbaloc. The first list is tried before the second: "iiop://" must win over "iiop:".
const std::pair<const char *, const char *> endpointForms[] = {
    {"giop:tcp:", "corbaloc:iiop:"},
    {"giop:ssl:", "corbaloc:ssliop:"},
    {"giop:http:", ""},
    {"giop::", "corbaloc:iiop:"},
    {"iiop://", "corbaloc:iiop:"},
    {"diop://", "corbaloc:diop:"},
    {"uiop://", "corbaloc:uiop:"},
    {"ssliop://", "corbaloc:ssliop:"},
    {"shmiop://", "corbaloc:shmiop:"},
    {"htiop://", "corbaloc:htiop:"},
    {"inet:", "corbaloc:iiop:"},
};
const std::pair<const char *, const char *> shortForms[] = {
    {"iiop:", "corbaloc:iiop:"},     {"ssliop:", "corbaloc:ssliop:"}, {"diop:", "corbaloc:diop:"},
    {"shmiop:", "corbaloc:shmiop:"}, {"htiop:", "corbaloc:htiop:"},
};

template<size_t N>
bool rewritePrefix(std::string &uri, const std::pair<const char *, const char *> (&forms)[N])
{
    for (const auto &form : forms) {
        if (startsWith(uri, form.first)) {
            uri = form.second + uri.substr(std::string(form.first).size());
            return true;
        }
    }
    return false;
}

// "host:port", "[v6]:port" or "host" into its parts; a missing port is CORBA's default, 2809.
void splitHostPort(const std::string &address, std::string *host, unsigned short *port)
{
    std::string::size_type colon;
    if (startsWith(address, "[")) {
        const std::string::size_type close = address.find(']');
        *host = address.substr(1, close == std::string::npos ? std::string::npos : close - 1);
        colon = close == std::string::npos ? close : address.find(':', close);
    } else {
        colon = address.rfind(':');
        *host = address.substr(0, colon);
    }
    *port = 2809;
    if (colon != std::string::npos && colon + 1 < address.size())
        *port = static_cast<unsigned short>(std::strtoul(address.c_str() + colon + 1, nullptr, 10));
}

} // namespace

CorbaURI::CorbaURI(std::string uri, const std::string &objkey)
    : m_port(0)
    , m_addressonly(false)
{
    if (!rewritePrefix(uri, endpointForms))
        rewritePrefix(uri, shortForms);
    m_fragment = objkey;
    if (startsWith(uri, "corbaloc:")) {
        m_protocol = "corbaloc";
        // corbaloc:<protocol>:<address>[,<address>…][/<key>]
        const std::string rest = uri.substr(std::string("corbaloc:").size());
        const std::string::size_type keyAt = rest.find('/');
        const std::string addresses = rest.substr(0, keyAt);
        const std::string first = addresses.substr(0, addresses.find(','));
        const std::string::size_type protocolEnd = first.find(':');
        if (protocolEnd != std::string::npos)
            splitHostPort(first.substr(protocolEnd + 1), &m_host, &m_port);
        m_uri = uri;
        if (keyAt != std::string::npos) {
            m_path = rest.substr(keyAt + 1);
        } else if (!objkey.empty()) {
            m_uri += "/" + objkey;
            m_path = objkey;
        }
    } else if (startsWith(uri, "corbaname:")) {
        m_protocol = "corbaname";
        m_uri = uri;
        if (uri.find('#') == std::string::npos && !objkey.empty())
            m_uri += "#" + objkey;
    } else {
        // A bare address: an IIOP endpoint of the given host and port.
        m_protocol = "corbaloc";
        m_addressonly = true;
        splitHostPort(uri, &m_host, &m_port);
        m_uri = "corbaloc:iiop:" + uri;
        if (!objkey.empty()) {
            m_uri += "/" + objkey;
            m_path = objkey;
        }
    }
}

CorbaURI::~CorbaURI() = default;

std::string CorbaURI::toString() const
{
    return m_uri;
}

std::string CorbaURI::getProtocol() const
{
    return m_protocol;
}

std::string CorbaURI::getHost() const
{
    return m_host;
}

unsigned short CorbaURI::getPort() const
{
    return m_port;
}

bool CorbaURI::isAddressOnly() const
{
    return m_addressonly;
}

RTCURIObject::RTCURIObject(const std::string &uri, bool isrtcname, bool isrtcloc)
    : m_is_rtcname(false)
    , m_is_rtcloc(false)
{
    const std::string::size_type schemeEnd = uri.find("://");
    if (schemeEnd == std::string::npos)
        return;
    const std::string scheme = uri.substr(0, schemeEnd);
    const bool byName = startsWith(scheme, "rtcname");
    const bool byManager = startsWith(scheme, "rtcloc");
    if ((!byName && !byManager) || (isrtcname && !byName) || (isrtcloc && !byManager))
        return;
    m_is_rtcname = byName;
    m_is_rtcloc = byManager;

    // "rtcname.<protocol>": iiop unless named; web protocols put the name after '#'.
    const std::string::size_type dot = scheme.find('.');
    const std::string protocol = dot == std::string::npos ? "" : scheme.substr(dot + 1);
    const bool web
        = protocol == "http" || protocol == "https" || protocol == "ws" || protocol == "wss";
    const std::string rest = uri.substr(schemeEnd + 3);
    const std::string::size_type nameAt = rest.find(web ? '#' : '/');
    const std::string hostPort = rest.substr(0, nameAt);
    if (nameAt != std::string::npos)
        m_rtcpath = rest.substr(nameAt + 1);
    if (hostPort == "*")
        m_address = hostPort;
    else if (web)
        m_address = protocol + "://" + hostPort;
    else
        m_address = "corbaloc:" + protocol + ":" + hostPort;
}

RTCURIObject::~RTCURIObject() = default;

std::string RTCURIObject::getRTCName() const
{
    return m_rtcpath;
}

std::string RTCURIObject::getAddress() const
{
    return m_address;
}

bool RTCURIObject::isRTCNameURI() const
{
    return m_is_rtcname;
}

bool RTCURIObject::isRTCLocURI() const
{
    return m_is_rtcloc;
}

} // namespace CORBA_RTCUtil
