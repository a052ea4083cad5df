// SPDX-License-Identifier: MIT
#pragma once

namespace Corba {

/**
 * Object references a peer sends whose profile omniORB cannot decode (an IIOP profile or a tagged
 * component that is not what its tag says) become references to no object: every call on them
 * fails with OBJECT_NOT_EXIST. Without this, omniORB 4.2.5 refuses the request or reply with
 * MARSHAL and loses the reference it was reading, with every byte of its profiles (up to a
 * message's size), so that a peer repeating such messages grows the process's memory without bound
 * (fuzz_giop found it). The runtime (managers, components) and the tools (rtctl, rtstudio, the
 * client library) install it. Works through omniORB's createIdentity interceptor, which sees each
 * reference before omniORB decodes it.
 */
class ReferenceGuard
{
public:
    /// Installs the guard for the ORB of this process (once; later calls do nothing).
    static void install();
    /**
     * How many undecodable references this thread has made into references to no object. A caller
     * turning text a user typed into a reference compares it before and after, to say that the
     * text does not decode rather than let the first call on it fail.
     */
    static unsigned long standInsOnThisThread();
};

} // namespace Corba
