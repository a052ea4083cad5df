// SPDX-License-Identifier: MIT
#pragma once

#include <QStringList>

namespace Corba {

/**
 * Process-wide settings of the one ORB the client library uses. The ORB is created on first use
 * (thread-safe, exactly once); every proxy call in any thread then uses it. Arguments given after
 * the ORB exists have no effect.
 *
 * Every remote call carries its own timeout (connection set-up included): the calling thread's
 * ThreadCallTimeout if one is in force, else the process default set here.
 */
class Orb
{
public:
    /// Extra ORB_init options (e.g. `-ORBendPoint giop:tcp:127.0.0.1:0`), before first use.
    static void setArguments(const QStringList &arguments);
    /// The default timeout in milliseconds of every remote call (default 3000); <= 0 restores it.
    static void setCallTimeout(int milliseconds);
    /// The timeout that applies to a call made now by the calling thread.
    static int callTimeout();
    /// True once the ORB has been created.
    static bool isInitialised();
    /**
     * TLS for every connection, before first use, with OpenRTM-aist's corba.ssl.* meanings: the
     * authority whose certificates are trusted, this user's private key and certificate in one PEM
     * file (none: the servers, which require one, refuse the connection) and the key's password.
     * Addresses `host:port` and `corbaloc:iiop:` are then reached over TLS (`corbaloc:ssliop:`).
     * False with the file and the reason in @p error when the files are not usable.
     */
    static bool setTls(const QString &certificateAuthorityFile, const QString &keyFile,
                       const QString &keyFilePassword, QString *error);
    /// True once setTls() succeeded.
    static bool usesTls();
    /**
     * Who the TLS server at @p hostPort (numeric, as in object references) proved to be when this
     * process connected to it: its certificate's common name; empty before a connection or without TLS.
     */
    static QString peerIdentity(const QString &hostPort);

    static constexpr int defaultCallTimeout = 3000;
};

/**
 * Overrides the call timeout for the calling thread while it exists (scopes nest; the innermost
 * wins), e.g. a poller that must give up quickly while other threads keep the default. Calls made
 * by other threads are unaffected.
 */
class ThreadCallTimeout
{
public:
    explicit ThreadCallTimeout(int milliseconds);
    ~ThreadCallTimeout();
    ThreadCallTimeout(const ThreadCallTimeout &) = delete;
    ThreadCallTimeout &operator=(const ThreadCallTimeout &) = delete;

private:
    int m_previous;
};

} // namespace Corba
