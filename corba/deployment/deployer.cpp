// SPDX-License-Identifier: MIT
#include "deployer.h"

#include "componentpackager.h"
#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "matcher.h"
#include "nodefactsreader.h"
#include "packageinstallerproxy.h"
#include "remoteindex.h"
#include "repositoryfetcher.h"
#include "requirements.h"
#include "restorer.h"
#include "rtsprofile.h"
#include "sequencerunner.h"
#include "steprecorder.h"

#include <QDeadlineTimer>
#include <QHash>
#include <QMutex>
#include <QRegularExpression>
#include <QSet>
#include <QThread>

namespace Deploy {

using Corba::Error;

namespace {

/// How long an uninstall is retried while the manager still counts a component that was just
/// made to exit (exit finishes asynchronously).
constexpr int uninstallSettleMs = 5000;

Corba::PackageInstallerProxy installerOf(const QString &node)
{
    return Corba::PackageInstallerProxy(ComponentMapper::resolveManager(node), node);
}

/// Uninstalls @p package (@p version; every version when empty) from @p node; an empty string
/// when done, else why not. Retried for a short while when the manager still counts a component
/// that was just made to exit.
QString uninstallPackage(const QString &node, const QString &package, const QString &version)
{
    QDeadlineTimer settle(uninstallSettleMs);
    while (true) {
        try {
            installerOf(node).uninstall(package, version);
            return QString();
        } catch (const Error &e) {
            if (!e.message().contains(QLatin1String("running")) || settle.hasExpired())
                return e.message();
        }
        QThread::msleep(50);
    }
}

const Packages::IndexEntry *entryOf(const Packages::RemoteIndex &index,
                                    const Planner::RepositoryPackage &package)
{
    for (const Packages::IndexEntry &entry : index.entries) {
        if (entry.package() == package.package && entry.version() == package.version
            && entry.architecture() == package.architecture)
            return &entry;
    }
    return nullptr;
}

/// The system's component types each node that creates components must get, by node.
QHash<QString, QStringList> typesByNode(const RestorePlan &plan, const TargetOptions &target)
{
    QHash<QString, QStringList> types;
    for (const ComponentMapping &c : plan.components) {
        if (c.kind != MappingKind::Create)
            continue;
        QStringList &list = types[creatingNode(c, target)];
        if (!list.contains(c.typeName))
            list.append(c.typeName);
    }
    return types;
}

void addInstall(DeployPlan *plan, const Packages::RemoteIndex &index, const QString &node,
                const Planner::RepositoryPackage &package, const QString &type)
{
    for (PackageInstall &install : plan->installs) {
        if (install.node == node && install.package == package.package) {
            install.types.append(type);
            return;
        }
    }
    const Packages::IndexEntry *entry = entryOf(index, package);
    plan->installs.append({node, package.package, package.version,
                           entry ? index.packageUrl(*entry) : QString(), {type}});
}

/// Why @p type cannot be created on @p node: one whole sentence per case, for translators.
QString notLoadable(const QString &type, const QString &node, const QString &repository,
                    const Planner::NodeFacts &facts)
{
    if (repository.isEmpty())
        return DeployPlan::tr("%1 on %2: not loadable there and no repository given")
            .arg(type, node);
    return DeployPlan::tr("%1 on %2: not loadable there and no package of %3 fits it (%4)")
        .arg(type, node, repository,
             facts.architecture.value_or(DeployPlan::tr("architecture unknown")));
}

/// Picks the packages each node needs; a type a node can neither load nor install is a problem.
void planInstalls(const QHash<QString, QStringList> &types, const DeployOptions &options,
                  DeployPlan *plan)
{
    const QStringList nodes = plan->nodes();
    const QList<NodeFactsReading> facts = readNodeFacts(nodes);
    QString error;
    const std::optional<Packages::RemoteIndex> index = readRepositoryIndex(options, &error);
    if (!index) {
        plan->problems << error;
        return;
    }
    const Planner::Matcher matcher(plannerPackages(*index));
    for (const NodeFactsReading &reading : facts) {
        const QString &node = reading.facts.name;
        if (!reading.error.isEmpty()) {
            plan->problems << DeployPlan::tr("node %1: %2").arg(node, reading.error);
            continue;
        }
        for (const QString &type : types.value(node)) {
            const Planner::Matcher::TypeSource source = matcher.typeSource(type, reading.facts);
            if (source.package)
                addInstall(plan, *index, node, *source.package, type);
            else if (!source.loadable)
                plan->problems << notLoadable(type, node, options.repository, reading.facts);
        }
    }
}

/// What a deploy installed, to be uninstalled when it rolls back.
struct Installed
{
    int step;
    PackageInstall install;
};

// One run of deploySystem(): the steps, what was installed, and the phases in order.
class DeployRun
{
public:
    DeployRun(const Profile::RtsProfile &profile, const DeployPlan &plan,
              const DeployOptions &options, const DeployControl &control)
        : m_profile(profile)
        , m_plan(plan)
        , m_options(options)
        , m_control(control)
        , m_steps(control)
    { }

