// SPDX-License-Identifier: MIT
#include <coil/Routing.h>

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>

namespace coil {
namespace {
std::string addressText(const sockaddr *address)
{
    char text[INET6_ADDRSTRLEN] = {0};
    if (address->sa_family == AF_INET) {
        const sockaddr_in *v4 = reinterpret_cast<const sockaddr_in *>(address);
        inet_ntop(AF_INET, &v4->sin_addr, text, sizeof(text));
    } else if (address->sa_family == AF_INET6) {
        const sockaddr_in6 *v6 = reinterpret_cast<const sockaddr_in6 *>(address);
        inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof(text));
    }
    return text;
}

// The kernel's routing decision without sending anything: connecting a UDP socket only picks
// the route, and getsockname() then tells the source address of that route.
bool sourceAddressFor(const std::string &destination, sockaddr_storage &source)
{
    addrinfo hints;
    std::memset(&hints, 0, sizeof(hints));
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    addrinfo *found = nullptr;
    if (destination.empty() || getaddrinfo(destination.c_str(), "9", &hints, &found) != 0)
        return false;
    bool ok = false;
    for (addrinfo *ai = found; ai != nullptr && !ok; ai = ai->ai_next) {
        const int fd = socket(ai->ai_family, SOCK_DGRAM, 0);
        if (fd < 0)
            continue;
        socklen_t length = sizeof(source);
        ok = connect(fd, ai->ai_addr, ai->ai_addrlen) == 0
             && getsockname(fd, reinterpret_cast<sockaddr *>(&source), &length) == 0;
        close(fd);
    }
    freeaddrinfo(found);
    return ok;
}

bool sameAddress(const sockaddr *a, const sockaddr_storage &b)
{
    if (a->sa_family != b.ss_family)
        return false;
    if (a->sa_family == AF_INET)
        return reinterpret_cast<const sockaddr_in *>(a)->sin_addr.s_addr
               == reinterpret_cast<const sockaddr_in *>(&b)->sin_addr.s_addr;
    if (a->sa_family == AF_INET6)
        return std::memcmp(&reinterpret_cast<const sockaddr_in6 *>(a)->sin6_addr,
                           &reinterpret_cast<const sockaddr_in6 *>(&b)->sin6_addr, sizeof(in6_addr))
               == 0;
    return false;
}
} // namespace

bool dest_to_endpoint(std::string dest_addr, std::string &endpoint)
{
    sockaddr_storage source;
    if (!sourceAddressFor(dest_addr, source))
        return false;
    endpoint = addressText(reinterpret_cast<const sockaddr *>(&source));
    return !endpoint.empty();
}

bool find_dest_ifname(std::string dest_addr, std::string &dest_if)
{
    sockaddr_storage source;
    if (!sourceAddressFor(dest_addr, source))
        return false;
    ifaddrs *interfaces = nullptr;
    if (getifaddrs(&interfaces) != 0)
        return false;
    bool found = false;
    for (ifaddrs *it = interfaces; it != nullptr && !found; it = it->ifa_next) {
        if (it->ifa_addr != nullptr && sameAddress(it->ifa_addr, source)) {
            dest_if = it->ifa_name;
            found = true;
        }
    }
    freeifaddrs(interfaces);
    return found;
}

bool ifname_to_ipaddr(const std::string &ifname, std::string &ipaddr)
{
    ifaddrs *interfaces = nullptr;
    if (getifaddrs(&interfaces) != 0)
        return false;
    std::string v4;
    std::string v6;
    for (ifaddrs *it = interfaces; it != nullptr; it = it->ifa_next) {
        if (it->ifa_addr == nullptr || ifname != it->ifa_name)
            continue;
        if (it->ifa_addr->sa_family == AF_INET && v4.empty())
            v4 = addressText(it->ifa_addr);
        else if (it->ifa_addr->sa_family == AF_INET6 && v6.empty())
            v6 = addressText(it->ifa_addr);
    }
    freeifaddrs(interfaces);
    ipaddr = v4.empty() ? v6 : v4;
    return !ipaddr.empty();
}
} // namespace coil
