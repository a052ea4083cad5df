// SPDX-License-Identifier: MIT
#pragma once

// What a TLS process is given: its files and its ORB options. Standard C++ only, so that programs
// that start TLS servers (the local runtime, the tests) need not link the transport.

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
 * ORB_init options for a TLS process: an SSL endpoint per `host:port` of @p listen (for a client,
 * none given: one on every interface and a port of the system's choosing, for the objects it serves
 * such as a port tap's), and transport rules that accept and use SSL only.
 */
inline std::vector<std::string> orbArguments(const std::vector<std::string> &listen = {})
{
    std::vector<std::string> arguments;
    for (const std::string &address : listen.empty() ? std::vector<std::string> {":"} : listen)
        arguments.insert(arguments.end(), {"-ORBendPoint", "giop:ssl:" + address});
    // Nothing but TLS in either direction: a reference offering only plain TCP is not used, and a
    // plain connection to our endpoints is not accepted.
    arguments.insert(arguments.end(), {"-ORBserverTransportRule", "* ssl", "-ORBclientTransportRule", "* ssl"});
    return arguments;
}

/**
 * How Debian's omniNames serves over TLS with @p settings: the environment variables to add (omniORB's
 * SSL transport preloaded by its soname, its files in omniORB's ORBssl* variables, which other users
 * cannot read as they could a command line).
 */
inline std::vector<std::pair<std::string, std::string>> nameServerEnvironment(const Settings &settings)
{
    return {{"LD_PRELOAD", RTSTUDIO_OMNIORB_SSL_SONAME},
            {"ORBsslCAFile", settings.certificateAuthorityFile},
            {"ORBsslKeyFile", settings.keyFile},
            // omniORB loads the key only when a password is given; an unencrypted key ignores it.
            {"ORBsslKeyPassword", settings.keyFilePassword.empty() ? "-" : settings.keyFilePassword}};
}

/// The options to add after omniNames' own: `-ignoreport`, the SSL endpoint at @p address, TLS only.
inline std::vector<std::string> nameServerArguments(const std::string &address)
{
    std::vector<std::string> arguments {"-ignoreport"};
    const std::vector<std::string> orb = orbArguments({address});
    arguments.insert(arguments.end(), orb.begin(), orb.end());
    return arguments;
}

} // namespace Tls
