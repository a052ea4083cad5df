// SPDX-License-Identifier: MIT
#include "restorer.h"

#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "liveports.h"
#include "managerproxy.h"
#include "portconnection.h"
#include "rtsprofile.h"
#include "steprecorder.h"

#include <QCoreApplication>
#include <QHash>

#include <cmath>
#include <functional>
#include <map>
#include <optional>

namespace Deploy {

using Corba::ComponentProxy;
using Corba::Error;

namespace {

struct Undo
{
    int step;
    std::function<void()> action;
};

// One run of restoreSystem(): the live proxies, cached port lists and what to undo.
class RestoreRun
{
    // What each step did or why it failed, shown in the Restore dialog (English in rtctl).
    Q_DECLARE_TR_FUNCTIONS(Deploy::Restorer)

public:
    RestoreRun(const Profile::RtsProfile &profile, const RestorePlan &plan,
               const TargetOptions &options, const DeployControl &control)
        : m_profile(profile)
        , m_plan(plan)
        , m_options(options)
        , m_steps(control)
    { }

    DeployReport run()
    {
        if (checkMissing() && findComponents() && connectAll() && configureAll() && setRates())
            return m_steps.report();
        rollback();
        return m_steps.report();
    }

private:
    // Only called for instances known to be in m_live.
    const ComponentProxy &proxy(const QString &instance) const
    {
        return *m_live.constFind(instance);
    }

    bool proceed() { return m_steps.ok() && !m_steps.checkCancelled(); }

    bool checkMissing()
    {
        for (const ComponentMapping &c : m_plan.components) {
            if (c.kind != MappingKind::Missing)
                continue;
            if (c.required)
                m_steps.fail(m_steps.begin(QStringLiteral("find"), c.instanceName), c.message);
            else
                m_steps.add(QStringLiteral("find"), c.instanceName, StepStatus::Skipped, c.message,
                            false);
        }
        return proceed();
    }

    bool findComponents()
    {
        for (const ComponentMapping &c : m_plan.components) {
            if (!proceed())
                return false;
            if (c.kind == MappingKind::Existing)
                m_live.insert(c.instanceName, ComponentProxy(c.ior, c.path));
            else if (c.kind == MappingKind::Create)
                create(c);
        }
        return proceed();
    }

    void create(const ComponentMapping &c)
    {
        const int step = m_steps.begin(QStringLiteral("create"), c.instanceName, c.required);
        try {
            const QString address = c.manager.isEmpty() ? m_options.manager : c.manager;
            if (address.isEmpty())
                throw Error(Error::Kind::BadPath, tr("no manager given"));
            auto manager = m_managers.find(address);
            if (manager == m_managers.end())
                manager = m_managers.emplace(address, Corba::ManagerProxy(ComponentMapper::resolveManager(address), address))
                              .first;
            const QString ior = manager->second.createComponent(c.createArgument);
            const ComponentProxy proxy(ior, c.path);
            m_live.insert(c.instanceName, proxy);
            m_undo.append({step, [proxy] { proxy.exit(); }});
            m_steps.finish(
                step, StepStatus::Done,
                tr("%1 by %2", "created: create argument, manager").arg(c.createArgument, address));
        } catch (const Error &e) {
            m_steps.fail(step, e.message());
        }
    }

    std::vector<Corba::PortInfo> ports(const QString &instance)
    {
        auto cached = m_ports.constFind(instance);
        if (cached == m_ports.constEnd())
            cached = m_ports.insert(instance, proxy(instance).ports());
        return *cached;
    }

    bool connectAll()
    {
        for (const ConnectorPlan &c : m_plan.connectors) {
            if (!proceed())
                return false;
            if (!c.connect) {
                m_steps.add(QStringLiteral("connect"), c.connectorId, StepStatus::Skipped,
                            tr("not selected"), c.required);
                continue;
            }
            const int step = m_steps.begin(QStringLiteral("connect"), c.connectorId, c.required);
            try {
                connect(c, step);
            } catch (const Error &e) {
                m_steps.fail(step, e.message());
            }
        }
        return proceed();
    }

