// SPDX-License-Identifier: MIT
#pragma once

#include "componentfactory.h"
#include "rtobject.h"

namespace Runtime {

/// Factory of a built-in type @p T with OpenRTM-aist's example profile.
template <typename T>
ComponentFactory builtinFactory(const std::string &type, const std::string &description)
{
    return {exampleProfile(type, description),
            [](PortableServer::POA_ptr poa) -> RtObject * { return new T(poa); }, {}};
}

} // namespace Runtime
