// SPDX-License-Identifier: MIT
// Data-port latency and throughput of components written against the SDK, measured the way
// OpenRTM-aist's Throughput example measures them: RTC::TimedDoubleSeq samples of 1 to 1,048,576
// elements over a push connection with subscription "flush" and interface "corba_cdr". One-way
// latency is the receiver's ON_BUFFER_WRITE listener time minus the time stamp the sender set just
// before write() (system_clock on both sides); throughput is the payload over the mean interval of
// back-to-back writes (a flush write returns once the receiver has the sample).
// Three placements in one run: two components in one RTC::Manager, and a receiver in a second process
// (this program run with --receiver PORT [tcp]) reached through corbaloc:iiop:127.0.0.1:PORT/manager,
// once through the Unix socket the runtime offers same-host peers by default and once over loopback
// TCP only (corba.unix_socket: NO in the receiver). A fourth, two processes over TLS with client
// certificates (corba.ssl.* keys, certificates made by `rtctl tls`), runs in a sender process of its
// own (--tls-sender FOLDER), as a process is plain or TLS from its first call on.
// The targets, from OpenRTM-aist 2.1's figures, are printed against the measurements at the end.
// With --openrtm PREFIX (or OPENRTM_PREFIX), OpenRTM-aist's own Throughput example installed there
// runs afterwards in both placements (bounded in time) and its figures are printed beside ours.
#include <rtm/ConnectorListener.h>
#include <rtm/DataFlowComponentBase.h>
#include <rtm/DataInPort.h>
#include <rtm/DataOutPort.h>
#include <rtm/Manager.h>

#include <Manager.hh>

#include "openrtmthroughput.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using Clock = std::chrono::steady_clock;

/// 1 to 1,048,576 elements, doubling: the sizes OpenRTM-aist's example measures, so that both
/// peaks are taken over the same sizes.
std::vector<CORBA::ULong> allSizes()
{
    std::vector<CORBA::ULong> result;
    for (CORBA::ULong elements = 1; elements <= 1048576; elements *= 2)
        result.push_back(elements);
    return result;
}
const std::vector<CORBA::ULong> sizes = allSizes();
// The first element of a sample says what it is: its index when measured, or one of these.
constexpr CORBA::Double warmUpMark = -1;
constexpr CORBA::Double endOfSizeMark = -2;
constexpr int warmUpSamples = 5;
// A size stops early (with at least minSamples) once its samples took this long.
constexpr double sizeBudgetSeconds = 6;
constexpr int minSamples = 10;
constexpr double mebibyte = 1024.0 * 1024.0;
// OpenRTM-aist's example, when run beside this benchmark, is stopped after this long.
constexpr int openRtmTimeoutSeconds = 180;
// omniORB refuses GIOP messages over 2 MiB by default; OpenRTM's Throughput script raises the limit
// with `corba.args: -ORBgiopMaxMsgSize 209715200`. The manager takes no ORB arguments, so the
// environment carries it (omniORB reads ORB<parameter> variables; the receiver inherits them).
const char *const giopMaxMsgSize = "209715200";

/// 200 samples for small sizes, fewer above 2 MiB so that each size sends about 512 MiB at most.
int samplesFor(CORBA::ULong elements)
{
    const double bytes = double(elements) * sizeof(CORBA::Double);
    return int(std::clamp(512.0 * mebibyte / bytes, 20.0, 200.0));
}

/// One size's latencies in microseconds, as the receiver saw them.
struct Latency
{
    CORBA::ULong elements = 0;
    long count = 0;
    double mean = 0;
    double min = 0;
    double max = 0;
    double stddev = 0;
};

Latency summarize(CORBA::ULong elements, const std::vector<double> &us)
{
    Latency result;
    result.elements = elements;
    result.count = long(us.size());
    if (us.empty())
        return result;
    double sum = 0;
    for (double value : us)
        sum += value;
    result.mean = sum / double(us.size());
    double squares = 0;
    for (double value : us)
        squares += (value - result.mean) * (value - result.mean);
    result.stddev = std::sqrt(squares / double(us.size()));
    result.min = *std::min_element(us.begin(), us.end());
    result.max = *std::max_element(us.begin(), us.end());
    return result;
}

/// The receiver process's report of one size, one line on its standard output.
std::string toLine(const Latency &l)
{
    std::ostringstream line;
    line << "result " << l.elements << ' ' << l.count << ' ' << l.mean << ' ' << l.min << ' '
         << l.max << ' ' << l.stddev << '\n';
    return line.str();
}

bool fromLine(const std::string &line, Latency *l)
{
    std::istringstream in(line);
    std::string word;
    return bool(in >> word >> l->elements >> l->count >> l->mean >> l->min >> l->max >> l->stddev)
        && word == "result";
}

