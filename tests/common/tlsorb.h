// SPDX-License-Identifier: MIT
#pragma once

// The ORB of a test or benchmark process that calls TLS servers itself (link rtcorba_tls_loaded).

#include "tlsarguments.h"
#include "tlstransport.h"

#include <omniORB4/CORBA.h>

#include <string>
#include <vector>

namespace LiveTest {

/**
 * Initialises this process's ORB as @p program; with enabled @p settings over TLS only, presenting
 * their certificate. Nil, with the reason in @p error, when the TLS files cannot be used.
 */
inline CORBA::ORB_ptr initOrb(const char *program, const Tls::Settings &settings, std::string *error)
{
    std::vector<std::string> arguments {program};
    if (settings.enabled()) {
        if (!Tls::Transport::install(settings, error))
            return CORBA::ORB::_nil();
        for (const std::string &argument : Tls::orbArguments())
            arguments.push_back(argument);
    }
    std::vector<char *> argv;
    for (std::string &argument : arguments)
        argv.push_back(argument.data());
    int argc = int(argv.size());
    return CORBA::ORB_init(argc, argv.data());
}

} // namespace LiveTest
