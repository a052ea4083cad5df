// SPDX-License-Identifier: MIT
#include "builtins.h"

namespace Runtime {

Properties exampleProfile(const std::string &typeName, const std::string &description)
{
    Properties p;
    p.set("implementation_id", typeName);
    p.set("type_name", typeName);
    p.set("description", description);
    p.set("version", "2.0.0");
    p.set("vendor", "AIST");
    p.set("category", "example");
    p.set("activity_type", "PERIODIC");
    p.set("kind", "DataFlowComponent");
    p.set("max_instance", "10");
    p.set("language", "C++");
    p.set("lang_type", "compile");
    return p;
}

std::vector<ComponentFactory> builtinFactories()
{
    std::vector<ComponentFactory> all;
    for (auto group : {consoleFactories, controlLoopFactories, sequenceFactories, serviceFactories,
                       configSampleFactories}) {
        for (ComponentFactory &factory : group())
            all.push_back(std::move(factory));
    }
    return all;
}

} // namespace Runtime
