// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>

#include <csignal>
#include <memory>

class QSocketNotifier;

namespace Codegen {

/**
 * While it lives, SIGINT, SIGTERM and SIGHUP no longer end the program at once: each one arrives
 * as received() in the event loop of the thread that made this object (the handler only writes
 * the signal's number to a pipe), so the program can stop what it started before it ends. One
 * lives at a time in a process; the handlers it replaced come back when it goes.
 */
class InterruptSignals : public QObject
{
    Q_OBJECT

public:
    explicit InterruptSignals(QObject *parent = nullptr);
    ~InterruptSignals() override;

    /// Puts the default action of @p signal back and raises it: the program ends as the signal meant.
    [[noreturn]] static void endAsSignalled(int signal);

signals:
    void received(int signal);

private:
    std::unique_ptr<QSocketNotifier> m_notifier;
    struct sigaction m_replaced[3] = {};
};

} // namespace Codegen
