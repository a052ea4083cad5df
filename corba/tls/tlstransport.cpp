// SPDX-License-Identifier: MIT
#include "tlstransport.h"

#include "omniorbssl.h"

#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/ssl.h>
#include <openssl/x509v3.h>

#include <arpa/inet.h>
#include <sys/socket.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <mutex>

namespace Tls {

namespace {

std::atomic<bool> s_installed {false};

// The settings outlive install(): omniORB reads its static members when the ORB starts. Made on
// first use, as install() may run from another library's static initialiser (the name server's).
Settings &installedSettings()
{
    static Settings settings;
    return settings;
}
// Client connections are set up in the thread that makes the call, so the reason a set-up failed
// is kept per thread for that call's error message. With TLS 1.3 a server's refusal of the
// client's certificate arrives after the handshake, possibly read by another of the ORB's threads:
// the process keeps the latest reason too, for a short while.
thread_local std::string t_lastFailure;
std::mutex s_failureMutex;
std::string s_lastFailure;
std::chrono::steady_clock::time_point s_lastFailureTime;
constexpr std::chrono::seconds RecentFailure {5};

void recordFailure(const std::string &reason)
{
    t_lastFailure = reason;
    std::lock_guard lock(s_failureMutex);
    s_lastFailure = reason;
    s_lastFailureTime = std::chrono::steady_clock::now();
}

// OpenSSL's and the C library's objects, each freed by its own function.
template<auto release>
struct Freeing
{
    template<typename T>
    void operator()(T *object) const
    {
        release(object);
    }
};
using File = std::unique_ptr<FILE, Freeing<::fclose>>;
using Certificate = std::unique_ptr<X509, Freeing<X509_free>>;
using PrivateKey = std::unique_ptr<EVP_PKEY, Freeing<EVP_PKEY_free>>;
using Store = std::unique_ptr<X509_STORE, Freeing<X509_STORE_free>>;
using StoreContext = std::unique_ptr<X509_STORE_CTX, Freeing<X509_STORE_CTX_free>>;

std::string openSslError()
{
    const unsigned long code = ERR_get_error();
    ERR_clear_error();
    if (code == 0)
        return "not PEM";
    char text[256];
    ERR_error_string_n(code, text, sizeof text);
    return text;
}

int passwordCallback(char *buffer, int size, int, void *password)
{
    const std::string &text = *static_cast<const std::string *>(password);
    if (text.empty() || int(text.size()) > size)
        return -1;
    text.copy(buffer, text.size());
    return int(text.size());
}

File openFile(const std::string &what, const std::string &path, std::string *error)
{
    File file(std::fopen(path.c_str(), "r"));
    if (!file)
        *error = what + ' ' + path + ": cannot be read";
    return file;
}

std::string timeText(const ASN1_TIME *time)
{
    struct tm parts = {};
    if (!time || ASN1_TIME_to_tm(time, &parts) != 1)
        return {};
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
    return text;
}

std::string nameText(const X509_NAME *name)
{
    char text[512];
    X509_NAME_oneline(name, text, sizeof text);
    return text;
}

std::string commonName(const X509_NAME *name)
{
    char text[256];
    return X509_NAME_get_text_by_NID(const_cast<X509_NAME *>(name), NID_commonName, text, sizeof text) > 0
        ? std::string(text)
        : std::string();
}

bool loadAuthority(const std::string &path, X509_STORE *store, std::string *error)
{
    File file = openFile("certificate authority file", path, error);
    if (!file)
        return false;
    int count = 0;
    while (X509 *read = PEM_read_X509(file.get(), nullptr, nullptr, nullptr)) {
        Certificate certificate(read);
        X509_STORE_add_cert(store, certificate.get());
        ++count;
    }
    ERR_clear_error();
    if (count == 0) {
        *error = "certificate authority file " + path + ": no PEM certificate in it";
        return false;
    }
    return true;
}

// The key file holds the private key and the certificate (and may hold the chain): omniORB reads
// both from it, as OpenRTM-aist's SSL transport does.
bool checkKeyFile(const Settings &settings, X509_STORE *store, std::string *error)
{
    const std::string &path = settings.keyFile;
    File file = openFile("key file", path, error);
    if (!file)
        return false;
    Certificate certificate(PEM_read_X509(file.get(), nullptr, nullptr, nullptr));
    if (!certificate) {
        *error = "key file " + path + ": no PEM certificate in it (" + openSslError() + ')';
        return false;
    }
    std::rewind(file.get());
    std::string password = settings.keyFilePassword;
    PrivateKey key(PEM_read_PrivateKey(file.get(), nullptr, passwordCallback, &password));
    if (!key) {
        *error = "key file " + path + ": no private key that opens "
            + (password.empty() ? std::string("without a password") : std::string("with the password given"))
            + " (" + openSslError() + ')';
        return false;
    }
    if (X509_check_private_key(certificate.get(), key.get()) != 1) {
        ERR_clear_error();
        *error = "key file " + path + ": the private key does not belong to its certificate";
        return false;
    }
    if (!store)
        return true;
    StoreContext context(X509_STORE_CTX_new());
    X509_STORE_CTX_init(context.get(), store, certificate.get(), nullptr);
    if (X509_verify_cert(context.get()) != 1) {
        const int code = X509_STORE_CTX_get_error(context.get());
        *error = "key file " + path + ": its certificate (" + nameText(X509_get_subject_name(certificate.get()))
            + ") does not verify against " + settings.certificateAuthorityFile + ": "
            + X509_verify_cert_error_string(code);
        ERR_clear_error();
        return false;
    }
    return true;
}

int verifyCallback(int ok, X509_STORE_CTX *context)
{
    if (!ok) {
        X509 *certificate = X509_STORE_CTX_get_current_cert(context);
        recordFailure("the peer's certificate"
                      + (certificate ? " (" + nameText(X509_get_subject_name(certificate)) + ')' : std::string())
                      + " was refused: " + X509_verify_cert_error_string(X509_STORE_CTX_get_error(context)));
    }
    return ok;
}

// Empty when the peer has gone already (a probe of whether the port listens).
std::string peerAddress(const SSL *ssl)
{
    sockaddr_storage address = {};
    socklen_t size = sizeof address;
    if (getpeername(SSL_get_fd(ssl), reinterpret_cast<sockaddr *>(&address), &size) != 0)
        return {};
    char host[INET6_ADDRSTRLEN] = {};
    int port = 0;
    if (address.ss_family == AF_INET) {
        const auto *in = reinterpret_cast<const sockaddr_in *>(&address);
        inet_ntop(AF_INET, &in->sin_addr, host, sizeof host);
        port = ntohs(in->sin_port);
    } else if (address.ss_family == AF_INET6) {
        const auto *in6 = reinterpret_cast<const sockaddr_in6 *>(&address);
        inet_ntop(AF_INET6, &in6->sin6_addr, host, sizeof host);
        port = ntohs(in6->sin6_port);
    }
    return std::string(host) + ':' + std::to_string(port);
}

// OpenSSL names the alerts of TLS 1.2; TLS 1.3's own are "unknown" to it.
std::string alertText(int value)
{
    switch (value & 0xff) {
    case 109:
        return "missing extension";
    case 116:
        return "certificate required (none was presented)";
    case 120:
        return "no application protocol";
    default:
        return SSL_alert_desc_string_long(value);
    }
}

// Fatal alerts are the TLS handshake's refusals: the one received says why the peer refused us,
// the one sent why we refused the peer (also said on standard error, a server's log).
void infoCallback(const SSL *ssl, int where, int value)
{
    if (where & SSL_CB_HANDSHAKE_START)
        t_lastFailure.clear();
    if (!(where & SSL_CB_ALERT) || std::string(SSL_alert_type_string(value)) != "F")
        return;
    const std::string reason = alertText(value);
    if (where & SSL_CB_READ) {
        recordFailure("the peer refused the TLS connection: " + reason);
        return;
    }
    // A client's refusals reach its caller in the call's error.
    if (!SSL_is_server(ssl))
        return;
    const std::string why = t_lastFailure.empty() ? reason : t_lastFailure;
    const std::string peer = peerAddress(ssl);
    if (!peer.empty())
        std::fprintf(stderr, "TLS: refused the connection of %s: %s\n", peer.c_str(), why.c_str());
}

} // namespace

bool Transport::install(const Settings &settings, std::string *error)
{
    if (settings.certificateAuthorityFile.empty()) {
        *error = "corba.ssl.certificate_authority_file is not set: TLS needs the authority whose "
                 "certificates it trusts";
        return false;
    }
    Store store(X509_STORE_new());
    if (!loadAuthority(settings.certificateAuthorityFile, store.get(), error))
        return false;
    if (!settings.keyFile.empty() && !checkKeyFile(settings, store.get(), error))
        return false;
    Settings &kept = installedSettings();
    kept = settings;
    if (!Internal::configureOmniOrbSsl(kept, verifyCallback, infoCallback, error))
        return false;
    s_installed = true;
    return true;
}

bool Transport::installed()
{
    return s_installed;
}

std::string Transport::lastFailure()
{
    if (!t_lastFailure.empty())
        return t_lastFailure;
    {
        std::lock_guard lock(s_failureMutex);
        if (std::chrono::steady_clock::now() - s_lastFailureTime < RecentFailure && !s_lastFailure.empty())
            return s_lastFailure;
    }
    // The server's refusal may not be read at all (the connection is closed under the client's
    // first request); without a certificate of its own, that is the likely reason.
    if (s_installed && installedSettings().keyFile.empty())
        return "this program presents no certificate (corba.ssl.key_file, RTSTUDIO_TLS_KEY), which the "
               "servers require";
    return {};
}

bool readCertificate(const std::string &path, CertificateInfo *info, std::string *error)
{
    File file = openFile("certificate file", path, error);
    if (!file)
        return false;
    Certificate certificate(PEM_read_X509(file.get(), nullptr, nullptr, nullptr));
    if (!certificate) {
        *error = "certificate file " + path + ": no PEM certificate in it (" + openSslError() + ')';
        return false;
    }
    info->subject = nameText(X509_get_subject_name(certificate.get()));
    info->issuer = nameText(X509_get_issuer_name(certificate.get()));
    info->commonName = commonName(X509_get_subject_name(certificate.get()));
    info->notBefore = timeText(X509_get0_notBefore(certificate.get()));
    info->notAfter = timeText(X509_get0_notAfter(certificate.get()));
    info->authority = X509_check_ca(certificate.get()) > 0;
    info->expired = X509_cmp_current_time(X509_get0_notAfter(certificate.get())) < 0;
    info->notYetValid = X509_cmp_current_time(X509_get0_notBefore(certificate.get())) > 0;
    return true;
}

} // namespace Tls
