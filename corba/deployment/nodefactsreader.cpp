// SPDX-License-Identifier: MIT
#include "nodefactsreader.h"

#include "componentmapper.h"
#include "concurrent.h"
#include "corbaerror.h"
#include "managerproxy.h"

namespace Deploy {

namespace {

NodeFactsReading readOne(const QString &address)
{
    NodeFactsReading reading;
    reading.facts.name = address;
    try {
        const Corba::ManagerProxy manager(ComponentMapper::resolveManager(address), address);
        const Corba::Properties profile = manager.profile();
        const Corba::Properties configuration = manager.configuration();
        std::optional<QList<Planner::FactProperties>> modules;
        try {
            // Types it creates already (factories: built in or loaded) and types it can load.
            const std::vector<Corba::Properties> factories = manager.factoryProfiles();
            const std::vector<Corba::Properties> loadable = manager.loadableModules();
            modules = QList<Planner::FactProperties>(factories.cbegin(), factories.cend());
            modules->append(QList<Planner::FactProperties>(loadable.cbegin(), loadable.cend()));
        } catch (const Corba::Error &) {
            // What it can load stays unknown: only installs can bring types there.
        }
        reading.facts = Planner::NodeFacts::fromManager(address, profile, configuration, modules);
    } catch (const Corba::Error &e) {
        reading.error = e.message();
    }
    return reading;
}

} // namespace

QList<NodeFactsReading> readNodeFacts(const QStringList &addresses)
{
    QList<NodeFactsReading> readings(addresses.size());
    Corba::forEachConcurrently(std::size_t(addresses.size()), [&](std::size_t i) {
        readings[qsizetype(i)] = readOne(addresses.at(qsizetype(i)));
    });
    return readings;
}

} // namespace Deploy
