// SPDX-License-Identifier: MIT
#pragma once

namespace Runtime {

/**
 * Object references a peer sends whose profile omniORB cannot decode (an IIOP profile or a tagged
 * component that is not what its tag says) become references to no object: every call on them
 * fails with OBJECT_NOT_EXIST. Without this, omniORB 4.2.5 answers the request with MARSHAL and
 * loses the reference it was reading, with every byte of its profiles (up to a request's size), so
 * that a peer repeating such requests grows the process's memory without bound (fuzz_giop found it).
 * Works through omniORB's createIdentity interceptor, which sees each reference before omniORB
 * decodes it.
 */
class ReferenceGuard
{
public:
    /// Installs the guard for the ORB of this process (once; later calls do nothing).
    static void install();
};

} // namespace Runtime
