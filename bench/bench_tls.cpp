// SPDX-License-Identifier: MIT
// What TLS costs: the same name server and rtmanager master once over plain TCP and once over TLS
// (certificates made with `rtctl tls`), on loopback, measured from clients of each kind:
//   rtctl ls       one rtctl process listing the name server (start, connection set-up, one call);
//   round trip     one small remote call on a live component (get_sdo_id), mean of 2,000, on an open
//                  connection;
//   1 MiB request  a configuration set with a 1 MiB value sent to the component, MiB/s over 50 calls;
//   first call     a new connection's set-up and its first call, mean of 50 fresh client processes.
// A process is plain or TLS from its first call on, so the calls are measured by this program run
// again as a client (--client).
#include "livesystem.h"
#include "rtctlrunner.h"
#include "tlsorb.h"

#include <Manager.hh>
#include <RTC.hh>
#include <SDOPackage.hh>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>

#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr int RoundTrips = 2000;
constexpr int BulkCalls = 50;
constexpr int BulkBytes = 1 << 20;
constexpr int RtctlCalls = 20;
constexpr int FreshClients = 50;

struct Figures
{
    double rtctlMs = -1;
    double roundTripUs = -1;
    double bulkMiBPerSecond = -1;
    double firstCallMs = -1;
};

// --- the client side: one process, plain or TLS ---

RTC::RTObject_ptr component(CORBA::ORB_ptr orb, const std::string &managerAddress)
{
    CORBA::Object_var object = orb->string_to_object(managerAddress.c_str());
    RTM::Manager_var manager = RTM::Manager::_narrow(object);
    RTC::RTCList_var components = manager->get_components();
    return components->length() > 0 ? RTC::RTObject::_duplicate(components[0]) : RTC::RTObject::_nil();
}

double roundTripUs(RTC::RTObject_ptr rtc)
{
    CORBA::String_var(rtc->get_sdo_id()); // the connection is open before the clock starts
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < RoundTrips; ++i)
        CORBA::String_var(rtc->get_sdo_id());
    return double(timer.nsecsElapsed()) / 1000.0 / RoundTrips;
}

double bulkMiBPerSecond(RTC::RTObject_ptr rtc)
{
    SDOPackage::Configuration_var configuration = rtc->get_configuration();
    SDOPackage::ConfigurationSet set;
    set.id = CORBA::string_dup("bench");
    set.description = CORBA::string_dup("");
    set.configuration_data.length(1);
    set.configuration_data[0].name = CORBA::string_dup("payload");
    const std::string payload(BulkBytes, 'x');
    set.configuration_data[0].value <<= payload.c_str();
    configuration->add_configuration_set(set);
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < BulkCalls; ++i)
        configuration->set_configuration_set_values(set);
    const double seconds = double(timer.nsecsElapsed()) / 1e9;
    return double(BulkCalls) * BulkBytes / (1 << 20) / seconds;
}

/// `--client ADDRESS [CA KEY] [--first-call]`: prints one line of figures.
int runClient(int argc, char **argv)
{
    const std::string address = argv[2];
    const bool tls = argc >= 5 && std::string(argv[3]) != "--first-call";
    const bool firstCallOnly = std::string(argv[argc - 1]) == "--first-call";
    std::string error;
    CORBA::ORB_var orb = LiveTest::initOrb(argv[0], tls ? Tls::Settings {argv[3], argv[4], {}} : Tls::Settings {}, &error);
    if (CORBA::is_nil(orb)) {
        std::printf("error %s\n", error.c_str());
        return 1;
    }
    try {
        QElapsedTimer timer;
        timer.start();
        RTC::RTObject_var rtc = component(orb, address);
        if (firstCallOnly) {
            std::printf("first %.3f\n", double(timer.nsecsElapsed()) / 1e6);
            return 0;
        }
        std::printf("roundtrip %.2f\n", roundTripUs(rtc));
        std::printf("bulk %.1f\n", bulkMiBPerSecond(rtc));
    } catch (const CORBA::Exception &e) {
        std::printf("error %s%s\n", e._name(), tls ? (" " + Tls::Transport::lastFailure()).c_str() : "");
        return 1;
    }
    std::fflush(stdout);
    std::_Exit(0);
}

// --- the measuring side ---

/// Runs this program as a client and reads its `name value` lines.
bool client(const QStringList &arguments, Figures *figures, QString *error)
{
    QProcess process;
    process.start(QCoreApplication::applicationFilePath(), QStringList {"--client"} + arguments);
    if (!process.waitForFinished(120000)) {
        *error = QStringLiteral("the client did not finish");
        return false;
    }
    for (const QString &line : QString::fromLocal8Bit(process.readAllStandardOutput()).split('\n')) {
        const QStringList parts = line.split(' ');
        if (parts.value(0) == QLatin1String("roundtrip"))
            figures->roundTripUs = parts.value(1).toDouble();
        else if (parts.value(0) == QLatin1String("bulk"))
            figures->bulkMiBPerSecond = parts.value(1).toDouble();
        else if (parts.value(0) == QLatin1String("first"))
            figures->firstCallMs = parts.value(1).toDouble();
        else if (parts.value(0) == QLatin1String("error"))
            *error = line;
    }
    return error->isEmpty();
}

struct System
{
    LiveTest::LiveSystem live;
    quint16 managerPort = 0;
};

