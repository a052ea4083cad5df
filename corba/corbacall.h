// SPDX-License-Identifier: MIT
#pragma once

// Internal to the rtcorba library: the omniORB side of the API. Nothing outside corba/ includes it.

#include "corbaerror.h"
#include "corbatypes.h"

#include <SDOPackage.hh>

#include <QString>

#include <utility>

namespace Corba::Internal {

/// The process's ORB, created on first use.
CORBA::ORB_ptr orb();

/// Creates the ORB on first use; the configured timeouts are in force from then on.
void ensureOrb();

/**
 * Puts the calling thread's call timeout (Orb::callTimeout()) in force for the remote calls made
 * while it lives, in any thread: omniORB keeps per-thread timeouts only for omni_threads, so a
 * thread it did not create (QThread, std::thread) gets a stand-in omni_thread for the duration.
 */
class CallTimeoutScope
{
public:
    CallTimeoutScope();
    CallTimeoutScope(const CallTimeoutScope &) = delete;
    CallTimeoutScope &operator=(const CallTimeoutScope &) = delete;

private:
    omni_thread::ensure_self m_self;
};

/// Translates the exception being handled into an Error naming `target`; call only in a catch.
[[noreturn]] void rethrowAsError(const QString &target);

/**
 * The translation boundary: runs `f` (which makes remote calls) with the call timeout in force and
 * turns any CORBA exception into a Corba::Error about `target`.
 */
template<typename F> auto call(const QString &target, F &&f) -> decltype(f())
{
    ensureOrb();
    const CallTimeoutScope timeout;
    try {
        return f();
    } catch (const Error &) {
        throw;
    } catch (...) {
        rethrowAsError(target);
    }
}

/**
 * The error `e` about an object whose reference is `ior`: when it means that the object's process
 * does not answer or cannot be reached, its message also names that process (`host:port`).
 */
Error withServingProcess(const Error &e, const QString &ior);

/// call() on the object with reference `ior` (see withServingProcess()).
template<typename F> auto callServed(const QString &target, const QString &ior, F &&f) -> decltype(f())
{
    try {
        return call(target, std::forward<F>(f));
    } catch (const Error &e) {
        throw withServingProcess(e, ior);
    }
}

/// string_to_object for an IOR, corbaloc (GIOP 1.2: corbalocWithGiop12) or corbaname; BadPath when
/// the text is not a reference.
CORBA::Object_ptr toObject(const QString &reference, const QString &target);
QString toIor(CORBA::Object_ptr object);

QString toQString(const char *text);
/// The text of an `any` holding a string or number, as OpenRTM tools print it.
QString anyToString(const CORBA::Any &value);
Properties fromNVList(const SDOPackage::NVList &list);
SDOPackage::NVList toNVList(const Properties &properties);

/// Throws Refused when a call reported RTC::ReturnCode_t other than RTC_OK (given as its number).
void checkReturnCode(int code, const QString &target, const QString &operation);

} // namespace Corba::Internal
