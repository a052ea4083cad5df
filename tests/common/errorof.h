// SPDX-License-Identifier: MIT
#pragma once

#include "corbaerror.h"

#include <QString>

#include <functional>

namespace LiveTest {

/// The kind of the Corba::Error @p action throws; Kind(-1) when it throws none.
inline Corba::Error::Kind kindOf(const std::function<void()> &action)
{
    try {
        action();
    } catch (const Corba::Error &e) {
        return e.kind();
    }
    return Corba::Error::Kind(-1);
}

/// The message of the Corba::Error @p action throws; empty when it throws none.
inline QString messageOf(const std::function<void()> &action)
{
    try {
        action();
    } catch (const Corba::Error &e) {
        return e.message();
    }
    return QString();
}

} // namespace LiveTest
