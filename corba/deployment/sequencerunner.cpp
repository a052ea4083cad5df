// SPDX-License-Identifier: MIT
#include "sequencerunner.h"

#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "rtsprofile.h"
#include "steprecorder.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QHash>
#include <QMutex>
#include <QSet>

#include <algorithm>
#include <climits>
#include <functional>
#include <thread>

namespace Deploy {

using Corba::ComponentProxy;
using Corba::Error;
using Profile::RtsCondition;
using Profile::RtsSequenceKind;

namespace {

// How often a wait looks again at its condition (rtshell polls at about 100 Hz): a SYNC wait ends
// within a few ms of the state change, a cancel within one interval, and a long wait costs next to
// nothing.
constexpr int pollIntervalMs = 10;

struct Target
{
    QString instance;
    QString ecId;
    const RtsCondition *condition = nullptr;
};

QString targetKey(const QString &instance, const QString &ecId)
{
    return instance + QLatin1Char('\n') + ecId;
}

int sequenceNumber(const RtsCondition &condition)
{
    bool ok = false;
    const int number = condition.sequence.trimmed().toInt(&ok);
    return ok ? number : INT_MAX;
}

int waitTimeMs(const RtsCondition &condition)
{
    return condition.waitTime ? condition.waitTime->waitTime.value_or(QString()).toInt() : 0;
}

bool isSync(const Profile::RtsPreceding &preceding)
{
    return preceding.sendingTiming.value_or(QString()).trimmed().toUpper() == QLatin1String("SYNC");
}

// rtshell's "delayed" actions: those that wait for time or for other components. The others
// (no target, or a target with neither condition) are immediate.
bool isDelayed(const Target &target)
{
    return target.condition
        && (waitTimeMs(*target.condition) > 0 || target.condition->preceding.has_value());
}

QString actionName(SequenceAction action)
{
    switch (action) {
    case SequenceAction::Activate:
        return QStringLiteral("activate");
    case SequenceAction::Deactivate:
        return QStringLiteral("deactivate");
    case SequenceAction::StartContext:
        return QStringLiteral("start");
    case SequenceAction::StopContext:
        break;
    }
    return QStringLiteral("stop");
}

/**
 * One run of a message sequence, the way rtshell's rtstart/rtstop execute their plan: every
 * delayed action waits in a thread of its own, all started with the plan, so their waits overlap
 * and count from the plan's start; meanwhile the immediate actions are sent. The first required
 * failure, a preceding condition that cannot be met, or the caller's cancel ends all waits.
 */
class SequenceRun
{
    // Why a start or stop step waited, was skipped or failed, shown by Start All / Stop All.
    Q_DECLARE_TR_FUNCTIONS(Deploy::SequenceRunner)

public:
    SequenceRun(const Profile::RtsProfile &profile, const RestorePlan &plan, SequenceAction action,
                StepRecorder &steps)
        : m_profile(profile)
        , m_plan(plan)
        , m_action(action)
        , m_steps(steps)
    { }

    void run(RtsSequenceKind kind)
    {
        m_clock.start();
        QList<Target> immediate;
        QList<Target> delayed;
        for (const Target &target : targets(kind)) {
            (isDelayed(target) ? delayed : immediate).append(target);
            m_planned.insert(targetKey(target.instance, target.ecId), target.instance);
        }
        // Task 0 sends the immediate actions; every other task is one delayed action, each on a
        // thread of its own (as many threads as tasks) so that no wait holds up another.
        const std::size_t tasks = std::size_t(delayed.size()) + 1;
        Corba::forEachConcurrently(
            tasks,
            [&](std::size_t i) {
                if (i == 0)
                    runImmediate(immediate);
                else
                    runDelayed(delayed.at(qsizetype(i) - 1));
            },
            tasks);
    }

private:
    enum class WaitResult { Met, TimedOut, Stopped };

    bool contextsOnly() const
    {
        return m_action == SequenceAction::StartContext || m_action == SequenceAction::StopContext;
    }

