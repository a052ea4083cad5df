// SPDX-License-Identifier: MIT
#include "interruptscope.h"

#include <csignal>

namespace Cli {

namespace {

std::atomic_bool s_interrupted {false};

void onInterrupt(int)
{
    s_interrupted = true;
}

} // namespace

InterruptScope::InterruptScope()
{
    s_interrupted = false;
    m_int = std::signal(SIGINT, onInterrupt);
    m_term = std::signal(SIGTERM, onInterrupt);
}

InterruptScope::~InterruptScope()
{
    std::signal(SIGINT, m_int);
    std::signal(SIGTERM, m_term);
}

const std::atomic_bool &InterruptScope::interrupted()
{
    return s_interrupted;
}

} // namespace Cli
