// SPDX-License-Identifier: MIT
// runsystem NAMESERVER MANAGER SYSTEM: restores a saved RT system onto live components found under
// the name server, creating the missing ones through the manager, starts it, and prints the
// state each component is in. Exit 0 when the system runs.
//
// What it shows of RT Studio's client library (find_package(RTStudioClient), RTStudio::Client):
// reading an RTS profile, planning and restoring a system, starting it, and component proxies.
#include <componentproxy.h>
#include <corbaerror.h>
#include <profileio.h>
#include <restoreplan.h>
#include <restorer.h>
#include <sequencerunner.h>

#include <QCoreApplication>
#include <QTextStream>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QTextStream out(stdout);
    QTextStream err(stderr);
    const QStringList arguments = app.arguments();
    if (arguments.size() != 4) {
        err << "usage: runsystem NAMESERVER MANAGER SYSTEM\n"
               "  e.g. runsystem 127.0.0.1:2809 corbaloc::127.0.0.1:2810 ConsoleInOut.xml\n";
        return 2;
    }

    // The system file, XML or YAML.
    Profile::Diagnostics problems;
    const std::optional<Profile::LoadedProfile> loaded = Profile::loadProfileFile(arguments[3], &problems);
    if (!loaded || !loaded->rts) {
        for (const Profile::Diagnostic &problem : problems)
            err << problem.toString() << '\n';
        err << arguments[3] << ": not an RTS profile\n";
        return 1;
    }
    const Profile::RtsProfile &system = *loaded->rts;

    // Where it goes: components are looked up under the name server; missing ones are created.
    Deploy::TargetOptions target;
    target.nameServers = {arguments[1]};
    target.manager = arguments[2];
    target.create = true;
    const Deploy::RestorePlan plan = Deploy::planRestore(system, target);
    out << plan.toText() << '\n';

    // Restore (transactional: a failure undoes what this run created and connected), then start.
    const Deploy::DeployReport restored = Deploy::restoreSystem(system, plan, target);
    out << restored.toText() << '\n';
    if (!restored.ok)
        return 1;
    const Deploy::DeployReport started = Deploy::startSystem(system, Deploy::planRestore(system, target));
    out << started.toText() << '\n';
    if (!started.ok)
        return 1;

    // Each component as it is now, through its proxy.
    for (const Deploy::ComponentMapping &component : Deploy::planRestore(system, target).components) {
        try {
            const Corba::ComponentProxy proxy(component.ior, component.path);
            out << component.instanceName << ' ' << Corba::stateName(proxy.state()) << '\n';
        } catch (const Corba::Error &e) {
            out << component.instanceName << ' ' << e.message() << '\n';
        }
    }
    return 0;
}