    DeployReport run()
    {
        if (!checkPlan() || !installAll()) {
            uninstallAll();
            return m_steps.report();
        }
        const DeployReport restored = restoreSystem(m_profile, m_plan.restore, target(), m_control);
        if (!restored.ok) {
            uninstallAll();
            return merged(restored);
        }
        if (!m_options.start)
            return merged(restored);
        const RestorePlan live = planRestore(m_profile, target());
        const DeployReport started = startSystem(m_profile, live, m_control);
        if (started.ok)
            return merged(restored, started);
        // The restore is complete, so its own undo is gone: stop, disconnect and remove what it made.
        DeployReport undone = merged(restored, started);
        append(&undone, stopSystem(m_profile, live));
        append(&undone, teardownSystem(live));
        exitCreated(restored, live, &undone);
        uninstallAll();
        DeployReport report = merged(undone);
        report.ok = false;
        report.error = started.error;
        return report;
    }

private:
    TargetOptions target() const
    {
        TargetOptions options = m_options.target;
        options.create = true;
        return options;
    }

    bool checkPlan()
    {
        for (const QString &problem : m_plan.problems)
            m_steps.fail(m_steps.begin(QStringLiteral("plan"),
                                       DeployPlan::tr("deploy", "what the plan check is about")),
                         problem);
        return m_steps.ok();
    }

    bool installAll()
    {
        const QStringList nodes = m_plan.nodes();
        Corba::forEachConcurrently(nodes.size(), [this, &nodes](std::size_t i) {
            installOnNode(nodes.at(int(i)));
        });
        m_steps.checkCancelled();
        return m_steps.ok();
    }

    void installOnNode(const QString &node)
    {
        for (const PackageInstall &install : m_plan.installs) {
            if (install.node != node)
                continue;
            if (!m_steps.ok() || m_steps.checkCancelled())
                return;
            const int step = m_steps.begin(QStringLiteral("install"), subject(install));
            try {
                Corba::PackageInstallerProxy installer = installerOf(node);
                installer.setInstallTimeout(m_options.installTimeoutMs);
                installer.installUrl(install.url);
                {
                    QMutexLocker lock(&m_mutex);
                    m_installed.append({step, install});
                }
                m_steps.finish(step, StepStatus::Done, install.types.join(QLatin1Char(' ')));
            } catch (const Error &e) {
                m_steps.fail(step, e.message());
            }
        }
    }

    void uninstallAll()
    {
        for (auto it = m_installed.crbegin(); it != m_installed.crend(); ++it) {
            const QString message = uninstallPackage(it->install.node, it->install.package, it->install.version);
            if (message.isEmpty())
                m_steps.finish(it->step, StepStatus::RolledBack);
            else
                m_steps.add(QStringLiteral("uninstall"), subject(it->install), StepStatus::Failed,
                            message, false);
        }
        m_installed.clear();
    }

