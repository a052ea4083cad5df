// SPDX-License-Identifier: MIT
#pragma once

#include "livesystem.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace LiveTest {

/**
 * Hosts simulated on this machine with Linux network namespaces (`ip netns`, root only). Each
 * host is a namespace with one IPv4 address of 10.231.N.0/24, joined to every other host and to
 * this process's namespace by a veth pair with point-to-point routes: traffic between two hosts
 * crosses their own link, and this process reaches every host directly, without a bridge, IP
 * forwarding or firewall rules. liveHost() starts processes inside a host, in a UTS namespace
 * of their own whose host name is the host's name.
 *
 * Namespaces left behind by earlier runs that were killed are removed first; everything made
 * here is removed again by remove() and the destructor.
 */
class SimulatedHosts
{
public:
    SimulatedHosts() = default;
    ~SimulatedHosts();
    SimulatedHosts(const SimulatedHosts &) = delete;
    SimulatedHosts &operator=(const SimulatedHosts &) = delete;

    /**
     * Makes one host per name (at most 9). False, with what stopped it in `why`, when this
     * machine cannot make them (not root, no iproute2, no veth); nothing is left behind then.
     */
    bool create(const QStringList &hostNames, QString *why);
    /// The address of `host` (empty when there is no such host).
    QString address(const QString &host) const;
    /// Servers of a LiveSystem on this host: its address, its namespaces and its host name.
    LiveHost liveHost(const QString &host) const;
    /// Removes the namespaces and links; safe to call more than once.
    void remove();

private:
    struct Host
    {
        QString name;
        QString netns;
        QString address;
        int netnsFd = -1;
    };

    bool run(const QStringList &arguments, QString *why) const;
    bool addHost(const QString &name, QString *why);
    bool linkToThisNamespace(const Host &host, int index, QString *why);
    bool linkHosts(const Host &a, int indexA, const Host &b, int indexB, QString *why);
    int freeSubnet() const;
    static void removeStale();

    QString m_tag;
    int m_subnet = 0;
    std::vector<Host> m_hosts;
    QStringList m_rootLinks;
};

} // namespace LiveTest
