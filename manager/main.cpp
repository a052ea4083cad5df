// SPDX-License-Identifier: MIT
// rtmanager: an OpenRTM-compatible manager process hosting the built-in components and the
// modules written against the component SDK (OpenRTM-aist's C++ API).
//   rtmanager [-f rtc.conf] [-i] [-o key:value]... [-p PORT] [-d] [-a]
// Without -f the configuration file is searched as OpenRTM-aist does (RTC_MANAGER_CONFIG, ./rtc.conf, …).
#include "builtins.h"
#include "forkserver.h"
#include "manager.h"
#include "managerconfig.h"
#include "packageinstallerservant.h"

#include <QCoreApplication>

#include <rtm/Manager.h>
#include <rtm/PeriodicECSharedComposite.h>

#include <cerrno>
#include <clocale>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <thread>
#include <unistd.h>

namespace {

const char *const usage = "usage: rtmanager [-f rtc.conf] [-i] [-o key:value]... [-p PORT] [-d] [-a]\n";

// `rtmanager --module-profile FILE`: loads the module, runs its init function and prints the
// component types it registered (ModuleProfiler's format). A manager lists its loadable modules
// through it, one process per module, as OpenRTM-aist's manager uses rtcprof.
int profileModule(const char *file)
{
    Runtime::Manager manager(Runtime::managerDefaults());
    RTC::Manager::attach(&manager);
    // Standard output carries the profile alone: what the module prints while it loads (a
    // Python module's prints among it) goes to standard error.
    std::cout.flush();
    const int output = dup(STDOUT_FILENO);
    dup2(STDERR_FILENO, STDOUT_FILENO);
    // A module that does not load is reported on stderr by the manager.
    const bool loaded = manager.loadModule(file, std::string(), nullptr);
    std::cout.flush();
    std::fflush(stdout);
    dup2(output, STDOUT_FILENO);
    close(output);
    if (!loaded)
        return 1;
    std::cout << Runtime::ModuleProfiler::format(manager.factoryProfiles()) << std::flush;
    return 0;
}

int runManager(int argc, char **argv)
{
    if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
        std::cout << "rtmanager " RTSTUDIO_VERSION "\n";
        return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "--help") == 0) {
        std::cout << usage
                  << "OpenRTM-aist's manager command line: -f names the configuration file (else it is searched\n"
                     "as OpenRTM-aist does; -i: a missing file is no error), -o sets one key, -p the port, -d makes\n"
                     "it a master, -a runs it without the manager servant. See rtmanager(1).\n";
        return 0;
    }
    Runtime::Properties config;
    std::string error;
    if (!Runtime::parseManagerArguments(argc, argv, &config, &error)) {
        std::cerr << "rtmanager: " << error << '\n' << usage;
        return 2;
    }

    // Signals are taken by one thread, which shuts the manager down cleanly.
    sigset_t stopSignals;
    sigemptyset(&stopSignals);
    sigaddset(&stopSignals, SIGTERM);
    sigaddset(&stopSignals, SIGINT);
    sigaddset(&stopSignals, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
    std::signal(SIGPIPE, SIG_IGN);

    Runtime::Manager manager(config);
    if (manager.isMaster())
        manager.startForkServer();
    for (Runtime::ComponentFactory &factory : Runtime::builtinFactories())
        manager.registerFactory(std::move(factory));
    // Modules are OpenRTM-aist modules: their init function gets the SDK's RTC::Manager.
    RTC::Manager *sdkManager = RTC::Manager::attach(&manager);
    // Like OpenRTM-aist's manager, every manager offers the composite component type.
    PeriodicECSharedCompositeInit(sdkManager);
    manager.setModuleProfileProgram(Runtime::ownExecutable());
    // The package installer runs Debian's tools and fetches over the network with Qt, which wants
    // its application object; the manager itself never runs Qt's event loop.
    QCoreApplication application(argc, argv);
    std::setlocale(LC_NUMERIC, "C");
    PortableServer::ServantBase_var installer = Runtime::PackageInstallerServant::create(manager, &error);
    if (!error.empty()) {
        std::cerr << "rtmanager: package store: " << error << std::endl;
        return 1;
    }
    if (!manager.start(&error)) {
        std::cerr << "rtmanager: " << error << std::endl;
        return 1;
    }
    if (installer.in()) {
        CORBA::Object_var reference = manager.activate(installer.in());
        manager.setPackageInstaller(reference);
    }
    // Preloads modules, then creates, connects and activates what rtc.conf names (precreate,
    // preconnect, preactivation), as OpenRTM-aist's manager does when it is activated.
    sdkManager->activateManager();

    // Launchers (and tests) wait for this line before talking to the manager.
    std::cout << "rtmanager ready on " << manager.address() << std::endl;
    std::thread([&manager, stopSignals] {
        int number = 0;
        sigwait(&stopSignals, &number);
        manager.shutdown();
    }).detach();
    manager.run();
    if (manager.restartRequested()) {
        // restart(): the same program with the same arguments, hence the same endpoint and setup.
        execv(Runtime::ownExecutable().c_str(), argv);
        std::cerr << "rtmanager: cannot restart: " << std::strerror(errno) << std::endl;
        return 1;
    }
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--module-profile") == 0)
        return profileModule(argv[2]);
    // Started by a master (descriptor 3 is its connection): starts its slaves, see ForkServer.
    if (argc >= 2 && std::strcmp(argv[1], "--fork-server") == 0)
        Runtime::ForkServer::serve(3, argc, argv, runManager);
    return runManager(argc, argv);
}
