// SPDX-License-Identifier: MIT
#pragma once

#include <QElapsedTimer>
#include <QFile>
#include <QTimer>

#include <algorithm>

namespace LiveTest {

/**
 * Measures how long the GUI thread's event loop was blocked while it runs: a 10 ms timer takes
 * the wall-clock gap between two ticks less the time the thread ran or waited for a CPU (Linux
 * schedstat). A busy machine stretches the gaps but not this; a remote call made on the GUI
 * thread would block it for a whole call timeout.
 */
class StallMeter
{
public:
    StallMeter()
    {
        m_clock.start();
        m_lastScheduled = scheduledNs();
        m_ticker.setInterval(10);
        QObject::connect(&m_ticker, &QTimer::timeout, [this] { tick(); });
        m_ticker.start();
    }
    void stop() { m_ticker.stop(); }
    /// The longest blocked stretch so far, in milliseconds.
    qint64 worstMs() const { return m_worstNs / 1000000; }
    qint64 worstNs() const { return m_worstNs; }
    /// Milliseconds since the meter started.
    qint64 elapsedMs() const { return m_clock.elapsed(); }

private:
    // Nanoseconds the calling thread has run or waited in a run queue; 0 where the kernel does
    // not tell, so that whole intervals count as blocked.
    static qint64 scheduledNs()
    {
        QFile file(QStringLiteral("/proc/thread-self/schedstat"));
        if (!file.open(QIODevice::ReadOnly))
            return 0;
        const QList<QByteArray> fields = file.readAll().split(' ');
        return fields.size() < 2 ? 0 : fields.at(0).toLongLong() + fields.at(1).toLongLong();
    }
    void tick()
    {
        const qint64 wall = m_clock.nsecsElapsed();
        const qint64 scheduled = scheduledNs();
        m_worstNs = std::max(m_worstNs, (wall - m_lastWall) - (scheduled - m_lastScheduled));
        m_lastWall = wall;
        m_lastScheduled = scheduled;
    }

    QElapsedTimer m_clock;
    QTimer m_ticker;
    qint64 m_lastWall = 0;
    qint64 m_lastScheduled = 0;
    qint64 m_worstNs = 0;
};

} // namespace LiveTest
