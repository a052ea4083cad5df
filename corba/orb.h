// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

namespace Corba {

/**
 * Process-wide settings of the one ORB the client library uses. The ORB is created on first use
 * (thread-safe, exactly once); every proxy call in any thread then uses it. Arguments given after
 * the ORB exists have no effect.
 */
class Orb
{
public:
    /// Extra ORB_init options (e.g. `-ORBendPoint giop:tcp:127.0.0.1:0`), before first use.
    static void setArguments(const QStringList &arguments);
    /// Timeout in milliseconds applied to every remote call and connection attempt (default 3000).
    static void setCallTimeout(int milliseconds);
    static int callTimeout();
    /// True once the ORB has been created.
    static bool isInitialised();

    static constexpr int defaultCallTimeout = 3000;
};

} // namespace Corba