double microsecondsSince(const RTC::Time &stamp)
{
    const auto now = std::chrono::duration_cast<std::chrono::nanoseconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
    const long long sent = (long long)stamp.sec * 1000000000LL + (long long)stamp.nsec;
    return double(now - sent) / 1000.0;
}

using Report = std::function<void(const Latency &)>;

/// Records the one-way latency of each measured sample; the end mark closes a size and reports it.
class LatencyListener : public RTC::ConnectorDataListenerT<RTC::TimedDoubleSeq>
{
    USE_CONNLISTENER_STATUS;

public:
    explicit LatencyListener(Report *report)
        : m_report(report)
    { }
    ReturnCode operator()(RTC::ConnectorInfo &, RTC::TimedDoubleSeq &data) override
    {
        const double us = microsecondsSince(data.tm);
        const CORBA::Double mark = data.data.length() > 0 ? data.data[0] : 0;
        std::lock_guard<std::mutex> lock(m_mutex);
        if (mark == endOfSizeMark && data.data.length() == 2) {
            const Latency result = summarize(CORBA::ULong(data.data[1]), m_latencies);
            m_latencies.clear();
            if (*m_report)
                (*m_report)(result);
        } else if (mark != warmUpMark) {
            m_latencies.push_back(us);
        }
        return NO_CHANGE;
    }

private:
    Report *m_report;
    std::mutex m_mutex;
    std::vector<double> m_latencies;
};

const char *const senderSpec[] = {"implementation_id",
                                  "FlowSender",
                                  "type_name",
                                  "FlowSender",
                                  "description",
                                  "sends TimedDoubleSeq samples",
                                  "version",
                                  "1.0.0",
                                  "vendor",
                                  "RTStudioBench",
                                  "category",
                                  "bench",
                                  "activity_type",
                                  "PERIODIC",
                                  "kind",
                                  "DataFlowComponent",
                                  "max_instance",
                                  "1",
                                  "language",
                                  "C++",
                                  "lang_type",
                                  "compile",
                                  ""};

