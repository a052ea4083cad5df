// SPDX-License-Identifier: MIT
/*!
 * @file Routing.h
 * @brief Which local address and network interface reach a destination.
 *
 * Used to publish the address a peer can reach this process at (e.g. the endpoint of an
 * interface on the route to the name server).
 */
#ifndef COIL_ROUTING_H
#define COIL_ROUTING_H

#include <string>

namespace coil {
/*!
 * The local IP address the system would send from to reach @p dest_addr (a host name or an
 * address); false when the destination cannot be resolved or is unreachable.
 */
bool dest_to_endpoint(std::string dest_addr, std::string &endpoint);
/*! The name of the network interface on the route to @p dest_addr ("lo", "eth0", …). */
bool find_dest_ifname(std::string dest_addr, std::string &dest_if);
/*! The IPv4 address of interface @p ifname (its IPv6 address when it has no IPv4 one). */
bool ifname_to_ipaddr(const std::string &ifname, std::string &ipaddr);
} // namespace coil

#endif // COIL_ROUTING_H
