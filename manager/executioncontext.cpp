// SPDX-License-Identifier: MIT
#include "executioncontext.h"
#include "properties.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace Runtime {

namespace {

// A participant that throws (process gone, object deleted) counts as failing the callback.
template <typename Call>
RTC::ReturnCode_t guarded(Call call)
{
    try {
        return call();
    } catch (const CORBA::Exception &) {
        return RTC::RTC_ERROR;
    }
}

} // namespace

ExecutionContext::ExecutionContext(const std::string &typeName, RTC::ExecutionKind kind, double rate,
                                   double transitionTimeoutSeconds)
    : m_rate(rate > 0 && std::isfinite(rate) ? rate : 1000.0)
    , m_transitionTimeout(transitionTimeoutSeconds)
    , m_typeName(typeName)
    , m_kind(kind)
{
}

ExecutionContext::~ExecutionContext()
{
    halt(true);
}

void ExecutionContext::addOwner(RTC::LightweightRTObject_ptr owner, RTC::ExecutionContextHandle_t handle)
{
    auto p = std::make_shared<Participant>();
    p->ref = RTC::LightweightRTObject::_duplicate(owner);
    p->dataflow = RTC::DataFlowComponentAction::_narrow(owner);
    p->handle = handle;
    p->owner = true;
    std::lock_guard lock(m_mutex);
    m_ownerRef = RTC::RTObject::_narrow(owner);
    m_participants.push_back(p);
}

void ExecutionContext::halt(bool quiet)
{
    std::thread thread;
    {
        std::lock_guard lock(m_mutex);
        if (!m_running)
            return;
        m_running = false;
        thread = std::move(m_thread);
    }
    m_wake.notify_all();
    m_transitioned.notify_all();
    if (thread.joinable()) {
        // stop() called from on_execute must not join its own thread.
        if (thread.get_id() == std::this_thread::get_id())
            thread.detach();
        else
            thread.join();
    }
    if (quiet)
        return;
    for (const ParticipantPtr &p : snapshot())
        guarded([&] { return p->ref->on_shutdown(p->handle); });
}

void ExecutionContext::startThread()
{
    if (!m_thread.joinable())
        m_thread = std::thread([this] { run(); });
}

void ExecutionContext::setExecutionKind(RTC::ExecutionKind kind)
{
    std::lock_guard lock(m_mutex);
    m_kind = kind;
}

unsigned long ExecutionContext::cycles()
{
    std::lock_guard lock(m_mutex);
    return m_cycles;
}

void ExecutionContext::runCycle()
{
    std::lock_guard cycle(m_cycleMutex);
    for (const ParticipantPtr &p : snapshot())
        process(p);
    std::lock_guard lock(m_mutex);
    ++m_cycles;
}

CORBA::Boolean ExecutionContext::is_running()
{
    std::lock_guard lock(m_mutex);
    return m_running;
}

