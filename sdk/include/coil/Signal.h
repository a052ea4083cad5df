// SPDX-License-Identifier: MIT
/*!
 * @file Signal.h
 * @brief coil::SignalAction: installs a signal handler for the lifetime of an object.
 */
#ifndef COIL_SIGNAL_H
#define COIL_SIGNAL_H

#include <coil/config_coil.h>

#include <csignal>
#include <signal.h>

namespace coil {
/*! A signal handler function. */
extern "C" typedef void (*SignalHandler)(int);

/*! Installs @p handle for @p signum; the destructor restores the default action. */
class SignalAction
{
public:
    /*! Installs nothing. */
    SignalAction();
    /*! Installs @p handle for signal @p signum. */
    SignalAction(SignalHandler handle, int signum);
    ~SignalAction();

private:
    SignalAction(const SignalAction &);
    SignalAction &operator=(const SignalAction &);
    SignalHandler m_handle;
    int m_signum;
};
} // namespace coil

#endif // COIL_SIGNAL_H
