// SPDX-License-Identifier: MIT
#pragma once

#include "corbatypes.h"

#include <QByteArray>

#include <memory>
#include <optional>

namespace Corba {

/// One sample as it arrived: the CDR bytes and when (milliseconds since the epoch).
struct PortSample
{
    QByteArray cdr;
    qint64 receivedMs = 0;
};

/**
 * Watches a data OutPort from this process, as rtshell's rtprint does: a connector whose other
 * end is an InPortCdr object of this process (`dataport.corba_cdr.inport_ior`), pushed to by the
 * port like any InPort. Samples wait in a bounded queue (the oldest are dropped when the reader
 * falls behind). The connector is removed when the tap is destroyed or closed.
 */
class PortTap
{
public:
    /**
     * Connects to `port` (a DataOutPort's profile) with the subscription type and other
     * `dataport.*` settings of `properties` (rtcon's defaults otherwise: push, `new`). Throws
     * Corba::Error naming `path` when the port refuses or does not answer.
     */
    PortTap(const PortInfo &port, const Properties &properties, const QString &path,
            int queueLength = 1024);
    ~PortTap();
    PortTap(const PortTap &) = delete;
    PortTap &operator=(const PortTap &) = delete;

    /// The next sample, waiting at most `timeoutMs` (0: do not wait).
    std::optional<PortSample> next(int timeoutMs);
    /// Waits at most `timeoutMs` until a sample is there, and leaves it there.
    bool wait(int timeoutMs);
    /// Samples dropped because the queue was full.
    quint64 dropped() const;
    /// The connector's byte order.
    bool littleEndian() const;
    /// Removes the connector (once; later calls do nothing). Throws on a failed disconnect.
    void close();

private:
    struct Private;
    std::unique_ptr<Private> d;
};

/**
 * Writes samples into a data InPort from this process, as rtshell's rtinject does: a connector
 * made through the InPort alone, whose InPortCdr object (published by the port in the connector's
 * properties) then receives `put` calls. Removed when destroyed or closed.
 */
class PortFeed
{
public:
    PortFeed(const PortInfo &port, const Properties &properties, const QString &path);
    ~PortFeed();
    PortFeed(const PortFeed &) = delete;
    PortFeed &operator=(const PortFeed &) = delete;

    /// Sends one sample; throws Corba::Error when the port reports anything but PORT_OK
    /// (BUFFER_FULL, …, named in the message) or does not answer.
    void put(const QByteArray &cdr);
    bool littleEndian() const;
    void close();

private:
    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace Corba
