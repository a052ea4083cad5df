// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Corba {

/**
 * `host:port` of the first IIOP profile of a stringified object reference (`IOR:0123…`), empty
 * when the text is not a readable IOR. The online views group calls and reachability by it, and
 * reports name the process that serves an object with it, without asking the ORB.
 */
QString iorEndpoint(const QString &ior);

/// The host a reference points at: the first IIOP profile's of an IOR, the first address's of a
/// `corbaloc:` URL (an IPv6 address without its brackets); empty when neither can be read.
QString referenceHost(const QString &reference);

/**
 * Whether @p host names this machine: `localhost`, a loopback address, the machine's host name or
 * an address of one of its network interfaces. Names are not looked up (no name service is asked).
 */
bool isThisHost(const QString &host);

} // namespace Corba