class FlowSender : public RTC::DataFlowComponentBase
{
public:
    explicit FlowSender(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_outOut("out", m_out)
    { }
    RTC::ReturnCode_t onInitialize() override
    {
        addOutPort("out", m_outOut);
        return RTC::RTC_OK;
    }
    /// Stamps and writes @p sample; with a flush connection this returns after the receiver took
    /// it.
    void send(RTC::TimedDoubleSeq &sample)
    {
        setTimestamp(sample);
        m_outOut.write(sample);
    }

private:
    RTC::TimedDoubleSeq m_out;
    RTC::OutPort<RTC::TimedDoubleSeq> m_outOut;
};

const char *const receiverSpec[] = {"implementation_id",
                                    "FlowReceiver",
                                    "type_name",
                                    "FlowReceiver",
                                    "description",
                                    "times TimedDoubleSeq samples",
                                    "version",
                                    "1.0.0",
                                    "vendor",
                                    "RTStudioBench",
                                    "category",
                                    "bench",
                                    "activity_type",
                                    "PERIODIC",
                                    "kind",
                                    "DataFlowComponent",
                                    "max_instance",
                                    "1",
                                    "language",
                                    "C++",
                                    "lang_type",
                                    "compile",
                                    ""};

class FlowReceiver : public RTC::DataFlowComponentBase
{
public:
    explicit FlowReceiver(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
        , m_inIn("in", m_in)
    { }
    RTC::ReturnCode_t onInitialize() override
    {
        addInPort("in", m_inIn);
        m_inIn.addConnectorDataListener(RTC::ConnectorDataListenerType::ON_BUFFER_WRITE,
                                        new LatencyListener(&m_report));
        return RTC::RTC_OK;
    }
    /// Where the results of each size go; set before any sample arrives.
    void setReport(Report report) { m_report = std::move(report); }

private:
    Report m_report;
    RTC::TimedDoubleSeq m_in;
    RTC::InPort<RTC::TimedDoubleSeq> m_inIn;
};

/// How a receiver in another process is reached.
enum class Transport { UnixSocket, Tcp, Tls };

/// The command-line word of each transport, for the receiver process.
const char *transportWord(Transport transport)
{
    return transport == Transport::UnixSocket ? "unix" : transport == Transport::Tcp ? "tcp" : "tls";
}

/// The manager of this process: no name server, no master, loopback only. With @p tlsFolder (made by
/// `rtctl tls init` and `issue … node`), TLS only, presenting the node's certificate.
RTC::Manager *startManager(const char *program, const std::string &endpoint,
                           Transport transport = Transport::UnixSocket, const std::string &tlsFolder = {})
{
    setenv("ORBgiopMaxMsgSize", giopMaxMsgSize, 0);
    const std::string endpoints = "corba.endpoints:" + endpoint;
    const char *unixSocket
        = transport == Transport::UnixSocket ? "corba.unix_socket:YES" : "corba.unix_socket:NO";
    const std::string authority = "corba.ssl.certificate_authority_file:" + tlsFolder + "/ca.pem";
    const std::string key = "corba.ssl.key_file:" + tlsFolder + "/node.pem";
    std::vector<const char *> args = {program,
                          "-o",
                          "naming.enable:NO",
                          "-o",
                          "corba.master_manager:",
                          "-o",
                          endpoints.c_str(),
                          "-o",
                          "logger.log_level:ERROR",
                          "-o",
                          unixSocket,
                          "-i",
                          "-f",
                          "/nonexistent"};
    if (transport == Transport::Tls)
        args.insert(args.end(), {"-o", authority.c_str(), "-o", key.c_str()});
    std::vector<char *> argv;
    for (const char *arg : args)
        argv.push_back(const_cast<char *>(arg));
    RTC::Manager *manager = RTC::Manager::init(int(argv.size()), argv.data());
    if (manager == nullptr || !manager->activateManager())
        return nullptr;
    manager->runManager(true);
    coil::Properties sender(senderSpec), receiver(receiverSpec);
    manager->registerFactory(sender, RTC::Create<FlowSender>, RTC::Delete<FlowSender>);
    manager->registerFactory(receiver, RTC::Create<FlowReceiver>, RTC::Delete<FlowReceiver>);
    return manager;
}

RTC::PortService_ptr portNamed(RTC::RTObject_ptr component, const std::string &name)
{
    RTC::PortServiceList_var ports = component->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        const std::string full(profile->name);
        if (full.size() > name.size()
            && full.compare(full.size() - name.size() - 1, std::string::npos, '.' + name) == 0)
            return RTC::PortService::_duplicate(ports[i]);
    }
    return RTC::PortService::_nil();
}

bool connectFlush(RTC::PortService_ptr out, RTC::PortService_ptr in)
{
    if (CORBA::is_nil(out) || CORBA::is_nil(in))
        return false;
    RTC::ConnectorProfile profile;
    profile.name = CORBA::string_dup("flow");
    profile.connector_id = CORBA::string_dup("");
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(out);
    profile.ports[1] = RTC::PortService::_duplicate(in);
    const char *const pairs[][2] = {{"dataport.interface_type", "corba_cdr"},
                                    {"dataport.dataflow_type", "push"},
                                    {"dataport.subscription_type", "flush"},
                                    {"dataport.data_type", "IDL:RTC/TimedDoubleSeq:1.0"}};
    profile.properties.length(4);
    for (CORBA::ULong i = 0; i < 4; ++i) {
        profile.properties[i].name = CORBA::string_dup(pairs[i][0]);
        profile.properties[i].value <<= pairs[i][1];
    }
    return out->connect(profile) == RTC::RTC_OK;
}

/// One row of the table: the receiver's latencies and the sender's throughput.
struct Row
{
    Latency latency;
    int sent = 0;
    double mibPerSecond = 0;
    bool reported = false;
};

/// Waits for the receiver's result of the size just ended; false when it did not come.
using AwaitResult = std::function<bool(Latency *)>;

Row measureSize(FlowSender *sender, CORBA::ULong elements, const AwaitResult &awaitResult)
{
    RTC::TimedDoubleSeq sample;
    sample.data.length(elements);
    for (CORBA::ULong i = 0; i < elements; ++i)
        sample.data[i] = 0.5 * i;
    sample.data[0] = warmUpMark;
    for (int i = 0; i < warmUpSamples; ++i)
        sender->send(sample);

    Row row;
    const int wanted = samplesFor(elements);
    const auto start = Clock::now();
    const auto budget = start
        + std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(sizeBudgetSeconds));
    while (row.sent < wanted && (row.sent < minSamples || Clock::now() < budget)) {
        sample.data[0] = row.sent;
        sender->send(sample);
        ++row.sent;
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    row.mibPerSecond = double(elements) * sizeof(CORBA::Double) * row.sent / seconds / mebibyte;

    RTC::TimedDoubleSeq end;
    end.data.length(2);
    end.data[0] = endOfSizeMark;
    end.data[1] = elements;
    sender->send(end);
    row.reported = awaitResult(&row.latency) && row.latency.elements == elements;
    return row;
}

void printHeader(const char *placement)
{
    std::printf("\n%s\n", placement);
    std::printf("| elements |      bytes | sent | received | mean us |  min us |   max us | stddev "
                "us |    MiB/s |\n");
    std::printf("|----------|------------|------|----------|---------|---------|----------|--------"
                "---|----------|\n");
}

void printRow(CORBA::ULong elements, const Row &row)
{
    if (!row.reported) {
        std::printf("| %8u | %10zu | %4d | no result from the receiver\n", unsigned(elements),
                    size_t(elements) * sizeof(CORBA::Double), row.sent);
        std::fflush(stdout);
        return;
    }
    const Latency &l = row.latency;
    std::printf("| %8u | %10zu | %4d | %8ld | %7.1f | %7.1f | %8.1f | %9.1f | %8.1f |\n",
                unsigned(elements), size_t(elements) * sizeof(CORBA::Double), row.sent, l.count,
                l.mean, l.min, l.max, l.stddev, row.mibPerSecond);
    std::fflush(stdout);
}

std::vector<Row> measureAll(FlowSender *sender, const AwaitResult &awaitResult)
{
    std::vector<Row> rows;
    for (CORBA::ULong elements : sizes) {
        rows.push_back(measureSize(sender, elements, awaitResult));
        printRow(elements, rows.back());
    }
    return rows;
}

// --- the receiver process ---

/// This program as the receiving process: a manager on 127.0.0.1:PORT with one FlowReceiver that
/// prints a result line per size; it runs until its standard input closes.
int runReceiver(const char *program, const char *port, Transport transport, const std::string &tlsFolder)
{
    RTC::Manager *manager = startManager(program, std::string("127.0.0.1:") + port, transport, tlsFolder);
    if (manager == nullptr)
        return 1;
    auto *receiver = dynamic_cast<FlowReceiver *>(manager->createComponent("FlowReceiver"));
    if (receiver == nullptr)
        return 1;
    receiver->setReport([](const Latency &l) {
        const std::string line = toLine(l);
        std::fwrite(line.data(), 1, line.size(), stdout);
        std::fflush(stdout);
    });
    std::printf("ready %s\n", receiver->getInstanceName());
    std::fflush(stdout);
    char buffer[256];
    while (read(STDIN_FILENO, buffer, sizeof buffer) > 0) { }
    // The sender is done; nothing here outlives the process, so skip the ORB's orderly shutdown.
    std::_Exit(0);
}

/// The receiver process seen from the sender: started with pipes on its standard input and output,
/// stopped (closed input, then SIGKILL) when this object goes.
class ReceiverProcess
{
public:
    ReceiverProcess() = default;
    ReceiverProcess(const ReceiverProcess &) = delete;
    ReceiverProcess &operator=(const ReceiverProcess &) = delete;
    ~ReceiverProcess() { stop(); }