    void exitCreated(const DeployReport &restored, const RestorePlan &live, DeployReport *report)
    {
        for (const DeployStep &step : restored.steps) {
            if (step.action != QLatin1String("create") || step.status != StepStatus::Done)
                continue;
            const ComponentMapping *c = live.component(step.subject);
            DeployStep exited;
            exited.action = QStringLiteral("exit");
            exited.subject = step.subject;
            exited.status = StepStatus::RolledBack;
            try {
                if (c && !c->ior.isEmpty())
                    Corba::ComponentProxy(c->ior, c->path).exit();
            } catch (const Error &e) {
                exited.status = StepStatus::Failed;
                exited.message = e.message();
                exited.required = false;
            }
            report->steps.append(exited);
        }
    }

    static QString subject(const PackageInstall &install)
    {
        return DeployPlan::tr("%1 %2 on %3", "package, version on node")
            .arg(install.package, install.version, install.node);
    }

    static void append(DeployReport *to, const DeployReport &from) { to->steps << from.steps; }

    DeployReport merged(const DeployReport &a, const DeployReport &b = {}) const
    {
        DeployReport report = m_steps.report();
        append(&report, a);
        append(&report, b);
        for (const DeployReport *part : {&a, &b}) {
            if (!part->ok && report.ok) {
                report.ok = false;
                report.error = part->error;
            }
            report.cancelled = report.cancelled || part->cancelled;
        }
        return report;
    }

private:
    const Profile::RtsProfile &m_profile;
    const DeployPlan &m_plan;
    const DeployOptions &m_options;
    DeployControl m_control;
    StepRecorder m_steps;
    QMutex m_mutex;
    QList<Installed> m_installed;
};

} // namespace

QString pinOf(const Profile::RtsComponent &component)
{
    return Profile::rtsPropertyValue(component.properties, Planner::Key::Pin).value_or(QString()).trimmed();
}

/// Components the system pins to a node are created by that node's manager directly; with
/// @p create, also those the mapper found no manager for.
void applyPins(const Profile::RtsProfile &profile, RestorePlan *plan, bool create)
{
    static const QRegularExpression managerAddress(QStringLiteral("&manager_address=[^&]*"));
    for (const Profile::RtsComponent &component : profile.components) {
        const QString pin = pinOf(component);
        if (pin.isEmpty())
            continue;
        for (ComponentMapping &mapping : plan->components) {
            if (mapping.instanceName != component.instanceName)
                continue;
            mapping.manager = pin;
            if (create && mapping.kind == MappingKind::Missing) {
                mapping.kind = MappingKind::Create;
                mapping.message = ComponentMapper::notFound(mapping.instanceName);
            }
            if (mapping.kind == MappingKind::Create) {
                mapping.createArgument.remove(managerAddress);
                mapping.path = pin + QLatin1Char('/') + mapping.instanceName + QStringLiteral(".rtc");
            }
        }
    }
}

QList<Planner::RepositoryPackage> plannerPackages(const Packages::RemoteIndex &index)
{
    QList<Planner::RepositoryPackage> packages;
    for (const Packages::IndexEntry &entry : index.entries) {
        packages.append({entry.package(), entry.version(), entry.architecture(),
                         entry.control.value(Packages::Field::SdkAbi).trimmed(),
                         Planner::splitFactList(entry.control.value(Packages::Field::RtcTypes))});
    }
    return packages;
}

std::optional<Packages::RemoteIndex> readRepositoryIndex(const DeployOptions &options, QString *error)
{
    if (options.repository.isEmpty())
        return Packages::RemoteIndex();
    const Packages::RepositoryFetcher fetcher(QString(), options.installTimeoutMs, options.caCertificates);
    std::optional<Packages::RemoteIndex> index = Packages::readRemoteIndex(options.repository, fetcher, error);
    if (!index)
        *error = DeployPlan::tr("repository %1: %2").arg(options.repository, *error);
    return index;
}

QString creatingNode(const ComponentMapping &mapping, const TargetOptions &target)
{
    if (!mapping.manager.isEmpty())
        return mapping.manager;
    if (!target.manager.isEmpty())
        return target.manager;
    // A live component found under a host's naming context: the manager registered beside it.
    const int slash = mapping.path.lastIndexOf(QLatin1Char('/'));
    return slash > 0 ? mapping.path.left(slash) + QStringLiteral("/manager.mgr") : QString();
}

QStringList DeployPlan::nodes() const
{
    QStringList list;
    for (const ComponentMapping &c : restore.components) {
        if (c.kind == MappingKind::Create && !list.contains(c.manager))
            list.append(c.manager);
    }
    return list;
}

QString DeployPlan::toText() const
{
    QString text;
    for (const PackageInstall &install : installs)
        text += tr("install %1 %2 on %3 (%4)")
                    .arg(install.package, install.version, install.node,
                         install.types.join(QLatin1Char(' ')))
            + QLatin1Char('\n');
    text += restore.toText();
    for (const QString &problem : problems)
        text += tr("problem %1").arg(problem) + QLatin1Char('\n');
    return text;
}

DeployPlan planDeploy(const Profile::RtsProfile &profile, const DeployOptions &options)
{
    TargetOptions target = options.target;
    target.create = true;
    DeployPlan plan;
    plan.restore = planRestore(profile, target);
    applyPins(profile, &plan.restore, true);
    for (ComponentMapping &c : plan.restore.components) {
        if (c.kind == MappingKind::Create && c.manager.isEmpty())
            c.manager = target.manager;
    }
    for (const ComponentMapping &c : plan.restore.missingRequired())
        plan.problems << QStringLiteral("%1: %2").arg(c.instanceName, c.message);
    planInstalls(typesByNode(plan.restore, target), options, &plan);
    return plan;
}

DeployReport deploySystem(const Profile::RtsProfile &profile, const DeployPlan &plan,
                          const DeployOptions &options, const DeployControl &control)
{
    return DeployRun(profile, plan, options, control).run();
}

DeployReport undeploySystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                            const TargetOptions &target, bool uninstall,
                            const DeployControl &control)
{
    RestorePlan pinned = plan;
    applyPins(profile, &pinned, false);
    DeployReport report = stopSystem(profile, pinned, control);
    report.steps << teardownSystem(pinned, control).steps;
    StepRecorder steps(control);
    QHash<QString, QSet<QString>> types;
    for (const ComponentMapping &c : pinned.components) {
        if (c.kind != MappingKind::Existing)
            continue;
        types[creatingNode(c, target)].insert(c.typeName);
        const int step = steps.begin(QStringLiteral("exit"), c.instanceName, false);
        try {
            Corba::ComponentProxy(c.ior, c.path).exit();
            steps.finish(step, StepStatus::Done);
        } catch (const Error &e) {
            steps.fail(step, e.message());
        }
    }
    for (auto node = types.cbegin(); uninstall && node != types.cend(); ++node) {
        QList<Corba::InstalledPackageInfo> installed;
        try {
            installed = installerOf(node.key()).installed();
        } catch (const Error &e) {
            steps.add(QStringLiteral("uninstall"), node.key(), StepStatus::Failed, e.message(), false);
            continue;
        }
        QSet<QString> done;
        for (const Corba::InstalledPackageInfo &package : installed) {
            const bool ours = std::any_of(package.componentTypes.cbegin(), package.componentTypes.cend(),
                                          [&](const QString &t) { return node->contains(t); });
            if (!ours || done.contains(package.name))
                continue;
            done.insert(package.name);
            const QString subject
                = DeployPlan::tr("%1 on %2", "package on node").arg(package.name, node.key());
            const QString message = uninstallPackage(node.key(), package.name, QString());
            steps.add(QStringLiteral("uninstall"), subject,
                      message.isEmpty() ? StepStatus::Done : StepStatus::Skipped, message, false);
        }
    }
    report.steps << steps.report().steps;
    return report;
}

} // namespace Deploy
