// SPDX-License-Identifier: MIT
#pragma once

#include <set>
#include <vector>

namespace Runtime {

/**
 * Refuses TCP connections to this process's endpoints beyond a maximum (`corba.max_connections`),
 * so that a peer opening connections without end meets a closed connection instead of a process
 * that runs out of file descriptors or threads. Connections through the Unix socket (peers on
 * this host) are not counted. Works through omniORB's accept interceptor: the connections it
 * accepted are kept by their peer's port, and those the kernel's table (/proc/net/tcp, tcp6) no
 * longer lists as established are dropped from the count when the next one comes.
 */
class ConnectionLimit
{
public:
    /// Installs the limit for the ORB of this process; call after ORB_init. 0: no limit.
    static void install(int maximum, const std::vector<int> &ports);
    /// The peers' ports of the established TCP connections to one of @p ports.
    static std::set<int> establishedPeerPorts(const std::vector<int> &ports);
};

} // namespace Runtime
