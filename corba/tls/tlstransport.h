// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace Tls {

/**
 * How a process takes part in TLS, with OpenRTM-aist's rtc.conf keys and meanings: the certificate
 * authority whose certificates it trusts (`corba.ssl.certificate_authority_file`), its own private key
 * and certificate in one PEM file (`corba.ssl.key_file`) and the key's password
 * (`corba.ssl.key_file_password`, empty for an unencrypted key).
 */
struct Settings
{
    std::string certificateAuthorityFile;
    std::string keyFile;
    std::string keyFilePassword;

    /// True when any key is set: the process then speaks TLS only.
    bool enabled() const { return !certificateAuthorityFile.empty() || !keyFile.empty(); }
};

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
     * ORB_init options for a TLS process: an SSL endpoint per `host:port` of @p listen (for a
     * client, none given: one on every interface and a port of the system's choosing, for the
     * objects it serves such as a port tap's), and transport rules that accept and use SSL only.
     */
    static std::vector<std::string> orbArguments(const std::vector<std::string> &listen = {});

    /**
     * How Debian's omniNames serves over TLS with @p settings: the environment variables to add
     * (the SSL transport's library preloaded, its files in omniORB's ORBssl* variables, which other
     * users cannot read as they could a command line) and the options to add after its own
     * (`-ignoreport`, the SSL endpoint at @p address `host:port`, TLS only).
     */
    static std::vector<std::pair<std::string, std::string>> nameServerEnvironment(const Settings &settings);
    static std::vector<std::string> nameServerArguments(const std::string &address);

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
