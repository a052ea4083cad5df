// SPDX-License-Identifier: MIT
// RTObject_impl's FSM hooks and FSM action listeners.
#include "fsmactions.h"

namespace RTC {

namespace {

size_t indexOf(PreFsmActionListenerType type)
{
    return size_t(type);
}

size_t indexOf(PostFsmActionListenerType type)
{
    return size_t(type);
}

} // namespace

void RTObject_impl::addFsmProfileListener(FsmProfileListenerType listener_type, FsmProfileListener *listener,
                                          bool autoclean)
{
    m_fsmActionListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removeFsmProfileListener(FsmProfileListenerType listener_type, FsmProfileListener *listener)
{
    m_fsmActionListeners.removeListener(listener_type, listener);
}

void RTObject_impl::addFsmStructureListener(FsmStructureListenerType listener_type, FsmStructureListener *listener,
                                            bool autoclean)
{
    m_fsmActionListeners.addListener(listener_type, listener, autoclean);
}

void RTObject_impl::removeFsmStructureListener(FsmStructureListenerType listener_type,
                                               FsmStructureListener *listener)
{
    m_fsmActionListeners.removeListener(listener_type, listener);
}

void RTObject_impl::addPreFsmActionListener(PreFsmActionListenerType listener_type, PreFsmActionListener *listener,
                                            bool autoclean)
{
    if (indexOf(listener_type) >= FsmActions::kinds)
        return;
    std::lock_guard lock(m_fsmActions->mutex);
    m_fsmActions->pre[indexOf(listener_type)].add(listener, autoclean);
}

void RTObject_impl::removePreFsmActionListener(PreFsmActionListenerType listener_type,
                                               PreFsmActionListener *listener)
{
    if (indexOf(listener_type) >= FsmActions::kinds)
        return;
    std::lock_guard lock(m_fsmActions->mutex);
    m_fsmActions->pre[indexOf(listener_type)].remove(listener);
}

void RTObject_impl::addPostFsmActionListener(PostFsmActionListenerType listener_type, PostFsmActionListener *listener,
                                             bool autoclean)
{
    if (indexOf(listener_type) >= FsmActions::kinds)
        return;
    std::lock_guard lock(m_fsmActions->mutex);
    m_fsmActions->post[indexOf(listener_type)].add(listener, autoclean);
}

void RTObject_impl::removePostFsmActionListener(PostFsmActionListenerType listener_type,
                                                PostFsmActionListener *listener)
{
    if (indexOf(listener_type) >= FsmActions::kinds)
        return;
    std::lock_guard lock(m_fsmActions->mutex);
    m_fsmActions->post[indexOf(listener_type)].remove(listener);
}

// Listeners run under the lock: one removed meanwhile is never called afterwards.
#define RTSDK_NOTIFY_PRE(TYPE)                                                                                 \
    std::lock_guard lock(m_fsmActions->mutex);                                                                 \
    m_fsmActions->pre[indexOf(PreFsmActionListenerType::TYPE)].forEach(                                        \
        [state](PreFsmActionListener &listener) { listener(state); })
#define RTSDK_NOTIFY_POST(TYPE)                                                                                \
    std::lock_guard lock(m_fsmActions->mutex);                                                                 \
    m_fsmActions->post[indexOf(PostFsmActionListenerType::TYPE)].forEach(                                      \
        [state, ret](PostFsmActionListener &listener) { listener(state, ret); })

void RTObject_impl::preOnFsmInit(const char *state)
{
    RTSDK_NOTIFY_PRE(PRE_ON_INIT);
}

void RTObject_impl::preOnFsmEntry(const char *state)
{
    RTSDK_NOTIFY_PRE(PRE_ON_ENTRY);
}

void RTObject_impl::preOnFsmDo(const char *state)
{
    RTSDK_NOTIFY_PRE(PRE_ON_DO);
}

void RTObject_impl::preOnFsmExit(const char *state)
{
    RTSDK_NOTIFY_PRE(PRE_ON_EXIT);
}

void RTObject_impl::preOnFsmStateChange(const char *state)
{
    RTSDK_NOTIFY_PRE(PRE_ON_STATE_CHANGE);
}

void RTObject_impl::postOnFsmInit(const char *state, ReturnCode_t ret)
{
    RTSDK_NOTIFY_POST(POST_ON_INIT);
}

void RTObject_impl::postOnFsmEntry(const char *state, ReturnCode_t ret)
{
    RTSDK_NOTIFY_POST(POST_ON_ENTRY);
}

void RTObject_impl::postOnFsmDo(const char *state, ReturnCode_t ret)
{
    RTSDK_NOTIFY_POST(POST_ON_DO);
}

void RTObject_impl::postOnFsmExit(const char *state, ReturnCode_t ret)
{
    RTSDK_NOTIFY_POST(POST_ON_EXIT);
}

void RTObject_impl::postOnFsmStateChange(const char *state, ReturnCode_t ret)
{
    setFsmState(state);
    RTSDK_NOTIFY_POST(POST_ON_STATE_CHANGE);
}

#undef RTSDK_NOTIFY_PRE
#undef RTSDK_NOTIFY_POST

void RTObject_impl::setFsmState(const char *state)
{
    const std::string name = state != nullptr ? state : "";
    {
        std::lock_guard lock(m_fsmActions->mutex);
        if (m_fsmActions->state == name)
            return;
        m_fsmActions->state = name;
    }
    RTC_DEBUG(("FSM state: %s", name.c_str()));
    setStatus("fsm_state", name);
}

std::string RTObject_impl::getFsmState() const
{
    std::lock_guard lock(m_fsmActions->mutex);
    return m_fsmActions->state;
}

} // namespace RTC
