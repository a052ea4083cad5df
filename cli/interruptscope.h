// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>

namespace Cli {

/**
 * While it lives, SIGINT and SIGTERM (Ctrl+C, a service stop) set interrupted() instead of ending
 * the process, so that a command's loop can stop and clean up (remove its connector, stop
 * watching). The handlers in force before are put back when it ends.
 */
class InterruptScope
{
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope &) = delete;
    InterruptScope &operator=(const InterruptScope &) = delete;

    /// Set once a signal came; also what a DeployControl's cancel may point at.
    static const std::atomic_bool &interrupted();

private:
    void (*m_int)(int);
    void (*m_term)(int);
};

} // namespace Cli
