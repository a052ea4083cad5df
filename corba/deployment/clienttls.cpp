// SPDX-License-Identifier: MIT
#include "clienttls.h"

#include "localruntime.h"
#include "orb.h"

namespace Deploy {

bool configureClientTls(QString *error, TlsSource *source)
{
    TlsSource chosen = TlsSource::None;
    QString authority = qEnvironmentVariable("RTSTUDIO_TLS_CA");
    QString key = qEnvironmentVariable("RTSTUDIO_TLS_KEY");
    const QString password = qEnvironmentVariable("RTSTUDIO_TLS_KEY_PASSWORD");
    if (!authority.isEmpty()) {
        chosen = TlsSource::Environment;
    } else {
        const LocalRuntimeTls local = LocalRuntime().tls();
        if (local.enabled) {
            chosen = TlsSource::LocalRuntime;
            authority = local.certificateAuthorityFile;
            key = local.userKeyFile;
        }
    }
    if (source)
        *source = chosen;
    if (chosen == TlsSource::None)
        return true;
    return Corba::Orb::setTls(authority, key, password, error);
}

} // namespace Deploy