    bool start(unsigned port, Transport transport, const std::string &tlsFolder)
    {
        int toChild[2], fromChild[2];
        if (pipe(toChild) != 0 || pipe(fromChild) != 0)
            return false;
        const std::string portText = std::to_string(port);
        m_pid = fork();
        if (m_pid == 0) {
            // Only async-signal-safe calls between fork and exec: the ORB's threads are not copied.
            prctl(PR_SET_PDEATHSIG, SIGKILL);
            dup2(toChild[0], STDIN_FILENO);
            dup2(fromChild[1], STDOUT_FILENO);
            close(toChild[1]);
            close(fromChild[0]);
            execl("/proc/self/exe", "bench_sdkflow", "--receiver", portText.c_str(), transportWord(transport),
                  tlsFolder.c_str(), static_cast<char *>(nullptr));
            _exit(127);
        }
        close(toChild[0]);
        close(fromChild[1]);
        m_input = toChild[1];
        m_output = fromChild[0];
        return m_pid > 0;
    }

    /// The next line of its output, or false after @p timeoutMs or when it closed its output.
    bool readLine(std::string *line, int timeoutMs)
    {
        const auto deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
        for (;;) {
            const size_t newline = m_pending.find('\n');
            if (newline != std::string::npos) {
                *line = m_pending.substr(0, newline);
                m_pending.erase(0, newline + 1);
                return true;
            }
            const auto left
                = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now())
                      .count();
            pollfd fd {m_output, POLLIN, 0};
            if (left <= 0 || poll(&fd, 1, int(left)) <= 0)
                return false;
            char buffer[4096];
            const ssize_t n = read(m_output, buffer, sizeof buffer);
            if (n <= 0)
                return false;
            m_pending.append(buffer, size_t(n));
        }
    }

    void stop()
    {
        if (m_input >= 0)
            close(m_input);
        m_input = -1;
        if (m_pid > 0) {
            int status = 0;
            for (int i = 0; i < 100 && waitpid(m_pid, &status, WNOHANG) == 0; ++i)
                usleep(20000);
            if (waitpid(m_pid, &status, WNOHANG) == 0) {
                kill(m_pid, SIGKILL);
                waitpid(m_pid, &status, 0);
            }
        }
        m_pid = -1;
        if (m_output >= 0)
            close(m_output);
        m_output = -1;
    }

private:
    pid_t m_pid = -1;
    int m_input = -1;
    int m_output = -1;
    std::string m_pending;
};

