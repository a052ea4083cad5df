// SPDX-License-Identifier: MIT
#pragma once

#include "tlsarguments.h"

#include <openssl/ssl.h>

#include <string>

namespace Tls::Internal {

using VerifyCallback = int (*)(int, X509_STORE_CTX *);
using InfoCallback = void (*)(const SSL *, int, int);

/**
 * Gives omniORB's SSL transport @p settings (kept alive by the caller) and the callbacks, before the
 * process's ORB is initialised. Two builds of it: one for programs linked with the transport, one that
 * loads the transport only when TLS is asked for, so that programs without TLS (every component on
 * the SDK by default) neither load it nor get omniORB's warning that it has no certificate authority.
 */
bool configureOmniOrbSsl(const Settings &settings, VerifyCallback verify, InfoCallback info, std::string *error);

} // namespace Tls::Internal