    // The sequence's targets by ascending `sequence`, then (activation and deactivation only)
    // every other context of the components, in file order.
    QList<Target> targets(RtsSequenceKind kind) const
    {
        QList<const RtsCondition *> conditions;
        if (const auto &sequence = m_profile.sequence(kind)) {
            for (const RtsCondition &condition : sequence->targets)
                conditions.append(&condition);
        }
        std::stable_sort(conditions.begin(), conditions.end(),
                         [](auto *a, auto *b) { return sequenceNumber(*a) < sequenceNumber(*b); });
        QList<Target> result;
        QSet<QString> covered;
        for (const RtsCondition *condition : conditions) {
            const auto &t = condition->targetComponent;
            result.append({t.instanceName, t.id, condition});
            covered.insert(targetKey(t.instanceName, t.id));
        }
        if (contextsOnly())
            return result;
        for (const auto &component : m_profile.components) {
            QStringList ids;
            for (const auto &ec : component.executionContexts)
                ids.append(ec.id);
            if (ids.isEmpty())
                ids.append(QStringLiteral("0"));
            for (const QString &id : ids) {
                if (!covered.contains(targetKey(component.instanceName, id)))
                    result.append({component.instanceName, id, nullptr});
            }
        }
        return result;
    }

    // The file's plain targets one after the other in their order, then the contexts the
    // sequence does not name, which have no order among them: several at once.
    void runImmediate(const QList<Target> &immediate)
    {
        qsizetype ordered = 0;
        for (; ordered < immediate.size() && immediate.at(ordered).condition; ++ordered) {
            if (stopped())
                return;
            runTarget(immediate.at(ordered));
        }
        Corba::forEachConcurrently(std::size_t(immediate.size() - ordered), [&](std::size_t i) {
            if (!stopped())
                runTarget(immediate.at(ordered + qsizetype(i)));
        });
    }

    void runDelayed(const Target &target)
    {
        const bool isRequired = required(target.instance);
        const ComponentMapping *mapping = live(target.instance);
        if (mapping && !mapping->activate) {
            runTarget(target);
            return;
        }
        if (waitBefore(target, isRequired) && !stopped())
            runTarget(target);
    }

    bool required(const QString &instance) const
    {
        const auto *component = m_profile.component(instance);
        return !component || component->isRequiredValue();
    }

    const ComponentMapping *live(const QString &instance) const
    {
        const ComponentMapping *mapping = m_plan.component(instance);
        return mapping && mapping->kind == MappingKind::Existing && !mapping->ior.isEmpty()
            ? mapping
            : nullptr;
    }

    // The saved EC id is the component's handle of the context; index 0 when none matches.
    int ecIndex(const ComponentProxy &proxy, const QString &ecId)
    {
        const QString key = proxy.ior();
        std::vector<Corba::ExecutionContextInfo> contexts;
        {
            QMutexLocker lock(&m_mutex);
            const auto cached = m_contexts.constFind(key);
            if (cached != m_contexts.constEnd())
                contexts = *cached;
        }
        if (contexts.empty()) {
            contexts = proxy.executionContexts();
            QMutexLocker lock(&m_mutex);
            m_contexts.insert(key, contexts);
        }
        bool numeric = false;
        const int handle = ecId.toInt(&numeric);
        for (size_t i = 0; numeric && i < contexts.size(); ++i) {
            if (contexts.at(i).handle == handle)
                return int(i);
        }
        return 0;
    }

    bool reached(const ComponentProxy &proxy, int index)
    {
        switch (m_action) {
        case SequenceAction::Activate:
            return proxy.state(index) == Corba::LifeCycleState::Active;
        case SequenceAction::Deactivate:
            return proxy.state(index) == Corba::LifeCycleState::Inactive;
        case SequenceAction::StartContext:
        case SequenceAction::StopContext:
            break;
        }
        const auto contexts = proxy.executionContexts();
        const bool running = size_t(index) < contexts.size() && contexts[size_t(index)].running;
        return running == (m_action == SequenceAction::StartContext);
    }

    void act(const ComponentProxy &proxy, int index) const
    {
        switch (m_action) {
        case SequenceAction::Activate:
            return proxy.activate(index);
        case SequenceAction::Deactivate:
            return proxy.deactivate(index);
        case SequenceAction::StartContext:
            return proxy.startContext(index);
        case SequenceAction::StopContext:
            return proxy.stopContext(index);
        }
    }

    // The plan ends early once a required step failed or the caller cancelled.
    bool stopped() { return !m_steps.ok() || m_steps.checkCancelled(); }