unsigned freePort()
{
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    unsigned port = 0;
    if (bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0
        && getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length) == 0)
        port = ntohs(address.sin_port);
    close(fd);
    return port;
}

// --- the two placements ---

std::vector<Row> measureInProcess(RTC::Manager *manager, FlowSender *sender)
{
    auto *receiver = dynamic_cast<FlowReceiver *>(manager->createComponent("FlowReceiver"));
    if (receiver == nullptr) {
        std::printf("cannot create the receiving component\n");
        return {};
    }
    // The listener reports in the writer's call chain: the result is there when write() returns.
    std::mutex mutex;
    std::vector<Latency> results;
    receiver->setReport([&](const Latency &l) {
        std::lock_guard<std::mutex> lock(mutex);
        results.push_back(l);
    });
    RTC::RTObject_var from = sender->getObjRef();
    RTC::RTObject_var to = receiver->getObjRef();
    RTC::PortService_var out = portNamed(from, "out");
    RTC::PortService_var in = portNamed(to, "in");
    if (!connectFlush(out, in)) {
        std::printf("cannot connect the ports\n");
        return {};
    }
    printHeader("(a) one process: two components in one RTC::Manager");
    const std::vector<Row> rows = measureAll(sender, [&](Latency *l) {
        std::lock_guard<std::mutex> lock(mutex);
        if (results.empty())
            return false;
        *l = results.back();
        results.clear();
        return true;
    });
    out->disconnect_all();
    receiver->setReport({});
    return rows;
}

const char *const unixPlacement
    = "(b) two processes on one host, through the Unix socket the runtime offers by default";
const char *const tcpPlacement = "(c) two processes over loopback TCP (receiver: corba.unix_socket NO)";
const char *const tlsPlacement = "(d) two processes over loopback TLS, each presenting a certificate (P-256)";

std::vector<Row> measureBetweenProcesses(RTC::Manager *manager, FlowSender *sender, Transport transport,
                                         const std::string &tlsFolder = {})
{
    const unsigned port = freePort();
    ReceiverProcess process;
    std::string line;
    // Anything else the receiver prints (its log) is passed over.
    const auto nextLine
        = [&process](std::string *text, const std::function<bool(const std::string &)> &wanted) {
              while (process.readLine(text, 30000)) {
                  if (wanted(*text))
                      return true;
              }
              return false;
          };
    if (port == 0 || !process.start(port, transport, tlsFolder)
        || !nextLine(&line, [](const std::string &text) { return text.rfind("ready", 0) == 0; })) {
        std::printf("\nthe receiver process did not start (%s)\n", line.c_str());
        return {};
    }
    RTC::PortService_var in;
    try {
        const std::string address = std::string(transport == Transport::Tls ? "corbaloc:ssliop:" : "corbaloc:iiop:")
            + "127.0.0.1:" + std::to_string(port) + "/manager";
        CORBA::Object_var object = manager->getORB()->string_to_object(address.c_str());
        RTM::Manager_var remote = RTM::Manager::_narrow(object);
        RTC::RTCList_var components = remote->get_components();
        if (components->length() == 1)
            in = portNamed(components[0], "in");
    } catch (const CORBA::Exception &e) {
        std::printf("\nthe receiver's manager did not answer: %s\n", e._name());
        return {};
    }
    RTC::RTObject_var from = sender->getObjRef();
    RTC::PortService_var out = portNamed(from, "out");
    if (!connectFlush(out, in)) {
        std::printf("\ncannot connect to the receiver's port\n");
        return {};
    }
    printHeader(transport == Transport::UnixSocket ? unixPlacement
                : transport == Transport::Tcp          ? tcpPlacement
                                                       : tlsPlacement);
    const std::vector<Row> rows = measureAll(sender, [&](Latency *l) {
        std::string result;
        return nextLine(&result, [l](const std::string &text) { return fromLine(text, l); });
    });
    out->disconnect_all();
    return rows;
}

// --- targets ---

/// The larger mean latency of the 1- and 8-element sizes; negative when either is missing.
double smallLatency(const std::vector<Row> &rows)
{
    double worst = -1;
    for (const Row &row : rows) {
        if (row.latency.elements > 8)
            continue;
        if (!row.reported)
            return -1;
        worst = std::max(worst, row.latency.mean);
    }
    return worst;
}

double peakGiBPerSecond(const std::vector<Row> &rows)
{
    double peak = 0;
    for (const Row &row : rows) {
        if (row.reported && row.latency.count == row.sent)
            peak = std::max(peak, row.mibPerSecond / 1024.0);
    }
    return peak;
}

