// SPDX-License-Identifier: MIT
#pragma once

#include <RTC.hh>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace Runtime {

/**
 * OpenRTM's PeriodicExecutionContext: a thread that, at `rate` Hz, drives every participant through
 * the OMG RTC state machine (INACTIVE → ACTIVE → ERROR → INACTIVE) and calls on_execute /
 * on_state_update on the active ones. State changes requested while the context runs happen in its
 * thread (the caller waits for them, bounded by the transition timeout); while it is stopped they
 * happen at once in the caller's thread. The thread starts with the first such request: a running
 * context of components that were only created (inactive) has no thread yet.
 */
class PeriodicExecutionContext : public virtual POA_RTC::ExecutionContextService
{
public:
    /// @p transitionTimeoutSeconds bounds how long activate/deactivate/reset wait for the EC thread.
    explicit PeriodicExecutionContext(double rate, double transitionTimeoutSeconds = 0.5);
    ~PeriodicExecutionContext() override;

    /// Adds the owning component with its handle for this context, without a remote attach_context.
    void addOwner(RTC::LightweightRTObject_ptr owner, RTC::ExecutionContextHandle_t handle);
    /// Stops the thread (no on_shutdown when @p quiet) — used when the owner goes away.
    void halt(bool quiet = false);

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

private:
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
    RTC::ReturnCode_t requestTransition(RTC::LightweightRTObject_ptr comp, RTC::LifeCycleState from,
                                        Request request);
    void process(const ParticipantPtr &p);
    void runTransition(const ParticipantPtr &p, Request request);
    void execute(const ParticipantPtr &p);
    void setState(const ParticipantPtr &p, RTC::LifeCycleState state);
    /// Whether a participant needs the thread: a transition asked for, or a state acted on each period.
    bool hasWork() const; // m_mutex held
    /// Starts the thread once the context runs and has work: a context whose components were only
    /// created costs no thread (m_mutex held).
    void startThread();
    void run();

    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::condition_variable m_transitioned;
    std::vector<ParticipantPtr> m_participants;
    std::thread m_thread;
    bool m_running = false;
    double m_rate;
    double m_transitionTimeout;
    RTC::RTObject_var m_ownerRef;
};

} // namespace Runtime
