// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Corba {

/**
 * `host:port` of the first IIOP profile of a stringified object reference (`IOR:0123…`), empty
 * when the text is not a readable IOR. The online views group calls and reachability by it, and
 * reports name the process that serves an object with it, without asking the ORB.
 */
QString iorEndpoint(const QString &ior);

} // namespace Corba
