// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <optional>
#include <string>

namespace Runtime {

/**
 * The argument of RTM::Manager::create_component parsed as OpenRTM-aist does:
 * `<id>[?k=v&k=v…]` where `<id>` is an implementation id (`ConsoleIn`) or
 * `RTC:vendor:category:impl_id:language:version`. `manager_address` and `manager_name` are taken
 * out wherever they stand; every other key becomes a component property.
 */
struct CreateRequest
{
    std::string implementationId;
    std::string vendor;   ///< From a full `RTC:` id; empty = any.
    std::string category; ///< From a full `RTC:` id; empty = any.
    std::string language; ///< From a full `RTC:` id; empty = any.
    std::string version;  ///< From a full `RTC:` id; empty = any.
    std::optional<std::string> managerAddress; ///< `host:port` of the slave to create on.
    std::optional<std::string> managerName;    ///< Name of the slave to create on.
    /// `version=`: the version of the installed component package whose module makes the
    /// component (see Manager::setPackageModuleDirs()); empty = the newest installed.
    std::string packageVersion;
    Properties properties;                     ///< Every other `k=v`.

    /// Parses @p text; on failure returns std::nullopt and sets @p error to a message naming the problem.
    static std::optional<CreateRequest> parse(const std::string &text, std::string *error);

    /// The request as text again, without the manager selection keys (to forward it to a slave).
    std::string toStringWithoutManager() const;
};

/// Splits `host:port`; false (with @p error) when malformed or the port is out of range.
bool parseHostPort(const std::string &text, std::string *host, int *port, std::string *error);

} // namespace Runtime
