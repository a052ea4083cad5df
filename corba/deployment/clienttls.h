// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Deploy {

/// Where a program's TLS settings came from.
enum class TlsSource { None, Environment, LocalRuntime };

/**
 * Chooses TLS for the calling program's CORBA connections (rtctl, rtstudio), before its first remote
 * call: the files named by RTSTUDIO_TLS_CA, RTSTUDIO_TLS_KEY and RTSTUDIO_TLS_KEY_PASSWORD when
 * RTSTUDIO_TLS_CA is set (the same meanings as OpenRTM-aist's corba.ssl.* keys); else, when the
 * user's local runtime runs with TLS, its authority and the user's certificate. False with the
 * reason when the files named cannot be used; @p source says which applied.
 */
bool configureClientTls(QString *error, TlsSource *source = nullptr);

} // namespace Deploy