/// "yes" when the strict end of the goal range is met, "partly" for the lenient end.
const char *verdict(double measured, double strict, double lenient, bool lowerIsBetter)
{
    if (measured <= 0)
        return "no data";
    const auto meets
        = [&](double goal) { return lowerIsBetter ? measured <= goal : measured >= goal; };
    return meets(strict) ? "yes" : meets(lenient) ? "partly" : "no";
}

void printTargets(const std::vector<Row> &inProcess, const std::vector<Row> &between,
                  const std::vector<Row> &tcp)
{
    std::printf("\nAgainst OpenRTM-aist 2.1 (latency: worse mean of 1 and 8 elements; peak: best "
                "size without loss)\n");
    std::printf("| figure                          | OpenRTM-aist 2.1 | goal                  | "
                "measured      | met    |\n");
    std::printf("|---------------------------------|------------------|-----------------------|----"
                "-----------|--------|\n");
    // One row: a latency (µs, lower is better) or a throughput (GiB/s); no goal where strict is 0.
    const auto row = [](const char *figure, const char *theirs, const char *goal, double measured,
                        bool latency, double strict, double lenient) {
        std::printf(latency ? "| %-31s | %-16s | %-21s | %8.1f us   | %-6s |\n"
                            : "| %-31s | %-16s | %-21s | %6.2f GiB/s  | %-6s |\n",
                    figure, theirs, goal, measured,
                    strict > 0 ? verdict(measured, strict, lenient, latency) : "-");
    };
    const char *halfLatency = "<= 22.5-38 us (1/2)";
    const char *peakGoal = ">= 1.35-1.95 GiB/s";
    row("latency, 1-8 elements, 2 procs", "45-76 us", halfLatency, smallLatency(between), true, 22.5, 38);
    row("peak throughput, 2 procs", "0.9-1.3 GiB/s", peakGoal, peakGiBPerSecond(between), false, 1.95, 1.35);
    row("latency, 2 procs, TCP only", "45-76 us", halfLatency, smallLatency(tcp), true, 22.5, 38);
    row("peak throughput, 2 procs, TCP", "0.9-1.3 GiB/s", peakGoal, peakGiBPerSecond(tcp), false, 1.95, 1.35);
    row("latency, 1-8 elements, 1 proc", "10-18 us", "-", smallLatency(inProcess), true, 0, 0);
    row("peak throughput, 1 proc", "1.7-1.8 GiB/s", ">= 8.5-9.0 GiB/s (5x)", peakGiBPerSecond(inProcess), false,
        9.0, 8.5);
    std::printf("(met: yes = the strict end of the goal range, partly = only its lenient end; \"2 procs\" is\n"
                "the runtime's default between processes on one host, a Unix socket)\n");
}

/// OpenRTM-aist's row of @p elements, or null.
const OpenRtmThroughput::Row *openRtmRow(const std::vector<OpenRtmThroughput::Row> &rows,
                                         CORBA::ULong elements)
{
    for (const OpenRtmThroughput::Row &row : rows) {
        if (row.elements == elements)
            return &row;
    }
    return nullptr;
}

/// The first component of the manager at @p port on loopback, once it has one; nil after
/// @p patience.
RTC::RTObject_ptr componentAt(CORBA::ORB_ptr orb, unsigned port, std::chrono::seconds patience)
{
    const std::string address = "corbaloc:iiop:127.0.0.1:" + std::to_string(port) + "/manager";
    const auto deadline = Clock::now() + patience;
    do {
        try {
            CORBA::Object_var object = orb->string_to_object(address.c_str());
            RTM::Manager_var manager = RTM::Manager::_narrow(object);
            RTC::RTCList_var components = manager->get_components();
            if (components->length() > 0)
                return RTC::RTObject::_duplicate(components[0]);
        } catch (const CORBA::Exception &) {
            // Not listening yet: the process is still starting.
        }
        poll(nullptr, 0, 50);
    } while (Clock::now() < deadline);
    return RTC::RTObject::_nil();
}

/// Joins two of OpenRTM-aist's Throughput examples the way its two-process script does with
/// rtcon and rtact: sender's out to receiver's in (named inDouble for doubles), then activate.
std::string connectOpenRtmExamples(CORBA::ORB_ptr orb, const OpenRtmThroughput::Ports &ports)
{
    try {
        RTC::RTObject_var from = componentAt(orb, ports.sender, std::chrono::seconds(30));
        RTC::RTObject_var to = componentAt(orb, ports.receiver, std::chrono::seconds(30));
        if (CORBA::is_nil(from) || CORBA::is_nil(to))
            return "its managers did not show a component within 30 s";
        RTC::PortService_var out = portNamed(from, "out");
        RTC::PortService_var in = portNamed(to, "inDouble");
        if (CORBA::is_nil(in))
            in = portNamed(to, "in");
        if (!connectFlush(out, in))
            return "cannot connect its ports";
        RTC::ExecutionContextList_var contexts = from->get_owned_contexts();
        if (contexts->length() == 0
            || contexts[0]->activate_component(from) != RTC::RTC_OK)
            return "cannot activate its sender";
    } catch (const CORBA::Exception &e) {
        return std::string("a call to it failed: ") + e._name();
    }
    return {};
}

