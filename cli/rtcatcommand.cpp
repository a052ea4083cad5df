// SPDX-License-Identifier: MIT
#include "rtcatcommand.h"

#include "corbaerror.h"
#include "managerproxy.h"
#include "rtjson.h"

namespace Cli {

using namespace Corba;

namespace {

void printProperties(const Properties &properties, const QString &indent, QTextStream &out)
{
    for (const auto &property : properties)
        out << indent << property.first << " = " << property.second << '\n';
}

void printField(const QString &label, const QString &value, QTextStream &out)
{
    out << "  " << QStringLiteral("%1").arg(label, -15) << value << '\n';
}

void printPort(const PortInfo &port, int detail, QTextStream &out)
{
    out << "  " << port.portType() << ": " << port.shortName() << '\n';
    for (const PortInterfaceInfo &interface : port.interfaces) {
        out << "    Interface  " << interface.instanceName << "  " << interface.typeName << "  "
            << (interface.provided ? "Provided" : "Required") << '\n';
    }
    if (detail >= 1)
        printProperties(port.properties, QStringLiteral("    "), out);
    for (const ConnectorInfo &connector : port.connectors) {
        QStringList others;
        for (const QString &name : connector.ports) {
            if (name != port.name)
                others.append(name);
        }
        out << "    Connected to  " << others.join(QStringLiteral(", ")) << "  (name "
            << connector.name << ", id " << connector.id << ")\n";
        if (detail >= 2)
            printProperties(connector.properties, QStringLiteral("      "), out);
    }
}

QString ecLine(int index, const ExecutionContextInfo &ec)
{
    return QStringLiteral("Execution context %1 (%2, handle %3): %4, %5, %6 Hz, component %7")
        .arg(index)
        .arg(ec.owned ? QStringLiteral("owned") : QStringLiteral("participating"))
        .arg(ec.handle)
        .arg(ec.running ? QStringLiteral("Running") : QStringLiteral("Stopped"), ec.kind)
        .arg(ec.rate)
        .arg(stateName(ec.state));
}

/// Where the component stands among composites; nothing for one that cannot say (no SDO
/// organizations), so that its profile still shows.
OrganizationInfo organizationsOf(const ComponentProxy &rtc)
{
    try {
        return rtc.organizations();
    } catch (const Error &) {
        return {};
    }
}

} // namespace

QString RtCatCommand::summary() const
{
    return QStringLiteral("show a component's profile, contexts, ports and connections");
}

QString RtCatCommand::usage() const
{
    return QStringLiteral(
        "Usage: rtctl cat [-l...] [--json] [--timeout MS] PATH[:PORT]...\n\n"
        "Shows a component (rtshell's rtcat): profile, execution contexts with the component's\n"
        "state in each, ports with interfaces and connections. With :PORT only that port. A\n"
        "manager path shows the manager's profile, components and loaded modules.\n"
        "  -l      also component and port properties; -ll also connector properties\n"
        "  --json  the component as one JSON object (array for several paths)\n");
}

QStringList RtCatCommand::flagNames() const
{
    return {QStringLiteral("-l"), QStringLiteral("--json")};
}

void RtCatCommand::printComponent(const ComponentProxy &rtc, const QString &port, int detail,
                                  Streams streams) const
{
    QTextStream &out = streams.out;
    const ComponentInfo info = rtc.profile();
    if (!port.isEmpty()) {
        printPort(rtc.port(port), detail, out);
        return;
    }
    const auto contexts = rtc.executionContexts();
    const QString state
        = contexts.empty() ? stateName(LifeCycleState::Unknown) : stateName(contexts.front().state);
    out << info.instanceName << ".rtc  " << state << '\n';
    printField(QStringLiteral("Category"), info.category, out);
    printField(QStringLiteral("Description"), info.description, out);
    printField(QStringLiteral("Instance name"), info.instanceName, out);
    printField(QStringLiteral("Type name"), info.typeName, out);
    printField(QStringLiteral("Vendor"), info.vendor, out);
    printField(QStringLiteral("Version"), info.version, out);
    // As rtshell's rtcat, composites and their members say so (plain components keep their lines).
    const OrganizationInfo organizations = organizationsOf(rtc);
    for (const QString &parent : organizations.parents)
        printField(QStringLiteral("Parent"), parent, out);
    if (organizations.composite)
        printField(QStringLiteral("Type"), organizations.parents.isEmpty() ? QStringLiteral("Composite")
                                                                          : QStringLiteral("Composite composite member"),
                   out);
    else if (!organizations.parents.isEmpty())
        printField(QStringLiteral("Type"), QStringLiteral("Monolithic composite member"), out);
    if (organizations.composite)
        printField(QStringLiteral("Members"), organizations.members.join(QStringLiteral(", ")), out);
    if (detail >= 1)
        printProperties(info.properties, QStringLiteral("  "), out);
    for (size_t i = 0; i < contexts.size(); ++i)
        out << "  " << ecLine(int(i), contexts[i]) << '\n';
    for (const PortInfo &p : rtc.ports())
        printPort(p, detail, out);
}

void RtCatCommand::printManager(const QString &ior, const QString &path, Streams streams) const
{
    const ManagerProxy manager(ior, path);
    streams.out << path << '\n';
    printProperties(manager.profile(), QStringLiteral("  "), streams.out);
    for (const ComponentInfo &component : manager.componentProfiles())
        streams.out << "  Component  " << component.instanceName << "  " << component.typeName
                    << '\n';
    for (const Properties &module : manager.loadedModules())
        streams.out << "  Loaded module  " << propertyValue(module, QStringLiteral("file_path"))
                    << '\n';
}

QJsonObject RtCatCommand::managerJson(const QString &ior, const QString &path) const
{
    const ManagerProxy manager(ior, path);
    QJsonArray components, loaded;
    for (const ComponentInfo &component : manager.componentProfiles())
        components.append(component.instanceName);
    for (const Properties &module : manager.loadedModules())
        loaded.append(propertiesToJson(module));
    return {{"path", path},
            {"profile", propertiesToJson(manager.profile())},
            {"components", components},
            {"loadedModules", loaded}};
}

QJsonObject RtCatCommand::componentJson(const ComponentProxy &rtc, const QString &port) const
{
    if (!port.isEmpty())
        return portToJson(rtc.port(port));
    ComponentInfo info = rtc.profile();
    info.ports = rtc.ports();
    QJsonObject object = componentToJson(info);
    QJsonArray contexts;
    for (const ExecutionContextInfo &ec : rtc.executionContexts())
        contexts.append(contextToJson(ec));
    object.insert("executionContexts", contexts);
    const OrganizationInfo organizations = organizationsOf(rtc);
    if (organizations.composite)
        object.insert("members", QJsonArray::fromStringList(organizations.members));
    if (!organizations.parents.isEmpty())
        object.insert("parents", QJsonArray::fromStringList(organizations.parents));
    object.insert("path", rtc.path());
    return object;
}

int RtCatCommand::execute(const RtOptions &options, Streams streams)
{
    if (options.positionals.isEmpty())
        return usageError(QStringLiteral("missing PATH"), streams);
    const bool json = options.has(QStringLiteral("--json"));
    QJsonArray objects;
    const int code = forEachPath(
        options.positionals, streams,
        [&](const QString &text) {
            const RtPath target = path(text);
            const NamingNode node = NamingBrowser::node(target);
            if (node.type == NodeType::Manager && json) {
                objects.append(managerJson(node.ior, node.path));
                return;
            }
            if (node.type == NodeType::Manager) {
                printManager(node.ior, node.path, streams);
                return;
            }
            const ComponentProxy rtc = component(target);
            if (json)
                objects.append(componentJson(rtc, target.port));
            else
                printComponent(rtc, target.port, options.count(QStringLiteral("-l")), streams);
        },
        name());
    if (json)
        streams.out << jsonText(objects.size() == 1 ? QJsonValue(objects.first())
                                                    : QJsonValue(objects));
    return code;
}

} // namespace Cli
