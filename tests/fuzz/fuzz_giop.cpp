// SPDX-License-Identifier: MIT
// The network surface: GIOP messages from a peer, through omniORB's request path, into the servants a
// manager serves (RTM::Manager with RTStudio::Manager's operations, a component's RTObject and SDO
// interfaces, its execution context, its configuration, its ports, the InPortCdr of a push connection,
// the OutPortCdr of a pull connection and the manager's package installer), in this process over
// loopback TCP.
//
// Input: byte 0 chooses the object (bits 0-2) or, with bit 7 set, sends the rest as it is on a
// connection of its own (any GIOP message, or none); byte 1 chooses an operation of the object's
// interface; bit 0 of byte 2 chooses the byte order; the rest is the request's body (the operation's
// arguments as CDR). A request is framed correctly, so that every input reaches the servant's
// unmarshalling. Left out: operations that end the process or the component (shutdown, restart, fork,
// exit, finalize) or start processes (slaves: manager.slaves.max is 0), and install_url, which
// would reach the hosts its inputs name (install_package takes the same package files pushed).
#include "manager.h"
#include "packageinstallerservant.h"
#include "rtobject.h"

#include <RTC.hh>
#include <RTStudioManager.hh>

#include <QCoreApplication>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <tuple>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <string>
#include <vector>

namespace {

constexpr int ReplyTimeoutMs = 30000;
constexpr int RawAnswerMs = 50;

class FuzzTarget : public Runtime::RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        addInPort<RTC::TimedLong>("in");
        addOutPort<RTC::TimedLong>("out");
        return RTC::RTC_OK;
    }
};

// Operation names from OpenRTM-aist's IDL, per interface served.
const std::vector<const char *> managerOperations {
    "load_module", "unload_module", "get_loadable_modules", "get_loaded_modules", "get_factory_profiles",
    "create_component", "delete_component", "get_components", "get_components_by_name", "get_profile",
    "get_configuration", "set_configuration", "is_master", "get_master_managers", "add_master_manager",
    "remove_master_manager", "get_slave_managers", "add_slave_manager", "remove_slave_manager", "get_service",
    "_is_a", "_non_existent", "_interface", "create_components", "get_package_installer"};
const std::vector<const char *> componentOperations {
    "initialize", "is_alive", "attach_context", "detach_context", "get_context", "get_owned_contexts",
    "get_participating_contexts", "get_context_handle", "on_initialize", "on_finalize", "on_startup", "on_shutdown",
    "on_activated", "on_deactivated", "on_aborting", "on_error", "on_reset", "on_execute", "on_state_update",
    "on_rate_changed", "get_component_profile", "get_ports", "get_sdo_id", "get_sdo_type", "get_device_profile",
    "get_service_profiles", "get_service_profile", "get_sdo_service", "get_configuration", "get_monitoring",
    "get_organizations", "get_status_list", "get_status", "_is_a", "_non_existent"};
const std::vector<const char *> contextOperations {
    "is_running", "start", "stop", "get_rate", "set_rate", "add_component", "remove_component",
    "activate_component", "deactivate_component", "reset_component", "get_component_state", "get_kind",
    "get_profile", "_is_a"};
const std::vector<const char *> configurationOperations {
    "set_device_profile", "add_service_profile", "add_organization", "remove_service_profile",
    "remove_organization", "get_configuration_parameters", "get_configuration_parameter_values",
    "get_configuration_parameter_value", "set_configuration_parameter", "get_configuration_sets",
    "get_configuration_set", "set_configuration_set_values", "get_active_configuration_set",
    "add_configuration_set", "remove_configuration_set", "activate_configuration_set"};
const std::vector<const char *> portOperations {
    "get_port_profile", "get_connector_profiles", "get_connector_profile", "connect", "disconnect",
    "disconnect_all", "notify_connect", "notify_disconnect"};
const std::vector<const char *> inPortCdrOperations {"put", "_is_a", "_non_existent"};
const std::vector<const char *> outPortCdrOperations {"get", "_is_a", "_non_existent"};
const std::vector<const char *> installerOperations {"install_package", "uninstall", "list_installed", "_is_a",
                                                     "_non_existent"};

struct Target
{
    std::string key;
    const std::vector<const char *> *operations;
};