/// Prints OpenRTM-aist's figures of one placement beside ours. Both MiB/s columns are the
/// payload over the mean one-way latency, as the example computes it; the targets above use ours
/// over the write interval, which counts the whole round trip of a flush write.
void printComparison(const char *placement, const std::vector<Row> &ours,
                     const OpenRtmThroughput::Run &run)
{
    std::printf("\n%s\n", placement);
    if (!run.error.empty())
        std::printf("OpenRTM-aist's example: %s\n", run.error.c_str());
    if (run.rows.empty())
        return;
    std::printf("| elements | SDK mean us | OpenRTM mean us | SDK MiB/s | OpenRTM MiB/s | ratio |\n");
    std::printf("|----------|-------------|-----------------|-----------|---------------|-------|\n");
    double ourPeak = 0, theirPeak = 0, ourSmall = -1, theirSmall = -1;
    for (const Row &row : ours) {
        const OpenRtmThroughput::Row *theirs = openRtmRow(run.rows, row.latency.elements);
        if (!row.reported || theirs == nullptr || row.latency.mean <= 0)
            continue;
        const double bytes = double(row.latency.elements) * sizeof(CORBA::Double) + 8;
        const double mibPerSecond = bytes / row.latency.mean * 1e6 / mebibyte;
        std::printf("| %8u | %11.1f | %15.1f | %9.1f | %13.1f | %5.2f |\n",
                    unsigned(row.latency.elements), row.latency.mean, theirs->meanUs,
                    mibPerSecond, theirs->mibPerSecond, mibPerSecond / theirs->mibPerSecond);
        ourPeak = std::max(ourPeak, mibPerSecond / 1024);
        theirPeak = std::max(theirPeak, theirs->mibPerSecond / 1024);
        if (row.latency.elements <= 8) {
            ourSmall = std::max(ourSmall, row.latency.mean);
            theirSmall = std::max(theirSmall, theirs->meanUs);
        }
    }
    std::printf("latency, worse mean of 1-8 elements: SDK %.1f us, OpenRTM-aist %.1f us (%.2fx)\n",
                ourSmall, theirSmall, theirSmall > 0 ? ourSmall / theirSmall : 0.0);
    std::printf("peak throughput (best size of each): SDK %.2f GiB/s, OpenRTM-aist %.2f GiB/s "
                "(%.2fx)\n",
                ourPeak, theirPeak, theirPeak > 0 ? ourPeak / theirPeak : 0.0);
}

/// Runs OpenRTM-aist's own Throughput example from @p prefix in both placements, one after the
/// other, and prints its figures beside this benchmark's.
void compareWithOpenRtm(const std::string &prefix, CORBA::ORB_ptr orb,
                        const std::vector<Row> &inProcess, const std::vector<Row> &between,
                        const std::vector<Row> &tcp)
{
    if (prefix.empty()) {
        std::printf("\nNo OpenRTM-aist prefix given (--openrtm PREFIX or OPENRTM_PREFIX): its "
                    "Throughput example was not run beside.\n");
        return;
    }
    std::printf("\nOpenRTM-aist's Throughput example from %s, run now: push / flush / corba_cdr, "
                "100 samples\nper size (sizes double from 1).\n",
                prefix.c_str());
    std::fflush(stdout);
    printComparison("(a) two components in one process",
                    inProcess,
                    OpenRtmThroughput::runSameProcess(prefix, sizes.back(), openRtmTimeoutSeconds));
    std::fflush(stdout);
    OpenRtmThroughput::Ports ports {freePort(), freePort(), freePort()};
    while (ports.receiver == ports.sender)
        ports.receiver = freePort();
    while (ports.noMaster == ports.sender || ports.noMaster == ports.receiver)
        ports.noMaster = freePort();
    const OpenRtmThroughput::Run twoProcesses = OpenRtmThroughput::runTwoProcesses(
        prefix, sizes.back(), openRtmTimeoutSeconds, ports,
        [orb](const OpenRtmThroughput::Ports &p) { return connectOpenRtmExamples(orb, p); });
    printComparison("(b) two processes, each product's default: the SDK through its Unix socket, "
                    "OpenRTM-aist over loopback TCP",
                    between, twoProcesses);
    printComparison("(c) two processes, both over loopback TCP", tcp, twoProcesses);
}

} // namespace