bool startSystem(System &system, const QStringList &tlsOptions, const QString &ca, const QString &key, QString *error)
{
    const bool ok = tlsOptions.isEmpty() ? system.live.startNameServer(error)
                                         : system.live.startTlsNameServer(ca, key, error);
    if (!ok)
        return false;
    system.managerPort = LiveTest::freePort();
    return system.live.startManager(QStringLiteral(RTMANAGER_PATH), system.managerPort,
                                    QStringList {"corba.nameservers=" + system.live.namingServer(),
                                                 "manager.components.precreate=ConsoleIn", "corba.unix_socket=NO"}
                                        + tlsOptions,
                                    error);
}

Figures measure(System &system, const QStringList &clientTls, const QHash<QString, QString> &rtctlEnvironment,
                const QString &scheme, QString *error)
{
    Figures figures;
    const QString address = QStringLiteral("corbaloc:") + scheme + QStringLiteral("127.0.0.1:%1/manager").arg(system.managerPort);
    // rtctl as a user runs it: a process per command.
    const QString root = QLatin1Char('/') + system.live.namingServer();
    runRtctl({"ls", "-R", root}, rtctlEnvironment);
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < RtctlCalls; ++i) {
        const RtctlResult r = runRtctl({"ls", root}, rtctlEnvironment);
        if (r.code != 0) {
            *error = r.err;
            return figures;
        }
    }
    figures.rtctlMs = double(timer.nsecsElapsed()) / 1e6 / RtctlCalls;
    if (!client(QStringList {address} + clientTls, &figures, error))
        return figures;
    double firstTotal = 0;
    for (int i = 0; i < FreshClients; ++i) {
        Figures one;
        if (!client(QStringList {address} + clientTls + QStringList {"--first-call"}, &one, error))
            return figures;
        firstTotal += one.firstCallMs;
    }
    figures.firstCallMs = firstTotal / FreshClients;
    return figures;
}

void printRow(const char *transport, const Figures &f)
{
    std::printf("| %-24s | %11.2f | %13.1f | %13.2f | %19.1f |\n", transport, f.rtctlMs, f.roundTripUs,
                f.firstCallMs, f.bulkMiBPerSecond);
}

} // namespace

int main(int argc, char **argv)
{
    if (argc >= 3 && std::string(argv[1]) == "--client")
        return runClient(argc, argv);
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    const QString authority = dir.filePath(QStringLiteral("ca"));
    for (const QStringList &step : QList<QStringList> {{"tls", "init", authority},
                                                       {"tls", "issue", authority, "node", "--host", "127.0.0.1"},
                                                       {"tls", "issue", authority, "operator"}}) {
        const RtctlResult r = runRtctl(step);
        if (r.code != 0) {
            std::printf("rtctl %s failed: %s\n", qPrintable(step.join(' ')), qPrintable(r.err));
            return 1;
        }
    }
    const QString ca = authority + QStringLiteral("/ca.pem");
    const QString node = authority + QStringLiteral("/node.pem");
    const QString user = authority + QStringLiteral("/operator.pem");
    const QHash<QString, QString> noLocalRuntime {{"XDG_RUNTIME_DIR", dir.path()}};

    QString error;
    System plain;
    if (!startSystem(plain, {}, {}, {}, &error)) {
        std::printf("cannot start the plain system: %s\n", qPrintable(error));
        return 1;
    }
    const Figures plainFigures = measure(plain, {}, noLocalRuntime, QStringLiteral("iiop:1.2@"), &error);
    if (!error.isEmpty()) {
        std::printf("plain TCP: %s\n", qPrintable(error));
        return 1;
    }
    System secure;
    if (!startSystem(secure, {"corba.ssl.certificate_authority_file=" + ca, "corba.ssl.key_file=" + node}, ca, node,
                     &error)) {
        std::printf("cannot start the TLS system: %s\n", qPrintable(error));
        return 1;
    }
    QHash<QString, QString> tlsEnvironment = noLocalRuntime;
    tlsEnvironment.insert("RTSTUDIO_TLS_CA", ca);
    tlsEnvironment.insert("RTSTUDIO_TLS_KEY", user);
    const Figures tlsFigures = measure(secure, {ca, user}, tlsEnvironment, QStringLiteral("ssliop:"), &error);
    if (!error.isEmpty()) {
        std::printf("TLS: %s\n", qPrintable(error));
        return 1;
    }

    std::printf("Loopback, one name server and one rtmanager master per transport; P-256 EC certificates.\n"
                "rtctl ls: mean of %d processes; round trip: get_sdo_id on an open connection, mean of %d;\n"
                "first call: connection set-up and one call in a fresh process, mean of %d; 1 MiB request:\n"
                "set_configuration_set_values with a 1 MiB value, %d calls.\n\n",
                RtctlCalls, RoundTrips, FreshClients, BulkCalls);
    std::printf("| transport                | rtctl ls ms | round trip us | first call ms | 1 MiB request MiB/s |\n");
    std::printf("|--------------------------|-------------|---------------|---------------|---------------------|\n");
    printRow("plain TCP", plainFigures);
    printRow("TLS (client certificate)", tlsFigures);
    std::printf("\nTLS / plain: rtctl ls %.2fx, round trip %.2fx, first call %.2fx, 1 MiB request %.2fx\n",
                tlsFigures.rtctlMs / plainFigures.rtctlMs, tlsFigures.roundTripUs / plainFigures.roundTripUs,
                tlsFigures.firstCallMs / plainFigures.firstCallMs,
                tlsFigures.bulkMiBPerSecond / plainFigures.bulkMiBPerSecond);
    return 0;
}