std::vector<Target> s_targets;
// The component's reference and how many ports it lists: what a request makes it do again (its
// onInitialize() on a remote on_initialize()) must not make its ports pile up.
RTC::RTObject_var s_component;
CORBA::ULong s_portCount = 0;
unsigned s_inputs = 0;
// The latest requests, printed when the server stops answering: the servants keep state from one
// input to the next, so the input that hangs is seldom the one that caused it.
std::vector<std::string> s_recent;

void remember(const std::string &request)
{
    if (s_recent.size() == 32)
        s_recent.erase(s_recent.begin());
    s_recent.push_back(request);
}
int s_port = 0;
int s_connection = -1;
uint32_t s_requestId = 0;

// A CDR encapsulation read from @p at: its first octet says the byte order; alignment counts from there.
struct Encapsulation
{
    const std::vector<uint8_t> &bytes;
    size_t base;
    size_t at;
    bool little;

    Encapsulation(const std::vector<uint8_t> &data, size_t start)
        : bytes(data), base(start), at(start + 1), little(data.at(start) == 1)
    { }
    uint32_t number(size_t size)
    {
        at = base + (at - base + size - 1) / size * size;
        uint32_t value = 0;
        for (size_t i = 0; i < size; ++i)
            value |= uint32_t(bytes.at(at + i)) << (little ? 8 * i : 8 * (size - 1 - i));
        at += size;
        return value;
    }
    /// Skips a sequence of octets (a string too) and gives where its data starts.
    size_t skipOctets()
    {
        const size_t length = number(4);
        const size_t start = at;
        at += length;
        return start;
    }
};

// The object key of the first profile (IIOP in every reference omniORB makes) of a stringified reference.
std::string objectKey(const std::string &ior)
{
    std::vector<uint8_t> bytes;
    for (size_t i = 4; i + 1 < ior.size(); i += 2)
        bytes.push_back(uint8_t(std::stoul(ior.substr(i, 2), nullptr, 16)));
    Encapsulation reference(bytes, 0);
    reference.skipOctets(); // repository id
    reference.number(4);    // profile count
    reference.number(4);    // profile tag
    reference.number(4);    // profile length
    Encapsulation profile(bytes, reference.at);
    profile.at += 2; // IIOP version
    profile.skipOctets(); // host
    profile.number(2);    // port
    const size_t keyLength = profile.number(4);
    return std::string(bytes.begin() + long(profile.at), bytes.begin() + long(profile.at + keyLength));
}

void append(std::vector<uint8_t> &out, const void *data, size_t size)
{
    const auto *bytes = static_cast<const uint8_t *>(data);
    out.insert(out.end(), bytes, bytes + size);
}

void appendULong(std::vector<uint8_t> &out, uint32_t value, bool little)
{
    while ((out.size() - 12) % 4)
        out.push_back(0);
    for (int i = 0; i < 4; ++i)
        out.push_back(uint8_t(value >> (little ? 8 * i : 8 * (3 - i))));
}

// Whether @p fd is ready for @p events (or was closed) within @p timeoutMs. libFuzzer's timer signal
// (-timeout) interrupts poll() and connect() without restarting them: the wait goes on for the time
// that is left.
bool waitFor(int fd, short events, int timeoutMs)
{
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs);
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline
                                                                                - std::chrono::steady_clock::now());
        pollfd ready {fd, events, 0};
        const int result = poll(&ready, 1, int(std::max<long>(0, long(left.count()))));
        if (result > 0)
            return true;
        if (result == 0 || errno != EINTR)
            return false;
    }
}

bool waitReadable(int fd, int timeoutMs)
{
    return waitFor(fd, POLLIN, timeoutMs);
}

// Connected (true), or the connection failed with errno set. An interrupted connect() goes on in
// the background; its outcome is the socket's error once it is writable.
bool connectTo(int fd, const sockaddr_in &address)
{
    if (connect(fd, reinterpret_cast<const sockaddr *>(&address), sizeof address) == 0)
        return true;
    if (errno != EINTR)
        return false;
    if (!waitFor(fd, POLLOUT, ReplyTimeoutMs)) {
        errno = ETIMEDOUT;
        return false;
    }
    int error = 0;
    socklen_t length = sizeof error;
    if (getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length) != 0)
        return false;
    errno = error;
    return error == 0;
}

int connectToOrb()
{
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(s_port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd < 0 || !connectTo(fd, address)) {
        std::fprintf(stderr, "fuzz_giop: cannot connect to the ORB: %s\n", std::strerror(errno));
        std::abort();
    }
    return fd;
}

