// SPDX-License-Identifier: MIT
#pragma once

#include "livesystem.h"
#include "orb.h"

#include <QProcess>

#include <csignal>

namespace LiveTest {

/**
 * Stops a process (SIGSTOP, as a debugger or a hung machine would) with a short call timeout in
 * force, and lets it go on (SIGCONT) with the usual timeout when it goes out of scope or on
 * resume(). isStopped() tells whether the stop took effect before the constructor returned.
 */
class StoppedProcess
{
public:
    StoppedProcess(QProcess *process, int callTimeoutMs, int usualTimeoutMs)
        : m_usualTimeout(usualTimeoutMs)
    {
        Corba::Orb::setCallTimeout(callTimeoutMs);
        // processId() is 0 once the process has ended, and kill(0, SIGSTOP) would stop this
        // test's own process group: check before signalling. SIGSTOP lands asynchronously, so
        // the stop is awaited (a call sent before it did would still be answered).
        if (process->state() == QProcess::Running && process->processId() > 0) {
            m_pid = pid_t(process->processId());
            m_stopped = ::kill(m_pid, SIGSTOP) == 0 && waitUntilStopped(m_pid, 5000);
        }
    }
    ~StoppedProcess() { resume(); }
    StoppedProcess(const StoppedProcess &) = delete;
    StoppedProcess &operator=(const StoppedProcess &) = delete;

    bool isStopped() const { return m_stopped; }
    void resume()
    {
        if (m_pid > 0)
            ::kill(m_pid, SIGCONT);
        m_pid = 0;
        m_stopped = false;
        Corba::Orb::setCallTimeout(m_usualTimeout);
    }

private:
    int m_usualTimeout;
    pid_t m_pid = 0;
    bool m_stopped = false;
};

} // namespace LiveTest
