// SPDX-License-Identifier: MIT
// rtstudio_livepeer: a small OpenRTM-compatible process for live tests of CORBA clients.
//
//   rtstudio_livepeer --naming PORT --port PORT [--host NAME] [--zombies]
//   [Type[?instance_name=N]]...
//
// Listens on 127.0.0.1:PORT (manager at corbaloc:iiop:127.0.0.1:PORT/manager), registers
// NAME.host_cxt/manager.mgr and each created component as NAME.host_cxt/<instance>.rtc in the
// name server at 127.0.0.1:NAMING, prints "ready" and serves until Manager::shutdown().
// --zombies also binds Ghost0.rtc (an unreachable object) and Stranger0.rtc (not an RTObject).

#include "livesystempeer.h"

#include <omniORB4/omniURI.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Options
{
    std::string host = "livehost";
    std::string namingPort;
    std::string port;
    bool zombies = false;
    std::vector<std::string> components;
};

bool parse(int argc, char **argv, Options &options)
{
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--host" && hasValue)
            options.host = argv[++i];
        else if (arg == "--naming" && hasValue)
            options.namingPort = argv[++i];
        else if (arg == "--port" && hasValue)
            options.port = argv[++i];
        else if (arg == "--zombies")
            options.zombies = true;
        else if (arg.rfind("--", 0) == 0)
            return false;
        else
            options.components.push_back(arg);
    }
    return !options.namingPort.empty() && !options.port.empty();
}

void bindZombies(LivePeer::Context &context)
{
    CORBA::Object_var unreachable
        = context.orb->string_to_object("corbaloc:iiop:127.0.0.1:1/Ghost");
    context.bind("Ghost0", "rtc", unreachable.in());
    context.bind("Stranger0", "rtc", context.naming.in());
}

} // namespace

int main(int argc, char **argv)
{
    Options options;
    if (!parse(argc, argv, options)) {
        std::fprintf(stderr,
                     "usage: rtstudio_livepeer --naming PORT --port PORT [--host NAME] "
                     "[--zombies] [Type[?instance_name=N]]...\n");
        return 2;
    }
    const std::string endpoint = "giop:tcp:127.0.0.1:" + options.port;
    const char *orbOptions[][2] = {{"endPoint", endpoint.c_str()}, {nullptr, nullptr}};
    int orbArgc = 0;
    LivePeer::Context context;
    context.host = options.host;
    context.orb = CORBA::ORB_init(orbArgc, nullptr, "omniORB4", orbOptions);
    CORBA::Object_var rootPoa = context.orb->resolve_initial_references("RootPOA");
    context.poa = PortableServer::POA::_narrow(rootPoa.in());
    const std::string namingAddress
        = "corbaloc:iiop:127.0.0.1:" + options.namingPort + "/NameService";
    CORBA::Object_var naming = context.orb->string_to_object(namingAddress.c_str());
    context.naming = CosNaming::NamingContext::_narrow(naming.in());

    // The manager lives under the fixed key "manager" so that corbaloc addresses reach it.
    // The POA holds the manager while it is active; destroying the ORB at exit releases it. The
    // INS POA's references are let go before that, or omniORB keeps the POA past destroy().
    auto *manager = new LivePeer::Manager(context);
    const PortableServer::ServantBase_var managerServant = manager;
    context.manager = manager;
    CORBA::Object_var managerRef;
    {
        CORBA::Object_var insObject = context.orb->resolve_initial_references("omniINSPOA");
        PortableServer::POA_var insPoa = PortableServer::POA::_narrow(insObject.in());
        PortableServer::ObjectId_var managerId = PortableServer::string_to_ObjectId("manager");
        insPoa->activate_object_with_id(managerId.in(), manager);
        managerRef = insPoa->id_to_reference(managerId.in());
        PortableServer::POAManager_var insManager = insPoa->the_POAManager();
        insManager->activate();
    }
    PortableServer::POAManager_var rootManager = context.poa->the_POAManager();
    rootManager->activate();

    context.bind("manager", "mgr", managerRef.in());
    for (const std::string &argument : options.components) {
        if (!manager->createFromArgument(argument)) {
            std::fprintf(stderr, "rtstudio_livepeer: cannot create '%s'\n", argument.c_str());
            return 1;
        }
    }
    if (options.zombies)
        bindZombies(context);
    std::printf("ready\n");
    std::fflush(stdout);
    // run() may report BAD_INV_ORDER when the shutdown thread has already torn the ORB down.
    try {
        context.orb->run();
    } catch (const CORBA::BAD_INV_ORDER &) { }
    if (context.shutdownThread.joinable())
        context.shutdownThread.join();
    context.orb->destroy();
    return 0;
}
