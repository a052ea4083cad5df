// SPDX-License-Identifier: MIT
// hrtm::sc: the state-independent part of HRTM's state machines.
#include <hrtm/logger.h>
#include <hrtm/statechart.h>

namespace hrtm {
namespace sc {

namespace {
// Transitions are logged at DEBUG under this name, as HRTM does.
const char logName[] = "StateChart";
} // namespace

StateInfo &StateBase::get_info(MachineBase &machine)
{
    StateInfo *&root = machine.get_info(key());
    if (root == nullptr)
        root = new RootStateInfo(machine, nullptr);
    return *root;
}

void StateBase::shutdown()
{
    state_info_.machine().shutdown();
}

void StateBase::restore(StateInfo &current)
{
    state_info_.machine().current_state_ = &current;
}

StateInfo::StateInfo(MachineBase &machine, StateInfo *parent)
    : machine_(machine)
    , instance_(nullptr)
    , history_(nullptr)
    , parent_(parent)
    , data_(nullptr)
    , data_place(nullptr)
{ }

StateInfo::~StateInfo()
{
    delete instance_;
}

void StateInfo::on_entry(StateInfo &previous, bool first)
{
    if (parent_ == nullptr) // the root is never entered
        return;
    // The target is always entered (also when it was active: a self-transition); its
    // superstates only when the previous state was not inside them.
    if (!first && previous.is_child(*this))
        return;
    parent_->on_entry(previous, false);
    if (data_ == nullptr)
        create_data();
    HRTM_DEBUG(logName, name() << ": entry");
    instance_->on_entry();
}

void StateInfo::on_exit(StateInfo &next)
{
    if (parent_ == nullptr)
        return;
    // A state that contains the next one stays, unless it is the next one itself.
    if (this != &next && next.is_child(*this))
        return;
    HRTM_DEBUG(logName, name() << ": exit");
    instance_->on_exit();
    instance_->delete_data(*this);
    parent_->on_exit(next);
}

void StateInfo::on_init(bool history)
{
    StateInfo *remembered = history ? history_ : nullptr;
    history_ = nullptr; // a history is used once
    if (remembered != nullptr) {
        HRTM_DEBUG(logName, name() << ": history transition to: " << remembered->name());
        machine_.set_pending_state(*remembered, true, nullptr);
        return;
    }
    HRTM_DEBUG(logName, name() << ": init");
    instance_->on_init();
}

void StateInfo::copy(StateInfo &original)
{
    if (original.history_ != nullptr) {
        StateInfo *history = machine_.get_info(original.history_->key());
        assert(history);
        set_history(history);
    }
    if (original.data_ != nullptr)
        clone_data(original.data_);
}

StateInfo *StateInfo::clone(MachineBase &new_machine)
{
    assert(!new_machine.get_info(key()));
    // Superstates first: the state object's constructor looks its superstate up.
    StateInfo *parent = parent_ != nullptr ? new_machine.create_clone(parent_->key(), parent_) : nullptr;
    return create(new_machine, parent);
}

MachineBase::MachineBase() = default;

MachineBase::~MachineBase()
{
    delete[] states_;
    delete pending_event_;
    for (EventQueue::value_type &deferred : deferred_events_)
        delete deferred.second;
}

void MachineBase::set_state(StateInfo &info, bool history, void *data)
{
    set_pending_state(info, history, data);
    perform_pending();
}

void MachineBase::set_state(const StateAlias &state, bool history)
{
    set_pending_state(state.get_info(*this), history, state.take_data());
    perform_pending();
}

void MachineBase::start(StateInfo &info, void *data)
{
    HRTM_DEBUG(logName, "Starting Machine");
    current_state_ = &StateBase::get_info(*this);
    set_state(info, false, data);
}

void MachineBase::shutdown()
{
    assert(!pending_state_);
    HRTM_DEBUG(logName, "Shutting down Machine");
    // Going to the root leaves every state, running their exit actions.
    set_state(StateBase::get_info(*this), false, nullptr);
    current_state_ = nullptr;
}

void MachineBase::allocate(unsigned int count)
{
    states_ = new StateInfo *[count];
    std::fill(states_, states_ + count, nullptr);
}

void MachineBase::free(unsigned int count)
{
    // Substates have higher keys than their superstates: delete from the end.
    for (unsigned int i = count; i > 0; --i) {
        delete states_[i - 1];
        states_[i - 1] = nullptr;
    }
}

void MachineBase::copy(StateInfo **other, unsigned int count)
{
    for (Key i = 0; i < count; ++i)
        create_clone(i, other[i]);
    // Histories refer to other states: copied once all exist.
    for (Key i = 0; i < count; ++i) {
        if (states_[i] != nullptr)
            states_[i]->copy(*other[i]);
    }
}

StateInfo *MachineBase::create_clone(Key key, StateInfo *original)
{
    StateInfo *&clone = get_info(key);
    if (clone == nullptr && original != nullptr)
        clone = original->clone(*this);
    return clone;
}

void MachineBase::add_deferred_event(EventBase *event, const std::string &name)
{
    assert(event);
    if (deferred_events_.count(name) != 0) {
        HRTM_DEBUG(logName, name << " is already deferred.");
        delete event;
        return;
    }
    deferred_events_[name] = event;
    deferred_names_.push_back(name);
}

void MachineBase::take_pending_transition()
{
    StateInfo *target = pending_state_;
    HRTM_DEBUG(logName, current_state_->name() << ": transition to: " << target->name());
    current_state_->on_exit(*target);
    current_state_->set_history_super(*current_state_);
    StateInfo *previous = current_state_;
    current_state_ = target;
    if (pending_data_ != nullptr)
        current_state_->set_data(pending_data_);
    current_state_->on_entry(*previous);
    pending_state_ = nullptr;
    pending_data_ = nullptr;
    const bool history = pending_history_;
    pending_history_ = false;
    current_state_->on_init(history);
    assert("init may only move on to a proper substate"
           && (!pending_state_ || (pending_state_->is_child(*current_state_) && current_state_ != pending_state_)));
    perform_pending_event();
}

void MachineBase::perform_pending()
{
    assert(current_state_);
    if (pending_state_ == nullptr) {
        perform_pending_event();
        return;
    }
    // init actions may request further transitions (into substates): take them all. Deferred
    // events wait until the machine has settled, and may start the next round.
    do {
        while (pending_state_ != nullptr)
            take_pending_transition();
        perform_deferred_events();
        perform_pending_event(); // posted by a deferred event's handler
    } while (pending_state_ != nullptr);
}

void MachineBase::perform_pending_event()
{
    if (pending_event_ == nullptr)
        return;
    EventBase *event = pending_event_;
    pending_event_ = nullptr;
    event->dispatch(*current_state_);
    delete event;
}

void MachineBase::perform_deferred_events()
{
    if (deferred_events_.empty() || current_state_ == nullptr)
        return;
    // Taken out first: a handler may defer events again, for the transition after this one.
    EventQueue events;
    EventNames names;
    events.swap(deferred_events_);
    names.swap(deferred_names_);
    for (const std::string &name : names) {
        EventBase *event = events[name];
        if (current_state_ != nullptr)
            event->dispatch(*current_state_);
        delete event;
    }
}
} // namespace sc
} // namespace hrtm
