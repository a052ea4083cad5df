// SPDX-License-Identifier: MIT
#include "interruptsignals.h"

#include <QSocketNotifier>

#include <cstdlib>
#include <iterator>
#include <fcntl.h>
#include <unistd.h>

namespace Codegen {

namespace {

constexpr int Handled[] = {SIGINT, SIGTERM, SIGHUP};

/// The pipe between the handler (writes) and the notifier (reads).
int signalPipe[2] = {-1, -1};

void onSignal(int signal)
{
    const char number = char(signal);
    [[maybe_unused]] const ssize_t written = ::write(signalPipe[1], &number, 1);
}

} // namespace

InterruptSignals::InterruptSignals(QObject *parent)
    : QObject(parent)
{
    if (signalPipe[0] >= 0 || ::pipe2(signalPipe, O_CLOEXEC | O_NONBLOCK) != 0)
        return;
    m_notifier = std::make_unique<QSocketNotifier>(signalPipe[0], QSocketNotifier::Read);
    connect(m_notifier.get(), &QSocketNotifier::activated, this, [this] {
        char number;
        while (::read(signalPipe[0], &number, 1) == 1)
            emit received(int(number));
    });
    struct sigaction action = {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (std::size_t i = 0; i < std::size(Handled); ++i)
        ::sigaction(Handled[i], &action, &m_replaced[i]);
}

InterruptSignals::~InterruptSignals()
{
    if (!m_notifier)
        return;
    for (std::size_t i = 0; i < std::size(Handled); ++i)
        ::sigaction(Handled[i], &m_replaced[i], nullptr);
    m_notifier.reset();
    ::close(signalPipe[0]);
    ::close(signalPipe[1]);
    signalPipe[0] = signalPipe[1] = -1;
}

void InterruptSignals::endAsSignalled(int signal)
{
    ::signal(signal, SIG_DFL);
    ::raise(signal);
    std::_Exit(128 + signal); // when the signal's default action is to go on
}

} // namespace Codegen
