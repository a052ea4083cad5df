// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <SDOPackage.hh>

#include <string>
#include <vector>

namespace Runtime {

/// Appends (or replaces) @p name = string @p value in @p list.
void nvSet(SDOPackage::NVList &list, const std::string &name, const std::string &value);
/// The string value of @p name in @p list; empty when absent or not a string.
std::string nvString(const SDOPackage::NVList &list, const std::string &name);
/// True when @p list has an entry @p name.
bool nvContains(const SDOPackage::NVList &list, const std::string &name);
/// Every string entry of @p list as properties (non-string values are skipped).
Properties nvToProperties(const SDOPackage::NVList &list);
/// Properties as an NVList of strings.
SDOPackage::NVList propertiesToNv(const Properties &properties);

/// Appends the elements of @p part to @p into (CORBA sequences; references are duplicated).
template<typename Sequence> void appendSequence(Sequence &into, const Sequence &part)
{
    const CORBA::ULong n = into.length();
    into.length(n + part.length());
    for (CORBA::ULong i = 0; i < part.length(); ++i)
        into[n + i] = part[i];
}

/// A new universally unique id (random, RFC 4122 version 4 text form).
std::string newUuid();

/**
 * Deactivates @p servant in @p poa (the POA drops its reference once in-flight calls finish) and
 * drops the creator's reference. Never throws.
 */
void releaseServant(PortableServer::POA_ptr poa, PortableServer::ServantBase *servant);

/// The process's ORB (initialised earlier by the runtime's owner).
CORBA::ORB_var theOrb();

/**
 * The URL of the object @p key at @p address, in any of the forms OpenRTM-aist's rtc.conf accepts
 * for name servers and managers: `host:port`; `giop:tcp:`, `giop::`, `inet:`, `iiop:`, `iiop://`
 * before it (TCP) or `giop:ssl:`, `ssliop:`, `ssliop://` (TLS); a `corbaloc:` URL the key is added to
 * after `/`, a `corbaname:` URL after `#`. A bare `host:port` is reached over TLS when @p tls, else
 * as `corbaloc:iiop:1.2@`: GIOP 1.2 from the first call, because with corbaloc's default 1.0 omniORB
 * talks to the object over one connection and to the references it hands out (a naming context, a
 * new slave) over a second one, a connection and a server thread more on both sides.
 */
std::string objectUrl(const std::string &address, const std::string &key, bool tls);

/// The reference objectUrl() names, over TLS when this process uses it.
CORBA::Object_ptr corbalocObject(const std::string &address, const std::string &key);

/// A loopback TCP port nobody listens on right now (for a manager process we start ourselves).
int freeLoopbackPort();

/**
 * The folder where this user's managers and components keep the Unix domain sockets that peers on
 * the same host reach them through (`rtstudio-orb-<uid>` in `$XDG_RUNTIME_DIR`, else in `$TMPDIR`
 * or /tmp), created private to the user. With @p removeStale, sockets left by processes that are
 * gone (killed before their ORB removed them) are removed. Empty when the folder cannot be made.
 */
std::string localSocketFolder(bool removeStale = true);

/**
 * Whether two references name the same object. omniORB calls remote references equivalent only when
 * they reach the object the same way, so `corbaloc:iiop:host:port/manager` and the manager's own
 * reference (which also offers a Unix socket) would differ; here they are the same when their object
 * keys are and they share a TCP address.
 */
bool sameObject(CORBA::Object_ptr a, CORBA::Object_ptr b);

/// `host:port` of each TCP address a reference offers (none for an unreadable one).
std::vector<std::string> tcpAddresses(CORBA::Object_ptr object);

/// The running program's name (`rtmanager`, `ConsoleInComp`, …), the prefix of its messages.
const char *programName();

/// One-line text of a CORBA exception for error messages.
std::string describeException(const CORBA::Exception &e);

} // namespace Runtime
