// SPDX-License-Identifier: MIT
#include "simulatedhosts.h"

#include <QDir>
#include <QFile>
#include <QProcess>

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

namespace LiveTest {

namespace {

// Namespaces and links are named after the test process: rtmh<pid>.
const QString namePrefix = QStringLiteral("rtmh");
// This process's end of every link.
constexpr int thisNamespaceHost = 254;

struct IpResult
{
    bool ok = false;
    QString output;
    QString error;
};

IpResult ip(const QStringList &arguments)
{
    QProcess process;
    process.start(QStringLiteral("ip"), arguments);
    IpResult result;
    if (!process.waitForStarted(10000)) {
        result.error = QStringLiteral("iproute2 is not installed (%1)").arg(process.errorString());
        return result;
    }
    if (!process.waitForFinished(10000)) {
        process.kill();
        process.waitForFinished();
        result.error = QStringLiteral("ip %1 did not finish").arg(arguments.join(QLatin1Char(' ')));
        return result;
    }
    result.ok = process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
    result.output = QString::fromLocal8Bit(process.readAllStandardOutput());
    result.error = QStringLiteral("ip %1: %2")
                       .arg(arguments.join(QLatin1Char(' ')),
                            QString::fromLocal8Bit(process.readAllStandardError()).trimmed());
    return result;
}

} // namespace

SimulatedHosts::~SimulatedHosts()
{
    remove();
}

bool SimulatedHosts::run(const QStringList &arguments, QString *why) const
{
    const IpResult result = ip(arguments);
    if (!result.ok)
        *why = result.error;
    return result.ok;
}

bool SimulatedHosts::create(const QStringList &hostNames, QString *why)
{
    remove();
    if (::geteuid() != 0) {
        *why = QStringLiteral("network namespaces need root");
        return false;
    }
    if (hostNames.size() > 9) {
        *why = QStringLiteral("at most 9 hosts");
        return false;
    }
    removeStale();
    m_tag = namePrefix + QString::number(::getpid());
    m_subnet = freeSubnet();
    if (m_subnet == 0) {
        *why = QStringLiteral("no free subnet in 10.231.0.0/16");
        return false;
    }
    bool made = true;
    for (int i = 0; made && i < hostNames.size(); ++i)
        made = addHost(hostNames.at(i), why) && linkToThisNamespace(m_hosts.back(), i, why);
    for (int i = 0; made && i < int(m_hosts.size()); ++i) {
        for (int j = i + 1; made && j < int(m_hosts.size()); ++j)
            made = linkHosts(m_hosts.at(size_t(i)), i, m_hosts.at(size_t(j)), j, why);
    }
    if (!made)
        remove();
    return made;
}

bool SimulatedHosts::addHost(const QString &name, QString *why)
{
    Host host;
    host.name = name;
    host.netns = m_tag + QLatin1Char('-') + name;
    host.address = QStringLiteral("10.231.%1.%2").arg(m_subnet).arg(m_hosts.size() + 1);
    if (!run({"netns", "add", host.netns}, why))
        return false;
    // Processes enter the namespace through this file (see liveHost()).
    host.netnsFd = ::open(QFile::encodeName(QStringLiteral("/run/netns/") + host.netns).constData(),
                          O_RDONLY | O_CLOEXEC);
    m_hosts.push_back(host);
    if (host.netnsFd < 0) {
        *why = QStringLiteral("cannot open the namespace %1").arg(host.netns);
        return false;
    }
    return run({"-n", host.netns, "link", "set", "lo", "up"}, why);
}

bool SimulatedHosts::linkToThisNamespace(const Host &host, int index, QString *why)
{
    const QString outer = m_tag + QStringLiteral("r%1").arg(index);
    const QString inner = m_tag + QStringLiteral("h%1").arg(index);
    const QString local = QStringLiteral("10.231.%1.%2").arg(m_subnet).arg(thisNamespaceHost);
    if (!run({"link", "add", outer, "type", "veth", "peer", "name", inner, "netns", host.netns},
             why))
        return false;
    m_rootLinks.append(outer);
    return run({"-n", host.netns, "addr", "add", host.address, "peer", local, "dev", inner}, why)
        && run({"addr", "add", local, "peer", host.address, "dev", outer}, why)
        && run({"-n", host.netns, "link", "set", inner, "up"}, why)
        && run({"link", "set", outer, "up"}, why);
}

bool SimulatedHosts::linkHosts(const Host &a, int indexA, const Host &b, int indexB, QString *why)
{
    const QString endA = m_tag + QStringLiteral("x%1%2").arg(indexA).arg(indexB);
    const QString endB = m_tag + QStringLiteral("x%1%2").arg(indexB).arg(indexA);
    return run({"-n", a.netns, "link", "add", endA, "type", "veth", "peer", "name", endB, "netns",
                b.netns},
               why)
        && run({"-n", a.netns, "addr", "add", a.address, "peer", b.address, "dev", endA}, why)
        && run({"-n", b.netns, "addr", "add", b.address, "peer", a.address, "dev", endB}, why)
        && run({"-n", a.netns, "link", "set", endA, "up"}, why)
        && run({"-n", b.netns, "link", "set", endB, "up"}, why);
}

// Concurrent runs (two build trees) start their search at different subnets and skip those in use.
int SimulatedHosts::freeSubnet() const
{
    const IpResult routes = ip({"-4", "route", "show", "table", "all"});
    if (!routes.ok)
        return 0;
    const int start = ::getpid() % 250;
    for (int i = 0; i < 250; ++i) {
        const int subnet = (start + i) % 250 + 1;
        if (!routes.output.contains(QStringLiteral("10.231.%1.").arg(subnet)))
            return subnet;
    }
    return 0;
}

// A run killed by its time limit never reaches remove(); its namespaces keep the pid it had.
void SimulatedHosts::removeStale()
{
    const QStringList names = QDir(QStringLiteral("/run/netns"))
                                  .entryList({namePrefix + QLatin1Char('*')}, QDir::Files);
    for (const QString &name : names) {
        const QString pid = name.mid(namePrefix.size()).section(QLatin1Char('-'), 0, 0);
        if (!pid.isEmpty() && !QFile::exists(QStringLiteral("/proc/") + pid))
            ip({"netns", "delete", name});
    }
}

QString SimulatedHosts::address(const QString &host) const
{
    for (const Host &h : m_hosts) {
        if (h.name == host)
            return h.address;
    }
    return QString();
}

LiveHost SimulatedHosts::liveHost(const QString &host) const
{
    for (const Host &h : m_hosts) {
        if (h.name != host)
            continue;
        const int fd = h.netnsFd;
        const QByteArray hostName = host.toLatin1();
        // Namespaces made by `ip netns` share the host name (and the file system), so processes
        // on different simulated hosts would take each other for local peers (omniORB prefers
        // Unix sockets to a peer of the same host name): each process gets its host's name.
        return {h.address, [fd, hostName] {
                    if (::setns(fd, CLONE_NEWNET) != 0 || ::unshare(CLONE_NEWUTS) != 0
                        || ::sethostname(hostName.constData(), size_t(hostName.size())) != 0)
                        ::_exit(127);
                }};
    }
    return {};
}

void SimulatedHosts::remove()
{
    // Deleting a namespace removes its links only later (asynchronously): delete ours at once.
    for (const QString &link : std::as_const(m_rootLinks))
        ip({"link", "delete", link});
    m_rootLinks.clear();
    for (const Host &host : m_hosts) {
        if (host.netnsFd >= 0)
            ::close(host.netnsFd);
        ip({"netns", "delete", host.netns});
    }
    m_hosts.clear();
}

} // namespace LiveTest