void sendAll(int fd, const std::vector<uint8_t> &message)
{
    size_t sent = 0;
    while (sent < message.size()) {
        const ssize_t n = send(fd, message.data() + sent, message.size() - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return; // the ORB closed the connection: its answer to this input
        sent += size_t(n);
    }
}

int s_connectionPort = 0;

int localPort(int fd)
{
    sockaddr_in address {};
    socklen_t length = sizeof address;
    if (getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length) != 0 || address.sin_family != AF_INET)
        return -1;
    return ntohs(address.sin_port);
}

// The harness's descriptor is still its own connection: the server and the harness share one
// process, so a descriptor closed twice on the server's side can take the harness's away.
void checkConnection()
{
    const int port = localPort(s_connection);
    if (port != s_connectionPort) {
        std::fprintf(stderr, "fuzz_giop: descriptor %d is no longer the harness's connection (port %d, now %d): "
                     "something in the process closed it; the latest requests:\n", s_connection, s_connectionPort,
                     port);
        for (const std::string &request : s_recent)
            std::fprintf(stderr, "  %s\n", request.c_str());
        std::abort();
    }
}

// Where every thread of the server waits, when gdb is installed: what a hang's cause is seen in.
void printThreads()
{
    std::fprintf(stderr, "fuzz_giop: the harness's connection is fd %d; the sockets of port %d:\n", s_connection,
                 s_port);
    const std::string sockets = "ss -tanpi '( sport = :" + std::to_string(s_port) + " or dport = :"
        + std::to_string(s_port) + " )' >&2";
    if (std::system(sockets.c_str()) != 0)
        std::fprintf(stderr, "fuzz_giop: (no socket list: ss is not installed)\n");
    const std::string command = "gdb -p " + std::to_string(getpid())
        + " -batch -nx -ex 'thread apply all bt 30' </dev/null >&2 2>/dev/null";
    if (std::system(command.c_str()) != 0)
        std::fprintf(stderr, "fuzz_giop: (no thread stacks: gdb is not installed or cannot attach)\n");
}