    void connect(const ConnectorPlan &c, int step)
    {
        if (!m_live.contains(c.sourceInstance) || !m_live.contains(c.targetInstance))
            throw Error(Error::Kind::NotFound,
                        tr("%1 or %2 is not there").arg(c.sourceInstance, c.targetInstance));
        const auto sourcePorts = ports(c.sourceInstance);
        const auto targetPorts = ports(c.targetInstance);
        const Corba::PortInfo *source = findPort(sourcePorts, c.sourcePort, c.sourceInstance);
        const Corba::PortInfo *target = findPort(targetPorts, c.targetPort, c.targetInstance);
        if (!source || !target)
            throw Error(Error::Kind::NotFound,
                        tr("no port %1").arg(source ? c.targetPort : c.sourcePort));
        const QString path = proxy(c.sourceInstance).path();
        bool replaced = false;
        if (const Corba::ConnectorInfo *existing = findConnector(*source, c.connectorId)) {
            const auto alreadyConnected
                = [&] { m_steps.finish(step, StepStatus::Skipped, tr("already connected")); };
            if (existing->portIors.contains(target->ior)) {
                alreadyConnected();
                return;
            }
            // The saved connector, left on this end when the process of the other end died (a
            // host or slave restarted): that port no longer answers. The port refuses a second
            // connector of the same id, so the broken one goes first; it cannot be restored on
            // rollback, having nothing to connect to.
            if (Corba::PortConnection::hasEndGone(*existing)) {
                Corba::PortConnection::disconnect(*source, c.connectorId, path);
                replaced = true;
            } else if (existing->ports.contains(target->name)) {
                // Both ends answer and one is named as the target: a reference written another
                // way (another tool made the connector) for the same port.
                alreadyConnected();
                return;
            }
        }
        Corba::ConnectionRequest request;
        request.id = c.connectorId;
        request.name = c.name;
        request.properties = adaptedProperties(c.properties, *source);
        const Corba::PortInfo sourcePort = *source;
        Corba::PortConnection::connect({*source, *target}, request, path);
        m_undo.append({step, [sourcePort, c, path] {
                           Corba::PortConnection::disconnect(sourcePort, c.connectorId, path);
                       }});
        m_steps.finish(
            step, StepStatus::Done,
            (replaced ? tr("%1 -> %2 (replaced a broken connector)") : QStringLiteral("%1 -> %2"))
                .arg(source->name, target->name));
    }

    // Files name data types either way (`IDL:RTC/TimedLong:1.0`, `RTC::TimedLong`); the port's
    // spelling is what its allowed list and its peer compare against.
    static Corba::Properties adaptedProperties(Corba::Properties properties,
                                               const Corba::PortInfo &source)
    {
        const QString key = QStringLiteral("dataport.data_type");
        const QString portType = Corba::propertyValue(source.properties, key);
        const QString saved = Corba::propertyValue(properties, key);
        if (!portType.isEmpty() && !saved.isEmpty() && !portType.contains(QLatin1Char(','))
            && sameDataType(saved, portType))
            Corba::setProperty(properties, key, portType);
        return properties;
    }

    bool configureAll()
    {
        for (const auto &component : m_profile.components) {
            if (!proceed())
                return false;
            if (!m_live.contains(component.instanceName))
                continue;
            const bool hasValues = !component.configurationSets.isEmpty();
            if (!hasValues && !component.activeConfigurationSet)
                continue;
            const int step = m_steps.begin(QStringLiteral("configure"), component.instanceName,
                                           component.isRequiredValue());
            try {
                configure(component, proxy(component.instanceName));
                m_steps.finish(step, StepStatus::Done,
                               component.activeConfigurationSet.value_or(QString()));
            } catch (const Error &e) {
                m_steps.fail(step, e.message());
            }
        }
        return proceed();
    }

