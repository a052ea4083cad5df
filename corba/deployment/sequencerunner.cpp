// SPDX-License-Identifier: MIT
#include "sequencerunner.h"

#include "componentproxy.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "rtsprofile.h"
#include "steprecorder.h"

#include <QDeadlineTimer>
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

// Often enough that a SYNC wait ends within a few ms of the state change, rarely enough that a
// long wait costs next to nothing.
constexpr int pollIntervalMs = 5;

struct Target
{
    QString instance;
    QString ecId;
    const RtsCondition *condition = nullptr;
};

int sequenceNumber(const RtsCondition &condition)
{
    bool ok = false;
    const int number = condition.sequence.trimmed().toInt(&ok);
    return ok ? number : INT_MAX;
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

class SequenceRun
{
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
        const QList<Target> all = targets(kind);
        // Targets of the file's sequence go one after the other, in its order (they may wait for
        // each other) ...
        qsizetype ordered = 0;
        for (; ordered < all.size() && all.at(ordered).condition; ++ordered) {
            if (!m_steps.ok() || m_steps.checkCancelled())
                return;
            runTarget(all.at(ordered));
        }
        // ... the others have no order among them: several at once.
        Corba::forEachConcurrently(std::size_t(all.size() - ordered), [&](std::size_t i) {
            if (!m_steps.ok() || m_steps.checkCancelled())
                return;
            runTarget(all.at(ordered + qsizetype(i)));
        });
    }

private:
    bool contextsOnly() const
    {
        return m_action == SequenceAction::StartContext || m_action == SequenceAction::StopContext;
    }

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
            covered.insert(t.instanceName + QLatin1Char('\n') + t.id);
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
                if (!covered.contains(component.instanceName + QLatin1Char('\n') + id))
                    result.append({component.instanceName, id, nullptr});
            }
        }
        return result;
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
            QMutexLocker lock(&m_contextsMutex);
            const auto cached = m_contexts.constFind(key);
            if (cached != m_contexts.constEnd())
                contexts = *cached;
        }
        if (contexts.empty()) {
            contexts = proxy.executionContexts();
            QMutexLocker lock(&m_contextsMutex);
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

    // Polls `condition` until it holds, `timeoutMs` passes (0 = no limit) or the caller cancels.
    bool waitUntil(const std::function<bool()> &condition, int timeoutMs)
    {
        QDeadlineTimer deadline(timeoutMs > 0 ? qint64(timeoutMs) : -1);
        while (!condition()) {
            if (m_steps.checkCancelled() || deadline.hasExpired())
                return false;
            std::this_thread::sleep_for(std::chrono::milliseconds(pollIntervalMs));
        }
        return true;
    }

    bool waitBefore(const Target &target, bool isRequired)
    {
        const RtsCondition *condition = target.condition;
        if (!condition)
            return true;
        if (condition->waitTime) {
            const int ms = condition->waitTime->waitTime.value_or(QString()).toInt();
            if (ms <= 0)
                return true;
            const int step = m_steps.begin(QStringLiteral("wait"), target.instance, isRequired);
            waitUntil([] { return false; }, ms);
            if (m_steps.checkCancelled()) {
                m_steps.fail(step, QStringLiteral("cancelled"));
                return false;
            }
            m_steps.finish(step, StepStatus::Done, QStringLiteral("%1 ms").arg(ms));
            return true;
        }
        if (!condition->preceding
            || condition->preceding->sendingTiming.value_or(QString()).toUpper()
                != QLatin1String("SYNC"))
            return true;
        return waitForPreceding(target, *condition->preceding, isRequired);
    }

    bool waitForPreceding(const Target &target, const Profile::RtsPreceding &preceding,
                          bool isRequired)
    {
        const int timeout = preceding.timeout.value_or(QString()).toInt();
        for (const auto &other : preceding.precedingComponents) {
            const int step = m_steps.begin(QStringLiteral("wait"), target.instance, isRequired);
            const ComponentMapping *mapping = live(other.instanceName);
            if (!mapping) {
                m_steps.fail(step,
                             QStringLiteral("preceding %1 is not there").arg(other.instanceName));
                return false;
            }
            try {
                const ComponentProxy proxy(mapping->ior, mapping->path);
                const int index = ecIndex(proxy, other.id);
                if (!waitUntil([&] { return reached(proxy, index); }, timeout)) {
                    m_steps.fail(step,
                                 QStringLiteral("%1 did not %2 within %3 ms")
                                     .arg(other.instanceName, actionName(m_action))
                                     .arg(timeout));
                    // A SYNC timeout cancels the rest of the plan, required or not.
                    return false;
                }
                m_steps.finish(step, StepStatus::Done,
                               QStringLiteral("after %1").arg(other.instanceName));
            } catch (const Error &e) {
                m_steps.fail(step, e.message());
                return false;
            }
        }
        return true;
    }

    void runTarget(const Target &target)
    {
        const bool isRequired = required(target.instance);
        const QString subject = target.instance + QLatin1Char('.') + target.ecId;
        const ComponentMapping *mapping = live(target.instance);
        if (mapping && !mapping->activate) {
            m_steps.add(actionName(m_action), subject, StepStatus::Skipped,
                        QStringLiteral("not selected"), isRequired);
            return;
        }
        if (!waitBefore(target, isRequired)) {
            forceStop();
            return;
        }
        const int step = m_steps.begin(actionName(m_action), subject, isRequired);
        if (!mapping) {
            m_steps.fail(step, QStringLiteral("%1 is not there").arg(target.instance));
            return;
        }
        try {
            const ComponentProxy proxy(mapping->ior, mapping->path);
            const int index = ecIndex(proxy, target.ecId);
            if (reached(proxy, index)) {
                m_steps.finish(step, StepStatus::Skipped, QStringLiteral("already done"));
                return;
            }
            act(proxy, index);
            m_steps.finish(step, StepStatus::Done);
        } catch (const Error &e) {
            m_steps.fail(step, e.message());
        }
    }

    // A failed SYNC wait stops the whole plan even for optional components.
    void forceStop()
    {
        if (m_steps.ok())
            m_steps.fail(m_steps.begin(QStringLiteral("cancel"), QStringLiteral("plan")),
                         QStringLiteral("a preceding condition was not met"));
    }

    const Profile::RtsProfile &m_profile;
    const RestorePlan &m_plan;
    SequenceAction m_action;
    StepRecorder &m_steps;
    QMutex m_contextsMutex;
    QHash<QString, std::vector<Corba::ExecutionContextInfo>> m_contexts;
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