// Reads until @p wanted bytes arrived (true) or the ORB closed the connection (false); a server that
// neither answers nor closes within the bound is a hang.
bool readBytes(int fd, uint8_t *buffer, size_t wanted)
{
    size_t have = 0;
    while (have < wanted) {
        if (!waitReadable(fd, ReplyTimeoutMs)) {
            if (fd == s_connection)
                checkConnection();
            std::fprintf(stderr, "fuzz_giop: no reply and no close within %d ms; the latest requests:\n",
                         ReplyTimeoutMs);
            for (const std::string &request : s_recent)
                std::fprintf(stderr, "  %s\n", request.c_str());
            printThreads();
            std::abort();
        }
        const ssize_t n = recv(fd, buffer + have, wanted - have, 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        have += size_t(n);
    }
    return true;
}

/// A GIOP message received: its type (1 Reply, 6 MessageError, …) and, for a reply, its status.
struct Received
{
    int type = -1;
    int replyStatus = -1;
    /// The request a Reply or LocateReply answers (-1: another message).
    int64_t requestId = -1;
};

// Reads one whole GIOP message, with the fragments that follow it (flag 0x02: more to come); false
// when the connection ended instead.
bool readMessage(int fd, Received *received = nullptr)
{
    bool first = true;
    for (;;) {
        uint8_t header[12];
        if (!readBytes(fd, header, sizeof header))
            return false;
        const bool little = header[6] & 1;
        uint32_t size = 0;
        for (int i = 0; i < 4; ++i)
            size |= uint32_t(header[8 + i]) << (little ? 8 * i : 8 * (3 - i));
        std::vector<uint8_t> body(size);
        if (!readBytes(fd, body.data(), size))
            return false;
        if (received && first) {
            received->type = header[7];
            // A 1.2 reply header: request id, then the reply status.
            if ((header[7] == 1 || header[7] == 4) && size >= 8) {
                received->replyStatus = little ? body[4] : body[7];
                uint32_t id = 0;
                for (int i = 0; i < 4; ++i)
                    id |= uint32_t(body[i]) << (little ? 8 * i : 8 * (3 - i));
                received->requestId = id;
            }
        }
        first = false;
        if (!(header[6] & 0x02))
            return true;
    }
}

// Bytes that are not a whole message may get no answer at all: the ORB waits for the rest (until
// its idle connections are closed, minutes later) while it serves every other connection, so the
// harness does not wait for an answer here; what it sends next finds the ORB still serving.
void sendRaw(const uint8_t *data, size_t size)
{
    const int fd = connectToOrb();
    sendAll(fd, std::vector<uint8_t>(data, data + size));
    shutdown(fd, SHUT_WR);
    char drain[4096];
    while (waitReadable(fd, RawAnswerMs) && recv(fd, drain, sizeof drain, 0) > 0) {
    }
    close(fd);
}

Received sendRequest(const Target &target, const char *operation, bool little, const uint8_t *body, size_t size)
{
    std::vector<uint8_t> message {'G', 'I', 'O', 'P', 1, 2, uint8_t(little ? 1 : 0), 0, 0, 0, 0, 0};
    appendULong(message, ++s_requestId, little);
    message.insert(message.end(), {3, 0, 0, 0}); // response expected; reserved
    message.insert(message.end(), {0, 0});       // KeyAddr
    appendULong(message, uint32_t(target.key.size()), little);
    append(message, target.key.data(), target.key.size());
    appendULong(message, uint32_t(std::strlen(operation) + 1), little);
    append(message, operation, std::strlen(operation) + 1);
    appendULong(message, 0, little); // no service contexts
    // A body starts at a multiple of 8 from the message's start; no body, no padding.
    while (size > 0 && message.size() % 8)
        message.push_back(0);
    append(message, body, size);
    const uint32_t length = uint32_t(message.size() - 12);
    for (int i = 0; i < 4; ++i)
        message[8 + i] = uint8_t(length >> (little ? 8 * i : 8 * (3 - i)));
    if (s_connection < 0) {
        s_connection = connectToOrb();
        s_connectionPort = localPort(s_connection);
    }
    checkConnection();
    sendAll(s_connection, message);
    // What comes back may not answer this request: omniORB answers some malformed requests with more
    // than one message, and a harness reading one message per request fell behind by one each time,
    // until both sides' buffers were full and neither could send (after about 45,000 inputs). A
    // connection out of step is closed, with what is still queued on it, and the next request opens
    // another.
    Received received;
    if (!readMessage(s_connection, &received) || received.requestId != s_requestId) {
        close(s_connection);
        s_connection = -1;
    }
    return received;
}

std::string keyOf(CORBA::ORB_ptr orb, CORBA::Object_ptr object)
{
    CORBA::String_var ior = orb->object_to_string(object);
    return objectKey(std::string(ior.in()));
}

// libFuzzer's leak check after each input stops the process while the ORB's worker threads still
// finish the request the reply answered (a connection's server-side request objects, held where the
// check does not look, are reported as leaked; one replay of such an input reports nothing). That
// check is off for this harness; the sanitizer's check when the process ends stays on.
[[maybe_unused]] void withoutPerInputLeakCheck(int *argc, char ***argv)
{
    static std::vector<char *> arguments;
    static char flag[] = "-detect_leaks=0";
    arguments.assign(*argv, *argv + *argc);
    arguments.insert(arguments.begin() + 1, flag);
    arguments.push_back(nullptr);
    *argc += 1;
    *argv = arguments.data();
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv)
{
#ifdef RTSTUDIO_LIBFUZZER
    withoutPerInputLeakCheck(argc, argv);
#else
    (void)argc;
    (void)argv;
#endif
    static char folder[] = "/tmp/fuzz_giop_modulesXXXXXX";
    if (!mkdtemp(folder))
        std::abort();
    // A free port, kept by the ORB from then on.
    const int probe = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    bind(probe, reinterpret_cast<sockaddr *>(&address), sizeof address);
    getsockname(probe, reinterpret_cast<sockaddr *>(&address), &length);
    s_port = ntohs(address.sin_port);
    close(probe);

    Runtime::Properties config;
    for (const auto &[key, value] : std::vector<std::pair<std::string, std::string>> {
             {"manager.is_master", "YES"},
             {"corba.endpoints", "127.0.0.1:" + std::to_string(s_port)},
             {"corba.master_manager", "127.0.0.1:" + std::to_string(s_port)},
             {"corba.unix_socket", "NO"},
             {"naming.enable", "NO"},
             {"logger.enable", "NO"},
             {"manager.slaves.max", "0"},
             // Components the inputs create stay: a bound keeps the server's state (and memory) small
             // over a million inputs, and the refusal beyond it is fuzzed too.
             {"manager.components.max", "8"},
             {"manager.modules.load_path", folder},
             // The installer's store: a folder of the run's own, with no key to trust.
             {"manager.packages.store", std::string(folder) + "/store"},
             // Servants call the references inputs carry: unreachable ones fail fast.
             {"corba.call_timeout", "500"},
             {"corba.connect_timeout", "500"},
             // What the ORB says of each malformed message would drown the fuzzer's own output.
             {"corba.args", "-ORBtraceLevel 0"}})
        config.set(key, value);
    // FUZZ_GIOP_ORB_ARGS replaces them, to follow a hang in omniORB's own trace, e.g.
    // "-ORBtraceLevel 25 -ORBtraceThreadId 1 -ORBtraceTime 1 -ORBtraceFile giop.trace".
    if (const char *orbArguments = std::getenv("FUZZ_GIOP_ORB_ARGS"))
        config.set("corba.args", orbArguments);
    // Never destroyed: it serves until the process ends, as rtmanager's does.
    static Runtime::Manager &manager = *new Runtime::Manager(config);
    // The package installer as rtmanager makes it, with the Qt application object its tools want.
    static int applicationArgc = 1;
    static char applicationName[] = "fuzz_giop";
    static char *applicationArgv[] = {applicationName, nullptr};
    static QCoreApplication &application = *new QCoreApplication(applicationArgc, applicationArgv);
    (void)application;
    std::string error;
    PortableServer::ServantBase_var installerServant = Runtime::PackageInstallerServant::create(manager, &error);
    if (installerServant.in() == nullptr || !manager.start(&error)) {
        std::fprintf(stderr, "fuzz_giop: the manager does not start: %s\n", error.c_str());
        std::abort();
    }
    CORBA::Object_var installerReference = manager.activate(installerServant.in());
    manager.setPackageInstaller(installerReference);
    Runtime::Properties profile;
    for (const auto &[key, value] : std::vector<std::pair<const char *, const char *>> {
             {"implementation_id", "FuzzTarget"}, {"type_name", "FuzzTarget"}, {"version", "1.0.0"},
             {"vendor", "RTStudio"}, {"category", "fuzz"}, {"activity_type", "PERIODIC"},
             {"kind", "DataFlowComponent"}, {"max_instance", "1"}, {"language", "C++"}})
        profile.set(key, value);
    manager.registerFactory({profile, [](PortableServer::POA_ptr poa) { return new FuzzTarget(poa); }, {}});
    RTC::RTObject_var rtc = manager.createComponent("FuzzTarget", &error);
    if (CORBA::is_nil(rtc)) {
        std::fprintf(stderr, "fuzz_giop: no component: %s\n", error.c_str());
        std::abort();
    }
    int orbArgc = 0;
    CORBA::ORB_var orb = CORBA::ORB_init(orbArgc, nullptr);
    s_targets.push_back({"manager", &managerOperations});
    s_targets.push_back({keyOf(orb, rtc), &componentOperations});
    RTC::ExecutionContextList_var contexts = rtc->get_owned_contexts();
    s_targets.push_back({keyOf(orb, contexts[0]), &contextOperations});
    SDOPackage::Configuration_var configuration = rtc->get_configuration();
    s_targets.push_back({keyOf(orb, configuration), &configurationOperations});
    s_component = RTC::RTObject::_duplicate(rtc);
    RTC::PortServiceList_var ports = rtc->get_ports();
    s_portCount = ports->length();
    RTC::PortService_var in, out;
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        s_targets.push_back({keyOf(orb, ports[i]), &portOperations});
        RTC::PortProfile_var port = ports[i]->get_port_profile();
        const std::string name(port->name.in());
        (name.size() > 3 && name.compare(name.size() - 3, 3, ".in") == 0 ? in : out) =
            RTC::PortService::_duplicate(ports[i]);
    }
    // The component's OutPort connected to its InPort twice: pushed, an InPortCdr that takes
    // samples; pulled, an OutPortCdr that gives them.
    for (const auto &[flow, end, operations] :
         {std::tuple("push", "inport", &inPortCdrOperations), std::tuple("pull", "outport", &outPortCdrOperations)}) {
        RTC::ConnectorProfile connector;
        connector.name = CORBA::string_dup(flow);
        connector.connector_id = CORBA::string_dup("");
        connector.ports.length(2);
        connector.ports[0] = RTC::PortService::_duplicate(out);
        connector.ports[1] = RTC::PortService::_duplicate(in);
        const char *const properties[][2] = {{"dataport.interface_type", "corba_cdr"},
                                             {"dataport.dataflow_type", flow},
                                             {"dataport.subscription_type", "flush"},
                                             {"dataport.data_type", "IDL:RTC/TimedLong:1.0"},
                                             {"dataport.allow_dup_connection", "YES"}};
        connector.properties.length(std::size(properties));
        for (CORBA::ULong i = 0; i < std::size(properties); ++i) {
            connector.properties[i].name = CORBA::string_dup(properties[i][0]);
            connector.properties[i].value <<= properties[i][1];
        }
        const std::string iorKey = std::string("dataport.corba_cdr.") + end + "_ior";
        const RTC::ReturnCode_t connected = out->connect(connector);
        if (connected != RTC::RTC_OK) {
            std::fprintf(stderr, "fuzz_giop: the %s connection was refused (%d)\n", flow, int(connected));
            std::abort();
        }
        for (CORBA::ULong i = 0; i < connector.properties.length(); ++i) {
            const char *value = nullptr;
            if (iorKey == connector.properties[i].name.in() && (connector.properties[i].value >>= value))
                s_targets.push_back({objectKey(value), operations});
        }
    }
    RTM::Manager_var reference = manager.reference();
    RTStudio::Manager_var extended = RTStudio::Manager::_narrow(reference);
    RTStudio::PackageInstaller_var installer = extended->get_package_installer();
    if (CORBA::is_nil(installer)) {
        std::fprintf(stderr, "fuzz_giop: the manager has no package installer\n");
        std::abort();
    }
    s_targets.push_back({keyOf(orb, installer), &installerOperations});
    std::fprintf(stderr, "fuzz_giop: %zu objects served\n", s_targets.size());
    // The harness's framing reaches the servants: a request without arguments gets its answer.
    for (const Target &target : s_targets) {
        const Received answer = sendRequest(target, "_non_existent", false, nullptr, 0);
        if (answer.type != 1 || answer.replyStatus != 0) {
            std::fprintf(stderr, "fuzz_giop: _non_existent on key %s got message type %d, reply status %d\n",
                         target.key.c_str(), answer.type, answer.replyStatus);
            std::abort();
        }
    }
    return 0;
}

