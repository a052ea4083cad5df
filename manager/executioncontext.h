// SPDX-License-Identifier: MIT
#pragma once

#include <RTC.hh>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace Runtime {

/**
 * The part every execution context shares: the participants and the OMG RTC state machine
 * (INACTIVE → ACTIVE → ERROR → INACTIVE) they go through, and runCycle(), which calls on_execute /
 * on_state_update on the active ones and on_error on the failed ones. What drives the cycles — a
 * timer thread, a remote tick(), a simulator — is the subclass's business. By default state
 * changes happen at once in the caller's thread, serialized with the cycles.
 */
class ExecutionContext : public virtual POA_RTC::ExecutionContextService
{
public:
    /// @p typeName is the name the context is known by (profile property `type`, ECFactory).
    ExecutionContext(const std::string &typeName, RTC::ExecutionKind kind, double rate,
                     double transitionTimeoutSeconds);
    ~ExecutionContext() override;
    ExecutionContext(const ExecutionContext &) = delete;
    ExecutionContext &operator=(const ExecutionContext &) = delete;

    const std::string &typeName() const { return m_typeName; }
    /// Adds the owning component with its handle for this context, without a remote attach_context.
    void addOwner(RTC::LightweightRTObject_ptr owner, RTC::ExecutionContextHandle_t handle);
    /// Stops the context's thread, if any (no on_shutdown when @p quiet) — used when the owner goes away.
    void halt(bool quiet = false);
    /// One cycle in the caller's thread: pending transitions, then on_execute + on_state_update for
    /// the active participants and on_error for those in error.
    void runCycle();
    /// How many cycles have run so far.
    unsigned long cycles();
    /// Sets the kind get_kind() and the profile report.
    void setExecutionKind(RTC::ExecutionKind kind);

    // RTC::ExecutionContext
    CORBA::Boolean is_running() override;
    RTC::ReturnCode_t start() override;
    RTC::ReturnCode_t stop() override;
    CORBA::Double get_rate() override;
    RTC::ReturnCode_t set_rate(CORBA::Double rate) override;
    RTC::ReturnCode_t add_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t remove_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t activate_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t deactivate_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::ReturnCode_t reset_component(RTC::LightweightRTObject_ptr comp) override;
    RTC::LifeCycleState get_component_state(RTC::LightweightRTObject_ptr comp) override;
    RTC::ExecutionKind get_kind() override;
    // RTC::ExecutionContextService
    RTC::ExecutionContextProfile *get_profile() override;

protected:
    enum class Request { None, Activate, Deactivate, Reset };
    struct Participant
    {
        RTC::LightweightRTObject_var ref;
        RTC::DataFlowComponentAction_var dataflow;
        RTC::ExecutionContextHandle_t handle = 0;
        RTC::LifeCycleState state = RTC::INACTIVE_STATE;
        Request request = Request::None;
        bool owner = false;
    };
    using ParticipantPtr = std::shared_ptr<Participant>;

    ParticipantPtr find(RTC::LightweightRTObject_ptr comp);
    std::vector<ParticipantPtr> snapshot();
    /**
     * Moves @p p out of state @p from. The default runs the transition at once in the caller's
     * thread, between cycles; a context with a thread of its own may hand it to that thread.
     */
    virtual RTC::ReturnCode_t requestTransition(const ParticipantPtr &p, RTC::LifeCycleState from, Request request);
    RTC::ReturnCode_t transitionNow(const ParticipantPtr &p, RTC::LifeCycleState from, Request request);
    void runTransition(const ParticipantPtr &p, Request request);
    void setState(const ParticipantPtr &p, RTC::LifeCycleState state);
    /// Called with m_mutex held once the context runs; a context with a thread starts it here.
    virtual void started() {}
    /// The body of the context's thread (startThread()); it returns once m_running is false.
    virtual void run() {}
    /// Starts run() in a thread unless it runs already (m_mutex held).
    void startThread();
    /// Whether the caller is the context's own thread.
    bool inOwnThread() const { return m_thread.get_id() == std::this_thread::get_id(); }

    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::condition_variable m_transitioned;
    std::vector<ParticipantPtr> m_participants;
    bool m_running = false;
    double m_rate;
    double m_transitionTimeout;

private:
    void process(const ParticipantPtr &p);
    void execute(const ParticipantPtr &p);

    /// Recursive: a component may change its own state from inside on_execute.
    std::recursive_mutex m_cycleMutex;
    std::thread m_thread;
    std::string m_typeName;
    RTC::ExecutionKind m_kind;
    RTC::RTObject_var m_ownerRef;
    unsigned long m_cycles = 0;
};

/**
 * OpenRTM's PeriodicExecutionContext: a thread that runs a cycle `rate` times a second. State
 * changes requested while the context runs happen in its thread (the caller waits for them,
 * bounded by the transition timeout); while it is stopped they happen at once in the caller's
 * thread. The thread starts with the first such request: a running context of components that
 * were only created (inactive) has no thread yet.
 */
class PeriodicExecutionContext : public ExecutionContext
{
public:
    /// @p transitionTimeoutSeconds bounds how long activate/deactivate/reset wait for the EC thread.
    explicit PeriodicExecutionContext(double rate, double transitionTimeoutSeconds = 0.5);
    ~PeriodicExecutionContext() override;

protected:
    RTC::ReturnCode_t requestTransition(const ParticipantPtr &p, RTC::LifeCycleState from, Request request) override;
    void started() override;
    void run() override;

private:
    /// Whether a participant needs the thread: a transition asked for, or a state acted on each period.
    bool hasWork() const; // m_mutex held
    bool hasRequest() const; // m_mutex held
};

} // namespace Runtime