    // Polls `condition` until it holds, the plan's clock reaches `untilMs` (< 0 = no limit) or
    // the plan stops.
    WaitResult waitUntil(const std::function<bool()> &condition, qint64 untilMs)
    {
        for (;;) {
            if (stopped())
                return WaitResult::Stopped;
            if (condition())
                return WaitResult::Met;
            const qint64 now = m_clock.elapsed();
            if (untilMs >= 0 && now >= untilMs)
                return WaitResult::TimedOut;
            const qint64 pause
                = untilMs >= 0 ? std::min<qint64>(pollIntervalMs, untilMs - now) : pollIntervalMs;
            std::this_thread::sleep_for(std::chrono::milliseconds(pause));
        }
    }

    bool waitBefore(const Target &target, bool isRequired)
    {
        const RtsCondition &condition = *target.condition;
        const int step = m_steps.begin(QStringLiteral("wait"), target.instance, isRequired);
        if (const int ms = waitTimeMs(condition); ms > 0 && !condition.preceding) {
            if (waitUntil([&] { return m_clock.elapsed() >= ms; }, -1) != WaitResult::Met)
                return cancelled(step);
            m_steps.finish(step, StepStatus::Done, tr("%1 ms from the start").arg(ms));
            return true;
        }
        const Profile::RtsPreceding &preceding = *condition.preceding;
        return isSync(preceding) ? waitForStates(target, preceding, step)
                                 : waitForSent(target, preceding, step);
    }

    bool cancelled(int step)
    {
        m_steps.fail(step, DeployReport::cancelledError());
        return false;
    }

    static QString names(const QList<Profile::RtsTargetExecutionContext> &components)
    {
        QStringList result;
        for (const auto &component : components)
            result.append(component.instanceName);
        return result.join(QStringLiteral(", "));
    }

    // SYNC: until every preceding context is in the state this action leads to; the timeout
    // counts from the plan's start and ends the whole plan.
    bool waitForStates(const Target &target, const Profile::RtsPreceding &preceding, int step)
    {
        const int timeout = preceding.timeout.value_or(QString()).toInt();
        struct Watched
        {
            Profile::RtsTargetExecutionContext component;
            ComponentProxy proxy;
            int index;
        };
        std::vector<Watched> watched;
        try {
            for (const auto &other : preceding.precedingComponents) {
                const ComponentMapping *mapping = live(other.instanceName);
                if (!mapping)
                    return unmet(target, step,
                                 tr("preceding %1 is not there").arg(other.instanceName));
                ComponentProxy proxy(mapping->ior, mapping->path);
                const int index = ecIndex(proxy, other.id);
                watched.push_back({other, std::move(proxy), index});
            }
            QList<Profile::RtsTargetExecutionContext> pending;
            const auto allReached = [&] {
                pending.clear();
                for (const Watched &w : watched) {
                    if (!reached(w.proxy, w.index))
                        pending.append(w.component);
                }
                return pending.isEmpty();
            };
            switch (waitUntil(allReached, timeout > 0 ? timeout : -1)) {
            case WaitResult::Met:
                break;
            case WaitResult::Stopped:
                return cancelled(step);
            case WaitResult::TimedOut:
                return unmet(target, step, notReached(names(pending), timeout));
            }
        } catch (const Error &e) {
            return unmet(target, step, e.message());
        }
        m_steps.finish(step, StepStatus::Done,
                       tr("after %1").arg(names(preceding.precedingComponents)));
        return true;
    }

    // ASYNC, NO_SYNC: until the preceding components' actions of this plan have been sent (or
    // skipped, or failed without ending the plan).
    bool waitForSent(const Target &target, const Profile::RtsPreceding &preceding, int step)
    {
        QStringList keys;
        for (const auto &other : preceding.precedingComponents) {
            const QStringList matching = plannedKeys(other);
            if (matching.isEmpty())
                return unmet(target, step,
                             tr("preceding %1 is not in the plan").arg(other.instanceName));
            keys += matching;
        }
        const auto allSent = [&] {
            QMutexLocker lock(&m_mutex);
            return std::all_of(keys.cbegin(), keys.cend(),
                               [&](const QString &key) { return m_sent.contains(key); });
        };
        if (waitUntil(allSent, -1) != WaitResult::Met)
            return cancelled(step);
        m_steps.finish(step, StepStatus::Done,
                       tr("after %1 was sent").arg(names(preceding.precedingComponents)));
        return true;
    }

    // The actions of this plan on `other`'s context, or on any context of that component when
    // the file names a context the plan does not have.
    QStringList plannedKeys(const Profile::RtsTargetExecutionContext &other) const
    {
        const QString exact = targetKey(other.instanceName, other.id);
        if (m_planned.contains(exact))
            return {exact};
        QStringList keys;
        for (auto it = m_planned.cbegin(); it != m_planned.cend(); ++it) {
            if (it.value() == other.instanceName)
                keys.append(it.key());
        }
        return keys;
    }