// With FUZZ_GIOP_INPUTS=DIR each input is also written to DIR, numbered, the latest 256 kept: a
// finding that needs the server's state from earlier inputs is then replayed in order with
// `fuzz_giop DIR/*`.
void keepInput(const uint8_t *data, size_t size)
{
    static const char *const folder = std::getenv("FUZZ_GIOP_INPUTS");
    static unsigned long number = 0;
    if (folder == nullptr)
        return;
    const auto path = [](unsigned long n) {
        char name[32];
        std::snprintf(name, sizeof name, "/%010lu", n);
        return std::string(folder) + name;
    };
    if (FILE *file = std::fopen(path(++number).c_str(), "wb")) {
        std::fwrite(data, 1, size, file);
        std::fclose(file);
    }
    if (number > 256)
        std::remove(path(number - 256).c_str());
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    keepInput(data, size);
    if (size < 3)
        return 0;
    if (data[0] & 0x80) {
        sendRaw(data + 1, size - 1);
        return 0;
    }
    const size_t index = data[0] % s_targets.size();
    const Target &target = s_targets[index];
    const char *operation = (*target.operations)[data[1] % target.operations->size()];
    std::string hex;
    for (size_t i = 0; i < size && i < 64; ++i) {
        char byte[4];
        std::snprintf(byte, sizeof byte, "%02x", data[i]);
        hex += byte;
    }
    remember("object " + std::to_string(index) + ' ' + operation + ": " + hex);
    sendRequest(target, operation, data[2] & 1, data + 3, size - 3);
    if (++s_inputs % 256 == 0 || std::strcmp(operation, "on_initialize") == 0) {
        RTC::PortServiceList_var ports = s_component->get_ports();
        if (ports->length() != s_portCount) {
            std::fprintf(stderr, "fuzz_giop: the component lists %u ports, not its %u; the latest requests:\n",
                         ports->length(), s_portCount);
            for (const std::string &request : s_recent)
                std::fprintf(stderr, "  %s\n", request.c_str());
            std::abort();
        }
    }
    return 0;
}
