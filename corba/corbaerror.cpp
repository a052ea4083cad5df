// SPDX-License-Identifier: MIT
#include "corbaerror.h"

namespace Corba {

Error::Error(Kind kind, QString message)
    : m_kind(kind)
    , m_message(std::move(message))
    , m_utf8(m_message.toUtf8())
{ }

QString Error::kindName(Kind kind)
{
    switch (kind) {
    case Kind::Transient:
        return QStringLiteral("transient");
    case Kind::CommFailure:
        return QStringLiteral("comm-failure");
    case Kind::ObjectNotExist:
        return QStringLiteral("object-not-exist");
    case Kind::Timeout:
        return QStringLiteral("timeout");
    case Kind::System:
        return QStringLiteral("system");
    case Kind::User:
        return QStringLiteral("user");
    case Kind::Refused:
        return QStringLiteral("refused");
    case Kind::NotFound:
        return QStringLiteral("not-found");
    case Kind::BadPath:
        return QStringLiteral("bad-path");
    case Kind::WrongType:
        return QStringLiteral("wrong-type");
    case Kind::Incompatible:
        return QStringLiteral("incompatible");
    }
    return QStringLiteral("unknown");
}

} // namespace Corba
