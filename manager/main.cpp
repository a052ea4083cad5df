// SPDX-License-Identifier: MIT
// rtmanager: an OpenRTM-compatible manager process hosting the built-in components.
//   rtmanager [-f rtc.conf] [-o key=value]... [-p PORT] [-d]
// -d makes it the master (manager.is_master=YES); -p sets the listening port.
#include "builtins.h"
#include "manager.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace {

Runtime::Properties defaults()
{
    Runtime::Properties p;
    p.set("corba.nameservers", "localhost");
    p.set("corba.master_manager", "localhost:2810");
    p.set("naming.enable", "YES");
    p.set("naming.formats", "%h.host_cxt/%n.rtc");
    p.set("manager.naming_formats", "%h.host_cxt/%n.mgr");
    p.set("manager.is_master", "NO");
    p.set("manager.corba_servant", "YES");
    p.set("manager.name", "manager");
    p.set("manager.instance_name", "manager");
    p.set("exec_cxt.periodic.type", "PeriodicExecutionContext");
    p.set("exec_cxt.periodic.rate", "1000");
    p.set("exec_cxt.transition_timeout", "0.5");
    return p;
}

int usage(const std::string &message)
{
    std::cerr << "rtmanager: " << message << "\nusage: rtmanager [-f rtc.conf] [-o key=value]... [-p PORT] [-d]\n";
    return 2;
}

bool readConf(const std::string &file, Runtime::Properties *config)
{
    std::ifstream in(file);
    if (!in)
        return false;
    std::stringstream text;
    text << in.rdbuf();
    std::vector<std::string> errors;
    config->merge(Runtime::Properties::parseConf(text.str(), &errors));
    for (const std::string &error : errors)
        std::cerr << file << ':' << error << std::endl;
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    Runtime::Properties config = defaults();
    Runtime::Properties overrides;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "-f" && hasValue) {
            if (!readConf(argv[++i], &config))
                return usage(std::string("cannot read ") + argv[i]);
        } else if (arg == "-o" && hasValue) {
            const std::string pair = argv[++i];
            const size_t eq = pair.find_first_of("=:");
            if (eq == std::string::npos || eq == 0)
                return usage("-o expects key=value, got '" + pair + "'");
            overrides.set(Runtime::trimmed(pair.substr(0, eq)), Runtime::trimmed(pair.substr(eq + 1)));
        } else if (arg == "-p" && hasValue) {
            overrides.set("corba.endpoints", std::string("127.0.0.1:") + argv[++i]);
        } else if (arg == "-d") {
            overrides.set("manager.is_master", "YES");
        } else if (arg.compare(0, 4, "-ORB") == 0 && hasValue) {
            ++i; // ORB options are derived from the configuration
        } else {
            return usage("unknown argument '" + arg + "'");
        }
    }
    config.merge(overrides);

    // Signals are taken by one thread, which shuts the manager down cleanly.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGTERM);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::signal(SIGPIPE, SIG_IGN);

    Runtime::Manager manager(config);
    for (Runtime::ComponentFactory &factory : Runtime::builtinFactories())
        manager.registerFactory(std::move(factory));
    std::string error;
    if (!manager.start(&error)) {
        std::cerr << "rtmanager: " << error << std::endl;
        return 1;
    }
    for (const std::string &module : Runtime::split(config.value("manager.preload.modules"), ',')) {
        const size_t colon = module.find(':');
        manager.loadModule(module.substr(0, colon), colon == std::string::npos ? "" : module.substr(colon + 1),
                           nullptr);
    }
    for (const std::string &request : Runtime::split(config.value("manager.components.precreate"), ','))
        CORBA::release(manager.createComponent(request, nullptr));

    // Launchers (and tests) wait for this line before talking to the manager.
    std::cout << "rtmanager ready on " << manager.address() << std::endl;
    std::thread([&manager, signals] {
        int number = 0;
        sigwait(&signals, &number);
        manager.shutdown();
    }).detach();
    manager.run();
    if (manager.restartRequested()) {
        // restart(): the same program with the same arguments, hence the same endpoint and setup.
        execv("/proc/self/exe", argv);
        std::cerr << "rtmanager: cannot restart: " << std::strerror(errno) << std::endl;
        return 1;
    }
    return 0;
}
