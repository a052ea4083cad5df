// SPDX-License-Identifier: MIT
#pragma once

// rtctl run in one host context of a live system's name server (`/<ns>/<host>.host_cxt`), as the
// live tests drive the components of one manager or program, and what those components report.

#include "componentstatus.h"
#include "livesystem.h"
#include "rtctlrunner.h"

#include <QDebug>

namespace LiveTest {

class HostRtctl
{
public:
    /// rtctl in the context `<host>.host_cxt` of @p live's name server (read at each call).
    HostRtctl(const LiveSystem &live, QString host)
        : m_live(live)
        , m_host(std::move(host))
    {
    }

    /// The tree path of the host's manager (`…/<host>.host_cxt/manager.mgr`).
    QString managerPath() const
    {
        return QStringLiteral("/%1/%2.host_cxt/manager.mgr").arg(m_live.namingServer(), m_host);
    }

    RtctlResult run(const QStringList &arguments) const
    {
        return runRtctlAt(QStringLiteral("/%1/%2.host_cxt").arg(m_live.namingServer(), m_host), arguments);
    }

    /// Runs rtctl; false (with what it printed as a warning) when it does not succeed.
    bool succeeds(const QStringList &arguments) const
    {
        const RtctlResult r = run(arguments);
        if (r.code != 0)
            qWarning().noquote() << "rtctl" << arguments.join(' ') << "failed:" << r.out << r.err;
        return r.code == 0;
    }

    /// The state `rtctl ls -l` shows for @p component (Active, Inactive, Error); empty when not listed.
    QString state(const QString &component) const
    {
        for (const QString &line : run({QStringLiteral("ls"), QStringLiteral("-l")}).lines()) {
            const QStringList fields = line.simplified().split(QLatin1Char(' '));
            if (fields.size() > 1 && fields.last() == component)
                return fields.first();
        }
        return {};
    }

    /// The string status @p name that @p component publishes (see componentStatus()).
    QString status(CORBA::ORB_ptr orb, const QString &component, const char *name) const
    {
        return componentStatus(orb, QStringLiteral("corbaname::%1#%2.host_cxt/%3").arg(m_live.namingServer(), m_host, component),
                               name);
    }

private:
    const LiveSystem &m_live;
    QString m_host;
};

} // namespace LiveTest