RTC::ReturnCode_t ExecutionContext::start()
{
    {
        std::lock_guard lock(m_mutex);
        if (m_running)
            return RTC::PRECONDITION_NOT_MET;
    }
    for (const ParticipantPtr &p : snapshot())
        guarded([&] { return p->ref->on_startup(p->handle); });
    std::lock_guard lock(m_mutex);
    m_running = true;
    started();
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContext::stop()
{
    if (!is_running())
        return RTC::PRECONDITION_NOT_MET;
    halt(false);
    return RTC::RTC_OK;
}

CORBA::Double ExecutionContext::get_rate()
{
    std::lock_guard lock(m_mutex);
    return m_rate;
}

RTC::ReturnCode_t ExecutionContext::set_rate(CORBA::Double rate)
{
    if (!(rate > 0.0) || !std::isfinite(rate))
        return RTC::BAD_PARAMETER;
    {
        std::lock_guard lock(m_mutex);
        m_rate = rate;
    }
    m_wake.notify_all();
    for (const ParticipantPtr &p : snapshot()) {
        if (!CORBA::is_nil(p->dataflow))
            guarded([&] { return p->dataflow->on_rate_changed(p->handle); });
    }
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContext::add_component(RTC::LightweightRTObject_ptr comp)
{
    if (CORBA::is_nil(comp))
        return RTC::BAD_PARAMETER;
    if (find(comp))
        return RTC::PRECONDITION_NOT_MET;
    auto p = std::make_shared<Participant>();
    try {
        p->ref = RTC::LightweightRTObject::_duplicate(comp);
        p->dataflow = RTC::DataFlowComponentAction::_narrow(comp);
        RTC::ExecutionContextService_var self = _this();
        p->handle = comp->attach_context(self);
    } catch (const CORBA::Exception &) {
        return RTC::BAD_PARAMETER;
    }
    std::lock_guard lock(m_mutex);
    m_participants.push_back(p);
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContext::remove_component(RTC::LightweightRTObject_ptr comp)
{
    ParticipantPtr p = find(comp);
    if (!p || p->owner)
        return RTC::BAD_PARAMETER;
    {
        std::lock_guard lock(m_mutex);
        if (p->state == RTC::ACTIVE_STATE)
            return RTC::PRECONDITION_NOT_MET;
        m_participants.erase(std::remove(m_participants.begin(), m_participants.end(), p), m_participants.end());
    }
    guarded([&] { return p->ref->detach_context(p->handle); });
    return RTC::RTC_OK;
}

RTC::ReturnCode_t ExecutionContext::activate_component(RTC::LightweightRTObject_ptr comp)
{
    ParticipantPtr p = find(comp);
    return p ? requestTransition(p, RTC::INACTIVE_STATE, Request::Activate) : RTC::BAD_PARAMETER;
}

RTC::ReturnCode_t ExecutionContext::deactivate_component(RTC::LightweightRTObject_ptr comp)
{
    ParticipantPtr p = find(comp);
    return p ? requestTransition(p, RTC::ACTIVE_STATE, Request::Deactivate) : RTC::BAD_PARAMETER;
}

RTC::ReturnCode_t ExecutionContext::reset_component(RTC::LightweightRTObject_ptr comp)
{
    ParticipantPtr p = find(comp);
    return p ? requestTransition(p, RTC::ERROR_STATE, Request::Reset) : RTC::BAD_PARAMETER;
}

RTC::LifeCycleState ExecutionContext::get_component_state(RTC::LightweightRTObject_ptr comp)
{
    ParticipantPtr p = find(comp);
    std::lock_guard lock(m_mutex);
    return p ? p->state : RTC::CREATED_STATE;
}

RTC::ExecutionKind ExecutionContext::get_kind()
{
    std::lock_guard lock(m_mutex);
    return m_kind;
}

RTC::ExecutionContextProfile *ExecutionContext::get_profile()
{
    auto *profile = new RTC::ExecutionContextProfile;
    std::lock_guard lock(m_mutex);
    profile->kind = m_kind;
    profile->rate = m_rate;
    profile->owner = RTC::RTObject::_duplicate(m_ownerRef);
    profile->participants.length(0);
    for (const ParticipantPtr &p : m_participants) {
        RTC::RTObject_var rtc = RTC::RTObject::_narrow(p->ref);
        const CORBA::ULong n = profile->participants.length();
        profile->participants.length(n + 1);
        profile->participants[n] = rtc._retn();
    }
    profile->properties.length(1);
    profile->properties[0].name = "type";
    profile->properties[0].value <<= m_typeName.c_str();
    return profile;
}

ExecutionContext::ParticipantPtr ExecutionContext::find(RTC::LightweightRTObject_ptr comp)
{
    if (CORBA::is_nil(comp))
        return nullptr;
    for (const ParticipantPtr &p : snapshot()) {
        try {
            if (p->ref->_is_equivalent(comp))
                return p;
        } catch (const CORBA::Exception &) {
        }
    }
    return nullptr;
}

std::vector<ExecutionContext::ParticipantPtr> ExecutionContext::snapshot()
{
    std::lock_guard lock(m_mutex);
    return m_participants;
}

RTC::ReturnCode_t ExecutionContext::requestTransition(const ParticipantPtr &p, RTC::LifeCycleState from,
                                                      Request request)
{
    return transitionNow(p, from, request);
}

RTC::ReturnCode_t ExecutionContext::transitionNow(const ParticipantPtr &p, RTC::LifeCycleState from, Request request)
{
    // Between cycles: a tick arriving meanwhile sees the state before or after, never half of it.
    std::lock_guard cycle(m_cycleMutex);
    {
        std::lock_guard lock(m_mutex);
        if (p->state != from || p->request != Request::None)
            return RTC::PRECONDITION_NOT_MET;
    }
    runTransition(p, request);
    return RTC::RTC_OK;
}

void ExecutionContext::setState(const ParticipantPtr &p, RTC::LifeCycleState state)
{
    std::lock_guard lock(m_mutex);
    p->state = state;
    p->request = Request::None;
    m_transitioned.notify_all();
}

void ExecutionContext::runTransition(const ParticipantPtr &p, Request request)
{
    switch (request) {
    case Request::Activate:
        if (guarded([&] { return p->ref->on_activated(p->handle); }) == RTC::RTC_OK) {
            setState(p, RTC::ACTIVE_STATE);
        } else {
            guarded([&] { return p->ref->on_aborting(p->handle); });
            setState(p, RTC::ERROR_STATE);
        }
        break;
    case Request::Deactivate:
        guarded([&] { return p->ref->on_deactivated(p->handle); });
        setState(p, RTC::INACTIVE_STATE);
        break;
    case Request::Reset:
        setState(p, guarded([&] { return p->ref->on_reset(p->handle); }) == RTC::RTC_OK ? RTC::INACTIVE_STATE
                                                                                         : RTC::ERROR_STATE);
        break;
    case Request::None:
        break;
    }
}

void ExecutionContext::execute(const ParticipantPtr &p)
{
    if (CORBA::is_nil(p->dataflow))
        return;
    RTC::ReturnCode_t result = guarded([&] { return p->dataflow->on_execute(p->handle); });
    if (result == RTC::RTC_OK)
        result = guarded([&] { return p->dataflow->on_state_update(p->handle); });
    if (result != RTC::RTC_OK) {
        guarded([&] { return p->ref->on_aborting(p->handle); });
        setState(p, RTC::ERROR_STATE);
    }
}

void ExecutionContext::process(const ParticipantPtr &p)
{
    Request request;
    RTC::LifeCycleState state;
    {
        std::lock_guard lock(m_mutex);
        request = p->request;
        state = p->state;
    }
    if (request != Request::None) {
        runTransition(p, request);
        return;
    }
    if (state == RTC::ACTIVE_STATE)
        execute(p);
    else if (state == RTC::ERROR_STATE)
        guarded([&] { return p->ref->on_error(p->handle); });
}

// --- PeriodicExecutionContext ---

PeriodicExecutionContext::PeriodicExecutionContext(double rate, double transitionTimeoutSeconds)
    : ExecutionContext("PeriodicExecutionContext", RTC::PERIODIC, rate, transitionTimeoutSeconds)
{
}

PeriodicExecutionContext::~PeriodicExecutionContext()
{
    // Before the members run() uses are gone.
    halt(true);
}

void PeriodicExecutionContext::started()
{
    if (hasWork())
        startThread();
}

bool PeriodicExecutionContext::hasWork() const
{
    for (const ParticipantPtr &p : m_participants) {
        if (p->request != Request::None || p->state == RTC::ACTIVE_STATE || p->state == RTC::ERROR_STATE)
            return true;
    }
    return false;
}

bool PeriodicExecutionContext::hasRequest() const
{
    return std::any_of(m_participants.begin(), m_participants.end(),
                       [](const ParticipantPtr &p) { return p->request != Request::None; });
}

RTC::ReturnCode_t PeriodicExecutionContext::requestTransition(const ParticipantPtr &p, RTC::LifeCycleState from,
                                                              Request request)
{
    std::unique_lock lock(m_mutex);
    if (!m_running || inOwnThread()) {
        lock.unlock();
        return transitionNow(p, from, request);
    }
    if (p->state != from || p->request != Request::None)
        return RTC::PRECONDITION_NOT_MET;
    p->request = request;
    startThread();
    m_wake.notify_all();
    // Wait a couple of periods at least, so slow rates still report the finished transition.
    const double waitSeconds = std::max(m_transitionTimeout, 2.0 / m_rate);
    m_transitioned.wait_for(lock, boundedSeconds(waitSeconds),
                            [&] { return p->request == Request::None || !m_running; });
    return RTC::RTC_OK;
}

void PeriodicExecutionContext::run()
{
    using Clock = std::chrono::steady_clock;
    auto next = Clock::now();
    for (;;) {
        runCycle();
        std::unique_lock lock(m_mutex);
        if (!m_running)
            return;
        // Only active components execute and only those in error are told so each period: with
        // neither (a stopped system) the thread sleeps until a transition is asked for, instead of
        // waking `rate` times a second for nothing.
        if (!hasWork()) {
            m_wake.wait(lock, [&] { return !m_running || hasWork(); });
            if (!m_running)
                return;
            next = Clock::now();
            continue;
        }
        next += boundedSeconds(1.0 / m_rate);
        const auto now = Clock::now();
        if (next < now)
            next = now; // overrun: do not try to catch up with a burst
        // A pending transition is served at once instead of waiting out the period.
        m_wake.wait_until(lock, next, [&] { return !m_running || hasRequest(); });
        if (!m_running)
            return;
    }
}

} // namespace Runtime
