// SPDX-License-Identifier: MIT
#include "connectionlimit.h"

#include "corbautil.h"

#include <omniORB4/omniInterceptors.h>
#include <omniORB4/omniORB.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <set>
#include <sstream>
#include <string>

namespace Runtime {

namespace {

struct State
{
    std::mutex mutex;
    int maximum = 0;
    std::vector<int> ports;
    /// The peers' ports of the TCP connections accepted and not known to be closed.
    std::set<int> accepted;
};

/// Never destroyed: the ORB's threads may accept a connection while the process exits, after its
/// static objects are gone (fuzz_giop found it).
State &state()
{
    static State *const s = new State;
    return *s;
}

/// The kernel's state code of an established TCP connection in /proc/net/tcp.
constexpr const char *Established = "01";

int peerPort(const std::string &address)
{
    const size_t colon = address.rfind(':');
    try {
        return colon == std::string::npos ? -1 : std::stoi(address.substr(colon + 1));
    } catch (const std::exception &) {
        return -1;
    }
}

CORBA::Boolean acceptConnection(omni::omniInterceptors::serverAcceptConnection_T::info_T &info)
{
    const std::string peer = info.peeraddress() ? info.peeraddress() : "";
    State &s = state();
    std::lock_guard lock(s.mutex);
    // TCP and TLS connections count alike (a TLS server listens on TCP ports too); the Unix socket's
    // peers are on this host.
    if (s.maximum <= 0 || (peer.rfind("giop:tcp:", 0) != 0 && peer.rfind("giop:ssl:", 0) != 0))
        return true;
    // Closed connections are dropped from the count first: what the kernel no longer lists as
    // established to one of our ports has gone.
    const std::set<int> open = ConnectionLimit::establishedPeerPorts(s.ports);
    for (auto it = s.accepted.begin(); it != s.accepted.end();)
        it = open.count(*it) ? std::next(it) : s.accepted.erase(it);
    if (int(s.accepted.size()) >= s.maximum) {
        info.reject = 1;
        info.why = "too many connections (corba.max_connections)";
        std::cerr << programName() << ": refused a connection from " << peer << ": " << s.accepted.size()
                  << " connections are open, as many as corba.max_connections allows" << std::endl;
        return true;
    }
    s.accepted.insert(peerPort(peer));
    return true;
}

} // namespace

void ConnectionLimit::install(int maximum, const std::vector<int> &ports)
{
    State &s = state();
    std::lock_guard lock(s.mutex);
    const bool installed = s.maximum > 0;
    s.maximum = maximum;
    s.ports = ports;
    if (maximum > 0 && !installed)
        omniORB::getInterceptors()->serverAcceptConnection.add(acceptConnection);
}

std::set<int> ConnectionLimit::establishedPeerPorts(const std::vector<int> &ports)
{
    std::set<int> peers;
    const auto port = [](const std::string &address) {
        const size_t colon = address.rfind(':');
        return colon == std::string::npos ? -1 : int(std::strtol(address.c_str() + colon + 1, nullptr, 16));
    };
    for (const char *table : {"/proc/net/tcp", "/proc/net/tcp6"}) {
        std::ifstream in(table);
        std::string line;
        std::getline(in, line); // the header
        while (std::getline(in, line)) {
            // "  sl  local_address rem_address   st …": addresses are ADDRESS:PORT in hex.
            std::istringstream fields(line);
            std::string slot;
            std::string local;
            std::string remote;
            std::string state;
            if ((fields >> slot >> local >> remote >> state) && state == Established
                && std::find(ports.begin(), ports.end(), port(local)) != ports.end())
                peers.insert(port(remote));
        }
    }
    return peers;
}

} // namespace Runtime