    static void configure(const Profile::RtsComponent &component, const ComponentProxy &proxy)
    {
        const std::vector<Corba::ConfigurationSet> live = proxy.configurationSets();
        for (const auto &saved : component.configurationSets) {
            Corba::ConfigurationSet set;
            set.id = saved.id;
            for (const auto &data : saved.data)
                set.data.append({data.name, data.data.value_or(QString())});
            const auto existing = std::find_if(live.begin(), live.end(),
                                               [&](const auto &s) { return s.id == saved.id; });
            if (existing == live.end())
                proxy.addConfigurationSet(set);
            else if (!set.data.isEmpty() && differs(*existing, set))
                proxy.setConfigurationSetValues(set);
        }
        if (component.activeConfigurationSet && !component.activeConfigurationSet->isEmpty())
            proxy.activateConfigurationSet(*component.activeConfigurationSet);
    }

    static bool differs(const Corba::ConfigurationSet &live, const Corba::ConfigurationSet &saved)
    {
        for (const auto &value : saved.data) {
            if (!Corba::hasProperty(live.data, value.first)
                || Corba::propertyValue(live.data, value.first) != value.second)
                return true;
        }
        return false;
    }

    bool setRates()
    {
        for (const auto &component : m_profile.components) {
            if (!proceed())
                return false;
            if (m_live.contains(component.instanceName))
                setRates(component, proxy(component.instanceName));
        }
        return proceed();
    }

    void setRates(const Profile::RtsComponent &component, const ComponentProxy &proxy)
    {
        std::optional<std::vector<Corba::ExecutionContextInfo>> live;
        for (const auto &ec : component.executionContexts) {
            if (!ec.rateValue())
                continue;
            const QString subject = component.instanceName + QLatin1Char('.') + ec.id;
            try {
                if (!live)
                    live = proxy.executionContexts();
                const int index = ownedIndex(*live, ec.id);
                if (index < 0 || std::abs(live->at(size_t(index)).rate - *ec.rateValue()) < 1e-9)
                    continue;
                const int step
                    = m_steps.begin(QStringLiteral("rate"), subject, component.isRequiredValue());
                try {
                    proxy.setRate(*ec.rateValue(), index);
                    m_steps.finish(step, StepStatus::Done, *ec.rate);
                } catch (const Error &e) {
                    m_steps.fail(step, e.message());
                }
            } catch (const Error &e) {
                m_steps.fail(
                    m_steps.begin(QStringLiteral("rate"), subject, component.isRequiredValue()),
                    e.message());
            }
        }
    }

    // The saved EC id is the owner's handle; a non-numeric id means the only owned context.
    static int ownedIndex(const std::vector<Corba::ExecutionContextInfo> &ecs, const QString &id)
    {
        bool numeric = false;
        const int handle = id.toInt(&numeric);
        int owned = 0;
        for (size_t i = 0; i < ecs.size(); ++i) {
            if (!ecs[i].owned)
                continue;
            ++owned;
            if (numeric && ecs[i].handle == handle)
                return int(i);
        }
        return owned == 1 && !ecs.empty() && ecs.front().owned ? 0 : -1;
    }

    void rollback()
    {
        for (auto it = m_undo.crbegin(); it != m_undo.crend(); ++it) {
            try {
                it->action();
                m_steps.finish(it->step, StepStatus::RolledBack, tr("undone"));
            } catch (const Error &e) {
                m_steps.finish(it->step, StepStatus::RolledBack,
                               tr("undo failed: %1").arg(e.message()));
            }
        }
        m_undo.clear();
    }

    const Profile::RtsProfile &m_profile;
    const RestorePlan &m_plan;
    const TargetOptions &m_options;
    StepRecorder m_steps;
    std::map<QString, Corba::ManagerProxy> m_managers;
    QHash<QString, ComponentProxy> m_live;
    QHash<QString, std::vector<Corba::PortInfo>> m_ports;
    QList<Undo> m_undo;
};

} // namespace

DeployReport restoreSystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                           const TargetOptions &options, const DeployControl &control)
{
    return RestoreRun(profile, plan, options, control).run();
}

