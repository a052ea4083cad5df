// SPDX-License-Identifier: MIT
#include <coil/Signal.h>

#include <cstring>

namespace coil {
SignalAction::SignalAction()
    : m_handle(nullptr)
    , m_signum(0)
{ }

SignalAction::SignalAction(SignalHandler handle, int signum)
    : m_handle(handle)
    , m_signum(signum)
{
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = handle;
    sigemptyset(&action.sa_mask);
    if (handle == nullptr || ::sigaction(signum, &action, nullptr) != 0) {
        m_handle = nullptr;
        m_signum = 0;
    }
}

SignalAction::~SignalAction()
{
    if (m_signum != 0)
        ::signal(m_signum, SIG_DFL);
}
} // namespace coil
