// SPDX-License-Identifier: MIT
// For the runtime (rtmanager and every program on the SDK): omniORB's SSL transport is loaded when
// TLS is asked for. Loaded before the ORB starts, it registers itself as a linked one does; its
// settings are the static members of its sslContext class, found by their symbols in Debian's
// omniORB 4.2 library.
#include "omniorbssl.h"

#include <dlfcn.h>

namespace Tls::Internal {

namespace {

template<typename T>
T *member(void *library, const char *symbol, std::string *missing)
{
    void *address = dlsym(library, symbol);
    if (!address && missing->empty())
        *missing = symbol;
    return static_cast<T *>(address);
}

} // namespace

bool configureOmniOrbSsl(const Settings &settings, VerifyCallback verify, InfoCallback info, std::string *error)
{
    void *library = dlopen(RTSTUDIO_OMNIORB_SSL_SONAME, RTLD_NOW | RTLD_GLOBAL);
    if (!library) {
        *error = std::string("omniORB's SSL transport cannot be loaded (Debian package libomniorb4-2): ") + dlerror();
        return false;
    }
    std::string missing;
    auto *authority = member<const char *>(library, "_ZN10sslContext26certificate_authority_fileE", &missing);
    auto *keyFile = member<const char *>(library, "_ZN10sslContext8key_fileE", &missing);
    auto *password = member<const char *>(library, "_ZN10sslContext17key_file_passwordE", &missing);
    auto *verifyMode = member<int>(library, "_ZN10sslContext11verify_modeE", &missing);
    auto *verifyCallback = member<VerifyCallback>(library, "_ZN10sslContext15verify_callbackE", &missing);
    auto *infoCallback = member<InfoCallback>(library, "_ZN10sslContext13info_callbackE", &missing);
    if (!missing.empty()) {
        *error = std::string(RTSTUDIO_OMNIORB_SSL_SONAME) + " is not the SSL transport of omniORB 4.2: no " + missing;
        return false;
    }
    *authority = settings.certificateAuthorityFile.c_str();
    *keyFile = settings.keyFile.empty() ? nullptr : settings.keyFile.c_str();
    // As omniorbssllinked.cpp: a password makes omniORB load the key, and must not come without one.
    *password = settings.keyFile.empty() ? nullptr : settings.keyFilePassword.c_str();
    *verifyMode = SSL_VERIFY_PEER | SSL_VERIFY_FAIL_IF_NO_PEER_CERT;
    *verifyCallback = verify;
    *infoCallback = info;
    return true;
}

} // namespace Tls::Internal
