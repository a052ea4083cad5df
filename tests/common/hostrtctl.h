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

    /// The port @p port (`out`) of @p component (`Comp0.rtc`) in the host's context; nil when not found.
    RTC::PortService_ptr portOf(CORBA::ORB_ptr orb, const QString &component, const QString &port) const
    {
        const QString name = QStringLiteral("corbaname::%1#%2.host_cxt/%3").arg(m_live.namingServer(), m_host, component);
        CORBA::Object_var object = orb->string_to_object(name.toUtf8().constData());
        RTC::RTObject_var rtc = RTC::RTObject::_narrow(object);
        RTC::PortServiceList_var ports = rtc->get_ports();
        const QString wanted = component.section(QLatin1Char('.'), 0, 0) + QLatin1Char('.') + port;
        for (CORBA::ULong i = 0; i < ports->length(); ++i) {
            RTC::PortProfile_var profile = ports[i]->get_port_profile();
            if (wanted == QLatin1String(profile->name.in()))
                return RTC::PortService::_duplicate(ports[i]);
        }
        return RTC::PortService::_nil();
    }

    /**
     * Connects @p from to @p to (ports as `Comp0.rtc:out`) with @p properties through their
     * references, as a manager's preconnect does: rtctl con would check the data types first.
     */
    bool connectThroughOrb(CORBA::ORB_ptr orb, const QString &from, const QString &to,
                           const QList<std::pair<QString, QString>> &properties) const
    {
        try {
            RTC::ConnectorProfile profile;
            profile.name = "connector";
            profile.connector_id = "";
            profile.ports.length(2);
            profile.ports[0] = portOf(orb, from.section(QLatin1Char(':'), 0, 0), from.section(QLatin1Char(':'), 1));
            profile.ports[1] = portOf(orb, to.section(QLatin1Char(':'), 0, 0), to.section(QLatin1Char(':'), 1));
            if (CORBA::is_nil(profile.ports[0]) || CORBA::is_nil(profile.ports[1]))
                return false;
            profile.properties.length(CORBA::ULong(properties.size()));
            for (qsizetype i = 0; i < properties.size(); ++i) {
                profile.properties[CORBA::ULong(i)].name = properties.at(i).first.toUtf8().constData();
                profile.properties[CORBA::ULong(i)].value <<= properties.at(i).second.toUtf8().constData();
            }
            return profile.ports[0]->connect(profile) == RTC::RTC_OK;
        } catch (const CORBA::Exception &error) {
            qWarning() << "connect" << from << to << error._name();
            return false;
        }
    }

private:
    const LiveSystem &m_live;
    QString m_host;
};

} // namespace LiveTest