    // One whole sentence per action, for translators.
    QString notReached(const QString &pending, int timeout) const
    {
        switch (m_action) {
        case SequenceAction::Activate:
            return tr("%1 did not activate within %2 ms of the start").arg(pending).arg(timeout);
        case SequenceAction::Deactivate:
            return tr("%1 did not deactivate within %2 ms of the start").arg(pending).arg(timeout);
        case SequenceAction::StartContext:
            return tr("%1 did not start within %2 ms of the start").arg(pending).arg(timeout);
        case SequenceAction::StopContext:
            break;
        }
        return tr("%1 did not stop within %2 ms of the start").arg(pending).arg(timeout);
    }

    // A preceding condition that cannot be met ends the whole plan, even for optional components.
    bool unmet(const Target &target, int step, const QString &reason)
    {
        m_steps.fail(step, reason);
        if (m_steps.ok())
            m_steps.fail(m_steps.begin(QStringLiteral("cancel"),
                                       tr("plan", "the start or stop plan, cancelled")),
                         tr("%1: %2", "instance: reason").arg(target.instance, reason));
        return false;
    }

    void runTarget(const Target &target)
    {
        sendTarget(target);
        QMutexLocker lock(&m_mutex);
        m_sent.insert(targetKey(target.instance, target.ecId));
    }

    void sendTarget(const Target &target)
    {
        const bool isRequired = required(target.instance);
        const QString subject = target.instance + QLatin1Char('.') + target.ecId;
        const ComponentMapping *mapping = live(target.instance);
        if (mapping && !mapping->activate) {
            m_steps.add(actionName(m_action), subject, StepStatus::Skipped, tr("not selected"),
                        isRequired);
            return;
        }
        const int step = m_steps.begin(actionName(m_action), subject, isRequired);
        if (!mapping) {
            m_steps.fail(step, tr("%1 is not there").arg(target.instance));
            return;
        }
        try {
            const ComponentProxy proxy(mapping->ior, mapping->path);
            const int index = ecIndex(proxy, target.ecId);
            if (reached(proxy, index)) {
                m_steps.finish(step, StepStatus::Skipped, tr("already done"));
                return;
            }
            act(proxy, index);
            m_steps.finish(step, StepStatus::Done);
        } catch (const Error &e) {
            m_steps.fail(step, e.message());
        }
    }

    const Profile::RtsProfile &m_profile;
    const RestorePlan &m_plan;
    SequenceAction m_action;
    StepRecorder &m_steps;
    QElapsedTimer m_clock; ///< the plan's start: WaitTime and SYNC timeouts count from here
    QHash<QString, QString> m_planned; ///< targetKey → instance, every action of the plan
    QMutex m_mutex; ///< guards m_contexts and m_sent
    QHash<QString, std::vector<Corba::ExecutionContextInfo>> m_contexts;
    QSet<QString> m_sent; ///< targetKeys of the actions sent, skipped or failed
};

} // namespace

DeployReport runSequence(const Profile::RtsProfile &profile, const RestorePlan &plan,
                         RtsSequenceKind kind, SequenceAction action, const DeployControl &control)
{
    StepRecorder steps(control);
    SequenceRun(profile, plan, action, steps).run(kind);
    return steps.report();
}

DeployReport startSystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                         const DeployControl &control)
{
    StepRecorder steps(control);
    if (profile.startUp)
        SequenceRun(profile, plan, SequenceAction::StartContext, steps)
            .run(RtsSequenceKind::StartUp);
    if (steps.ok())
        SequenceRun(profile, plan, SequenceAction::Activate, steps)
            .run(RtsSequenceKind::Activation);
    return steps.report();
}

DeployReport stopSystem(const Profile::RtsProfile &profile, const RestorePlan &plan,
                        const DeployControl &control)
{
    StepRecorder steps(control);
    SequenceRun(profile, plan, SequenceAction::Deactivate, steps)
        .run(RtsSequenceKind::Deactivation);
    if (steps.ok() && profile.shutDown)
        SequenceRun(profile, plan, SequenceAction::StopContext, steps)
            .run(RtsSequenceKind::ShutDown);
    return steps.report();
}

} // namespace Deploy
