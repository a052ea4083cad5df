// SPDX-License-Identifier: MIT
// For programs linked with omniORB's SSL transport (rtctl, rtstudio, the client library).
#include "omniorbssl.h"

#include <omniORB4/CORBA.h>
#include <omniORB4/sslContext.h>

namespace Tls::Internal {

bool configureOmniOrbSsl(const Settings &settings, VerifyCallback verify, InfoCallback info, std::string *)
{
    sslContext::certificate_authority_file = settings.certificateAuthorityFile.c_str();
    sslContext::key_file = settings.keyFile.empty() ? nullptr : settings.keyFile.c_str();
    // omniORB loads the private key only when a password is set (an unencrypted key ignores it), and
    // fails to start when it is set without a key file.
    sslContext::key_file_password = settings.keyFile.empty() ? nullptr : settings.keyFilePassword.c_str();
    // Both ends present a certificate; one without is refused during the handshake.
    sslContext::verify_mode = SSL_VERIFY_PEER | SSL_VERIFY_FAIL_IF_NO_PEER_CERT;
    sslContext::verify_callback = verify;
    sslContext::info_callback = info;
    return true;
}

} // namespace Tls::Internal
