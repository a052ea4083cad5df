// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace SystemEditor {

/**
 * `host:port` of the first IIOP profile of a stringified object reference (`IOR:0123…`), empty
 * when the text is not a readable IOR. The online views use it to group calls and reachability by
 * the process that serves an object, without asking the ORB.
 */
QString iorEndpoint(const QString &ior);

} // namespace SystemEditor