DeployReport teardownSystem(const RestorePlan &plan, const DeployControl &control)
{
    StepRecorder steps(control);
    // One job per source component: its ports are read once for all of its connectors.
    struct Disconnect
    {
        int step;
        const ConnectorPlan *connector;
    };
    struct Job
    {
        const ComponentMapping *source;
        std::vector<Disconnect> connectors;
    };
    std::vector<Job> jobs;
    QHash<QString, std::size_t> jobOf;
    for (const ConnectorPlan &c : plan.connectors) {
        const ComponentMapping *source = plan.component(c.sourceInstance);
        if (!source || source->kind != MappingKind::Existing) {
            steps.add(QStringLiteral("disconnect"), c.connectorId, StepStatus::Skipped,
                      RestoreRun::tr("%1 is not there").arg(c.sourceInstance), false);
            continue;
        }
        const auto known = jobOf.constFind(c.sourceInstance);
        const std::size_t index = known != jobOf.constEnd() ? *known : jobs.size();
        if (index == jobs.size()) {
            jobs.push_back({source, {}});
            jobOf.insert(c.sourceInstance, index);
        }
        jobs[index].connectors.push_back({steps.begin(QStringLiteral("disconnect"), c.connectorId, c.required), &c});
    }
    // Components are independent of each other: several are taken apart at once.
    Corba::forEachConcurrently(jobs.size(), [&steps, &jobs](std::size_t i) {
        const Job &job = jobs[i];
        // The ports the plan read are used first; they are read again as soon as they disagree
        // with the component (a connector made or removed since).
        std::vector<Corba::PortInfo> ports = job.source->plannedPorts;
        bool fresh = ports.empty();
        QString unreachable;
        const auto readPorts = [&] {
            fresh = true;
            try {
                ports = ComponentProxy(job.source->ior, job.source->path).profile().ports;
            } catch (const Error &e) {
                unreachable = e.message();
            }
        };
        if (fresh)
            readPorts();
        for (const Disconnect &d : job.connectors) {
            const ConnectorPlan &c = *d.connector;
            if (steps.checkCancelled()) {
                steps.finish(d.step, StepStatus::Skipped, DeployReport::cancelledError());
                continue;
            }
            const Corba::PortInfo *port = nullptr;
            const auto connected = [&] {
                port = unreachable.isEmpty() ? findPort(ports, c.sourcePort, c.sourceInstance) : nullptr;
                return port && findConnector(*port, c.connectorId);
            };
            if (!connected() && !fresh) {
                readPorts();
                connected();
            }
            if (!unreachable.isEmpty()) {
                steps.fail(d.step, unreachable);
                continue;
            }
            if (!port) {
                steps.fail(
                    d.step,
                    RestoreRun::tr("%1: no port named '%2'")
                        .arg(job.source->path, shortPortName(c.sourcePort, c.sourceInstance)));
                continue;
            }
            if (!findConnector(*port, c.connectorId)) {
                steps.finish(d.step, StepStatus::Skipped, RestoreRun::tr("not connected"));
                continue;
            }
            try {
                Corba::PortConnection::disconnect(*port, c.connectorId, job.source->path);
                steps.finish(d.step, StepStatus::Done);
            } catch (const Error &e) {
                // Refused by ports the plan read: disconnected since, unless a fresh look finds it.
                const bool stale = !fresh && e.kind() == Error::Kind::Refused;
                if (stale)
                    readPorts();
                if (stale && unreachable.isEmpty() && !connected())
                    steps.finish(d.step, StepStatus::Skipped, RestoreRun::tr("not connected"));
                else
                    steps.fail(d.step, e.message());
            }
        }
    });
    return steps.report();
}

} // namespace Deploy
