// SPDX-License-Identifier: MIT
#include "orb.h"

#include "corbacall.h"
#include "iorendpoint.h"
#include "referenceguard.h"
#include "rtpath.h"
#include "tlstransport.h"

#include <omniORB4/minorCode.h>
#include <omniORB4/omniInterceptors.h>
#include <returncode.h>

#include <QHash>
#include <QMutex>

#include <atomic>
#include <mutex>
#include <vector>

namespace Corba {

namespace {

std::atomic<int> s_callTimeout {Orb::defaultCallTimeout};
std::atomic<bool> s_initialised {false};
QMutex s_argumentsMutex;
QStringList s_arguments;
std::once_flag s_once;
CORBA::ORB_var s_orb;

thread_local int t_threadTimeout = 0;

// The default also bounds remote calls the ORB makes outside Internal::call (narrowing, locate
// requests). No separate connect timeout: omniORB would stretch a shorter per-call deadline to it,
// while without one connection set-up is bounded by the call's own deadline.
void applyDefaultTimeout(int milliseconds)
{
    omniORB::setClientCallTimeout(CORBA::ULong(milliseconds));
    omniORB::setClientConnectTimeout(0);
}

QMutex s_peersMutex;
QHash<QString, QString> s_peerIdentities;

// Remembers who each TLS server proved to be (its certificate's common name), by its address.
CORBA::Boolean recordPeer(omni::omniInterceptors::clientOpenConnection_T::info_T &info)
{
    QString address = QString::fromLatin1(info.peeraddress());
    const QLatin1String scheme("giop:ssl:");
    if (!address.startsWith(scheme))
        return true;
    address.remove(0, scheme.size());
    const char *identity = info.peeridentity();
    QMutexLocker locker(&s_peersMutex);
    s_peerIdentities.insert(address, identity ? QString::fromUtf8(identity) : QString());
    return true;
}

void createOrb()
{
    QStringList arguments {QStringLiteral("rtcorba")};
    {
        QMutexLocker locker(&s_argumentsMutex);
        arguments += s_arguments;
    }
    if (Tls::Transport::installed()) {
        for (const std::string &argument : Tls::orbArguments())
            arguments << QString::fromStdString(argument);
    }
    std::vector<QByteArray> storage;
    for (const QString &argument : std::as_const(arguments))
        storage.push_back(argument.toLocal8Bit());
    std::vector<char *> argv;
    for (QByteArray &bytes : storage)
        argv.push_back(bytes.data());
    argv.push_back(nullptr);
    int argc = int(argv.size()) - 1;
    // omniORB's defaults would print to stderr and retry forever; a tool wants quick, quiet
    // failure. Per-thread timeouts are off unless asked for (CallTimeoutScope relies on them).
    // giopMaxMsgSize: the profiles of a large system (every component's ports and connectors in
    // one reply) pass omniORB's 2 MiB default. verifyObjectExistsAndType 0: no LocateRequest before
    // the first call on each new reference (one round trip per reference made from an IOR); a
    // reference to a gone object still fails its first call with OBJECT_NOT_EXIST or TRANSIENT.
    const char *options[][2] = {{"traceLevel", "0"},
                                {"supportPerThreadTimeOut", "1"},
                                {"giopMaxMsgSize", "268435456"},
                                {"verifyObjectExistsAndType", "0"},
                                {nullptr, nullptr}};
    s_orb = CORBA::ORB_init(argc, argv.data(), "omniORB4", options);
    ReferenceGuard::install();
    if (Tls::Transport::installed())
        omniORB::getInterceptors()->clientOpenConnection.add(recordPeer);
    s_initialised = true;
    applyDefaultTimeout(s_callTimeout);
}

} // namespace

void Orb::setArguments(const QStringList &arguments)
{
    QMutexLocker locker(&s_argumentsMutex);
    s_arguments = arguments;
}

void Orb::setCallTimeout(int milliseconds)
{
    s_callTimeout = milliseconds > 0 ? milliseconds : defaultCallTimeout;
    if (s_initialised)
        applyDefaultTimeout(s_callTimeout);
}

int Orb::callTimeout()
{
    return t_threadTimeout > 0 ? t_threadTimeout : s_callTimeout.load();
}

ThreadCallTimeout::ThreadCallTimeout(int milliseconds)
    : m_previous(t_threadTimeout)
{
    t_threadTimeout = milliseconds > 0 ? milliseconds : m_previous;
}

ThreadCallTimeout::~ThreadCallTimeout()
{
    t_threadTimeout = m_previous;
}

bool Orb::isInitialised()
{
    return s_initialised;
}

bool Orb::setTls(const QString &certificateAuthorityFile, const QString &keyFile, const QString &keyFilePassword,
                 QString *error)
{
    if (s_initialised) {
        *error = QStringLiteral("TLS must be chosen before the first remote call");
        return false;
    }
    std::string reason;
    if (!Tls::Transport::install({certificateAuthorityFile.toStdString(), keyFile.toStdString(),
                                  keyFilePassword.toStdString()},
                                 &reason)) {
        *error = QString::fromStdString(reason);
        return false;
    }
    return true;
}

bool Orb::usesTls()
{
    return Tls::Transport::installed();
}

QString Orb::peerIdentity(const QString &hostPort)
{
    QMutexLocker locker(&s_peersMutex);
    return s_peerIdentities.value(hostPort);
}

namespace Internal {

CORBA::ORB_ptr orb()
{
    std::call_once(s_once, createOrb);
    return s_orb.in();
}

void ensureOrb()
{
    orb();
}

CallTimeoutScope::CallTimeoutScope()
{
    // A per-thread timeout overrides the process-wide one for this thread's calls only.
    omniORB::setClientThreadCallTimeout(CORBA::ULong(Orb::callTimeout()));
}

namespace {

QString systemExceptionText(const CORBA::SystemException &e)
{
    return QStringLiteral("CORBA::%1 (minor %2, %3)")
        .arg(QLatin1String(e._name()))
        .arg(e.minor())
        .arg(e.completed() == CORBA::COMPLETED_YES      ? QStringLiteral("completed")
                 : e.completed() == CORBA::COMPLETED_NO ? QStringLiteral("not completed")
                                                        : QStringLiteral("maybe completed"));
}

// Why the TLS handshake of this thread's call failed, when one did: the ORB itself only says the
// connection could not be made.
QString tlsFailure()
{
    const std::string reason = Tls::Transport::lastFailure();
    return reason.empty() ? QString() : QStringLiteral(": ") + QString::fromStdString(reason);
}

/// @p text, or its start and end around an ellipsis when it is longer than a message should quote.
QString elided(const QString &text)
{
    const qsizetype shown = 120;
    if (text.size() <= shown)
        return text;
    return text.left(shown / 2) + QStringLiteral("…") + text.right(shown / 2);
}

} // namespace

void rethrowAsError(const QString &target)
{
    using Kind = Error::Kind;
    const auto fail = [&target](Kind kind, const QString &reason) {
        return Error(kind, QStringLiteral("%1: %2").arg(target, reason));
    };
    try {
        throw;
    } catch (const CORBA::TIMEOUT &) {
        throw fail(Kind::Timeout, QStringLiteral("no reply within %1 ms").arg(Orb::callTimeout()));
    } catch (const CORBA::TRANSIENT &e) {
        // omniORB reports its own call timeouts as TRANSIENT with a dedicated minor code.
        if (e.minor() == omni::TRANSIENT_CallTimedout)
            throw fail(Kind::Timeout,
                       QStringLiteral("no reply within %1 ms").arg(Orb::callTimeout()));
        const QString why = e.minor() == omni::TRANSIENT_ConnectFailed
            ? QStringLiteral("cannot connect")
            : systemExceptionText(e);
        throw fail(Kind::Transient, QStringLiteral("unreachable (%1)%2").arg(why, tlsFailure()));
    } catch (const CORBA::COMM_FAILURE &e) {
        throw fail(Kind::CommFailure,
                   QStringLiteral("connection failed (%1)%2").arg(systemExceptionText(e), tlsFailure()));
    } catch (const CORBA::OBJECT_NOT_EXIST &) {
        throw fail(Kind::ObjectNotExist, QStringLiteral("object does not exist"));
    } catch (const CORBA::SystemException &e) {
        throw fail(Kind::System, systemExceptionText(e));
    } catch (const CORBA::UserException &e) {
        throw fail(Kind::User, QStringLiteral("exception %1").arg(QLatin1String(e._rep_id())));
    } catch (const CORBA::Exception &e) {
        throw fail(Kind::System, QStringLiteral("exception %1").arg(QLatin1String(e._name())));
    } catch (const std::exception &e) {
        throw fail(Kind::System, QString::fromLocal8Bit(e.what()));
    } catch (...) {
        // Falls through to the generic error below.
    }
    throw fail(Kind::System, QStringLiteral("unknown exception"));
}

Error withServingProcess(const Error &e, const QString &ior)
{
    const Error::Kind kind = e.kind();
    const QString endpoint = iorEndpoint(ior);
    if (endpoint.isEmpty()
        || (kind != Error::Kind::Timeout && kind != Error::Kind::Transient
            && kind != Error::Kind::CommFailure))
        return e;
    return Error(kind, QStringLiteral("%1 (its process at %2)").arg(e.message(), endpoint));
}

CORBA::Object_ptr toObject(const QString &reference, const QString &target)
{
    return call(target, [&] {
        try {
            const QString address = Orb::usesTls() ? corbalocOverTls(reference) : corbalocWithGiop12(reference);
            const unsigned long standIns = ReferenceGuard::standInsOnThisThread();
            CORBA::Object_var object = orb()->string_to_object(address.toLatin1().constData());
            if (ReferenceGuard::standInsOnThisThread() != standIns) {
                throw Error(Error::Kind::BadPath, QStringLiteral("%1: not an object reference (its profile does not "
                                                                 "decode): %2").arg(target, elided(reference)));
            }
            return object._retn();
        } catch (const CORBA::SystemException &e) {
            // Turning text into a reference makes no remote call: BAD_PARAM or MARSHAL means the text.
            if (!CORBA::BAD_PARAM::_downcast(&e) && !CORBA::MARSHAL::_downcast(&e))
                throw;
            throw Error(Error::Kind::BadPath,
                        QStringLiteral("%1: not an object reference: %2").arg(target, elided(reference)));
        }
    });
}

QString toIor(CORBA::Object_ptr object)
{
    if (CORBA::is_nil(object))
        return QString();
    CORBA::String_var text = orb()->object_to_string(object);
    return QString::fromLatin1(text.in());
}

QString toQString(const char *text)
{
    return text ? QString::fromUtf8(text) : QString();
}

QString anyToString(const CORBA::Any &value)
{
    const char *text = nullptr;
    if (value >>= text)
        return toQString(text);
    CORBA::Long l;
    if (value >>= l)
        return QString::number(l);
    CORBA::ULong ul;
    if (value >>= ul)
        return QString::number(ul);
    CORBA::Short s;
    if (value >>= s)
        return QString::number(s);
    CORBA::Double d;
    if (value >>= d)
        return QString::number(d);
    CORBA::Float f;
    if (value >>= f)
        return QString::number(double(f));
    CORBA::Boolean b;
    if (value >>= CORBA::Any::to_boolean(b))
        return b ? QStringLiteral("true") : QStringLiteral("false");
    return QString();
}

Properties fromNVList(const SDOPackage::NVList &list)
{
    Properties properties;
    properties.reserve(int(list.length()));
    for (CORBA::ULong i = 0; i < list.length(); ++i)
        properties.append({toQString(list[i].name.in()), anyToString(list[i].value)});
    return properties;
}

SDOPackage::NVList toNVList(const Properties &properties)
{
    SDOPackage::NVList list;
    list.length(CORBA::ULong(properties.size()));
    for (int i = 0; i < properties.size(); ++i) {
        list[CORBA::ULong(i)].name = properties.at(i).first.toUtf8().constData();
        list[CORBA::ULong(i)].value <<= properties.at(i).second.toUtf8().constData();
    }
    return list;
}

void checkReturnCode(int code, const QString &target, const QString &operation)
{
    if (code == 0)
        return;
    const char *idlName = RtStudio::returnCodeName(code);
    const QString name = idlName ? QLatin1String(idlName) : QString::number(code);
    throw Error(Error::Kind::Refused,
                QStringLiteral("%1: %2 returned %3").arg(target, operation, name));
}

} // namespace Internal
} // namespace Corba