/// Runs @p arguments (a program and its arguments), its output passed over: true when it exited with 0.
bool runQuietly(const std::vector<std::string> &arguments)
{
    std::vector<char *> argv;
    for (const std::string &argument : arguments)
        argv.push_back(const_cast<char *>(argument.c_str()));
    argv.push_back(nullptr);
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(null, STDOUT_FILENO);
        execv(argv[0], argv.data());
        _exit(127);
    }
    close(null);
    int status = 0;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/// (d): certificates made with rtctl, then this program again as a TLS sender, which prints the table.
void measureOverTls()
{
    char folder[] = "/tmp/bench_sdkflow-XXXXXX";
    if (mkdtemp(folder) == nullptr) {
        std::printf("\ncannot make a folder for the TLS certificates\n");
        return;
    }
    const std::string fleet = std::string(folder) + "/fleet";
    if (!runQuietly({RTCTL_PATH, "tls", "init", fleet})
        || !runQuietly({RTCTL_PATH, "tls", "issue", fleet, "node", "--host", "127.0.0.1"})) {
        std::printf("\nrtctl tls could not make the certificates (%s)\n", RTCTL_PATH);
    } else {
        std::fflush(stdout);
        const pid_t pid = fork();
        if (pid == 0) {
            execl("/proc/self/exe", "bench_sdkflow", "--tls-sender", fleet.c_str(), static_cast<char *>(nullptr));
            _exit(127);
        }
        int status = 0;
        if (pid <= 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
            std::printf("\nthe TLS sender did not finish\n");
    }
    runQuietly({"/bin/rm", "-rf", folder});
}

/// This program as the sender over TLS: a manager presenting @p fleet's node certificate.
int runTlsSender(const char *program, const std::string &fleet)
{
    std::signal(SIGPIPE, SIG_IGN);
    RTC::Manager *manager = startManager(program, "127.0.0.1:", Transport::Tls, fleet);
    auto *sender = manager ? dynamic_cast<FlowSender *>(manager->createComponent("FlowSender")) : nullptr;
    if (sender == nullptr) {
        std::printf("cannot start the TLS manager or create the sending component\n");
        return 1;
    }
    measureBetweenProcesses(manager, sender, Transport::Tls, fleet);
    std::fflush(stdout);
    std::_Exit(0);
}

int main(int argc, char **argv)
{
    if ((argc == 4 || argc == 5) && std::string(argv[1]) == "--receiver") {
        const std::string word = argv[3];
        const Transport transport = word == "tls" ? Transport::Tls : word == "tcp" ? Transport::Tcp : Transport::UnixSocket;
        return runReceiver(argv[0], argv[2], transport, argc == 5 ? argv[4] : "");
    }
    if (argc == 3 && std::string(argv[1]) == "--tls-sender")
        return runTlsSender(argv[0], argv[2]);
    std::string openRtm = std::getenv("OPENRTM_PREFIX") ? std::getenv("OPENRTM_PREFIX") : "";
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::string(argv[i]) == "--openrtm")
            openRtm = argv[i + 1];
    }
    // A receiver gone while a write is under way must not end the sender.
    std::signal(SIGPIPE, SIG_IGN);
    RTC::Manager *manager = startManager(argv[0], "127.0.0.1:");
    auto *sender
        = manager ? dynamic_cast<FlowSender *>(manager->createComponent("FlowSender")) : nullptr;
    if (sender == nullptr) {
        std::printf("cannot start the manager or create the sending component\n");
        return 1;
    }
    std::printf(
        "RTC::TimedDoubleSeq, push / flush / corba_cdr, %d warm-up samples per size, then up to "
        "200\n"
        "samples (fewer above 2 MiB, or once a size took %.0f s); latency = ON_BUFFER_WRITE time - "
        "sender's time stamp;\nMiB/s = payload / mean interval of back-to-back writes; "
        "ORBgiopMaxMsgSize %s.\n",
        warmUpSamples, sizeBudgetSeconds, std::getenv("ORBgiopMaxMsgSize"));
    const std::vector<Row> inProcess = measureInProcess(manager, sender);
    const std::vector<Row> between = measureBetweenProcesses(manager, sender, Transport::UnixSocket);
    const std::vector<Row> tcp = measureBetweenProcesses(manager, sender, Transport::Tcp);
    measureOverTls();
    printTargets(inProcess, between, tcp);
    compareWithOpenRtm(openRtm, manager->getORB(), inProcess, between, tcp);
    std::fflush(stdout);
    // As in the receiver: the measurement is printed and the ORB holds nothing worth an orderly
    // end.
    std::_Exit(0);
}
