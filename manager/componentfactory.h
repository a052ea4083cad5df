// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <omniORB4/CORBA.h>

#include <functional>
#include <string>

namespace Runtime {

class RtObject;

/**
 * How a manager creates one component type: the type's profile (`implementation_id`, `type_name`,
 * `vendor`, `category`, `version`, `language`, `description`, `conf.default.*`, …) and a function
 * making a new, not yet initialized servant.
 */
struct ComponentFactory
{
    Properties profile;
    std::function<RtObject *(PortableServer::POA_ptr poa)> create;
    std::string modulePath; ///< Empty for built-in types; the module file for loaded ones.

    std::string implementationId() const { return profile.value("implementation_id"); }
};

/// Profile of an example type with OpenRTM-aist's usual fields filled in.
Properties exampleProfile(const std::string &typeName, const std::string &description);

} // namespace Runtime
