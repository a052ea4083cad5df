// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

#include <exception>

namespace Corba {

/**
 * The one error type the CORBA client library throws. Every remote call goes through a single
 * translation boundary that turns omniORB's exceptions into an Error whose kind says what went
 * wrong and whose message names the object or path involved.
 */
class Error : public std::exception
{
public:
    enum class Kind {
        Transient, ///< peer unreachable (connection refused, no route, not yet started)
        CommFailure, ///< connection broke during the call
        ObjectNotExist, ///< the peer answered: no such object (stale reference)
        Timeout, ///< no reply within the call timeout
        System, ///< any other CORBA system exception
        User, ///< a user exception declared by the IDL
        Refused, ///< the call returned a failure code (RTC::ReturnCode_t, false)
        NotFound, ///< a name, port, set or parameter that does not exist
        BadPath, ///< a path or address that cannot be parsed
        WrongType, ///< the object is not of the expected interface
        Incompatible ///< ports that cannot be connected (rtcon checks)
    };

    Error(Kind kind, QString message);

    Kind kind() const { return m_kind; }
    /// Human-readable text: "<object or path>: <reason>".
    QString message() const { return m_message; }
    const char *what() const noexcept override { return m_utf8.constData(); }

    /// Stable lower-case name of a kind ("timeout", "transient", ...), for scripts and JSON.
    static QString kindName(Kind kind);

private:
    Kind m_kind;
    QString m_message;
    QByteArray m_utf8;
};

} // namespace Corba
