// SPDX-License-Identifier: MIT
#include "statepoller.h"

#include "concurrent.h"
#include "corbacall.h"
#include "rtcconversion.h"

#include <QElapsedTimer>
#include <QHash>
#include <QMutex>

namespace Corba {

using namespace Internal;

namespace {

/// How long a component that is no longer asked about keeps its entry.
constexpr qint64 UnusedMs = 60000;

struct Entry
{
    RTC::RTObject_var rtc;
    RTC::ExecutionContext_var context;
    qint64 usedMs = 0;
};

} // namespace

struct StatePoller::Cache
{
    QMutex mutex;
    QHash<QString, std::shared_ptr<Entry>> entries;
    QElapsedTimer clock;
};

StatePoller::StatePoller()
    : m_cache(std::make_unique<Cache>())
{
    m_cache->clock.start();
}

StatePoller::~StatePoller() = default;

std::vector<LifeCycleState> StatePoller::poll(const QStringList &iors, const QStringList &paths)
{
    std::vector<LifeCycleState> states(std::size_t(iors.size()), LifeCycleState::Unknown);
    Cache &cache = *m_cache;
    {
        QMutexLocker lock(&cache.mutex);
        const qint64 now = cache.clock.elapsed();
        for (auto it = cache.entries.begin(); it != cache.entries.end();) {
            if (now - (*it)->usedMs > UnusedMs)
                it = cache.entries.erase(it);
            else
                ++it;
        }
    }
    forEachConcurrently(states.size(), [&](std::size_t i) {
        const QString &ior = iors.at(qsizetype(i));
        const QString &path = paths.at(qsizetype(i));
        std::shared_ptr<Entry> entry;
        {
            QMutexLocker lock(&cache.mutex);
            entry = cache.entries.value(ior);
        }
        try {
            if (!entry) {
                auto made = std::make_shared<Entry>();
                made->rtc = RTC::RTObject::_unchecked_narrow(CORBA::Object_var(toObject(ior, path)).in());
                // rtshell's context 0: the first owned one, else the first it takes part in.
                made->context = call(path, [&] {
                    RTC::ExecutionContextList_var owned = made->rtc->get_owned_contexts();
                    if (owned->length() > 0)
                        return RTC::ExecutionContext::_duplicate(owned[0]);
                    RTC::ExecutionContextList_var participating = made->rtc->get_participating_contexts();
                    if (participating->length() > 0)
                        return RTC::ExecutionContext::_duplicate(participating[0]);
                    throw Error(Error::Kind::NotFound,
                                QStringLiteral("%1: no execution context with index 0").arg(path));
                });
                entry = made;
            }
            states[i] = callServed(path, ior, [&] {
                return toLifeCycleState(entry->context->get_component_state(entry->rtc.in()));
            });
            QMutexLocker lock(&cache.mutex);
            entry->usedMs = cache.clock.elapsed();
            cache.entries.insert(ior, entry);
        } catch (const Error &) {
            // Unknown: one silent component must not hide the others; it is looked up anew.
            QMutexLocker lock(&cache.mutex);
            cache.entries.remove(ior);
        }
    });
    return states;
}

} // namespace Corba
