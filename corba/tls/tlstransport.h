// SPDX-License-Identifier: MIT
#pragma once

#include "tlsarguments.h"

#include <string>

namespace Tls {

/**
 * omniORB's SSL transport for the whole process. Every connection made or accepted is TLS, and
 * both ends present a certificate that the other verifies against its certificate authority: a
 * peer without one, with one of another authority or with an expired one is refused while the
 * connection is set up, before any request runs.
 */
class Transport
{
public:
    /**
     * Checks @p settings (both files readable PEM, the key opens with the password and belongs to the
     * certificate, the certificate is signed by the authority and valid now) and configures omniORB's
     * SSL transport with them; before the process's ORB is initialised. False with a message naming
     * the file and what is wrong in @p error.
     */
    static bool install(const Settings &settings, std::string *error);

    /// True once install() succeeded.
    static bool installed();

    /**
     * Why the last TLS connection set-up of this process failed, as OpenSSL names it: the peer's
     * alert ("the peer refused: certificate expired") or this side's verification of the peer's
     * certificate ("the peer's certificate: unable to get local issuer certificate"); empty
     * when none failed.
     */
    static std::string lastFailure();
};

/// What a certificate says: its subject and issuer (one line each), validity and whether it is a CA.
struct CertificateInfo
{
    std::string subject;
    std::string issuer;
    std::string commonName;
    std::string notBefore; ///< ISO 8601, UTC
    std::string notAfter;
    bool authority = false;
    bool expired = false;
    bool notYetValid = false;
};

/// Reads the first certificate of the PEM file @p path; false with the reason in @p error.
bool readCertificate(const std::string &path, CertificateInfo *info, std::string *error);

} // namespace Tls
