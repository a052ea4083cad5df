// SPDX-License-Identifier: MIT
// Component creation through RTM::Manager::create_component on a real rtmanager: 1, 10 and 1,000
// components in the manager's own process and 1 and 10 in separate (newly spawned slave) processes.
// Targets: ≤ 1 ms per component in the same process, ≤ 10 ms per component in separate processes.
// Naming is off so the table shows creation itself; run with --naming HOST:PORT to include it.
#include <Manager.hh>
#include <omniORB4/omniORB.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QTextStream>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <vector>

namespace {

constexpr int Runs = 3;

quint16 freePort()
{
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    quint16 port = 0;
    if (bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0
        && getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length) == 0)
        port = ntohs(address.sin_port);
    close(fd);
    return port;
}

/// One fresh master per measurement, killed afterwards (its slaves follow it).
class Master
{
public:
    Master(CORBA::ORB_ptr orb, const QString &naming)
    {
        const quint16 port = freePort();
        QStringList args = {"-d", "-o", QString("corba.endpoints=127.0.0.1:%1").arg(port)};
        args << "-o" << (naming.isEmpty() ? QString("naming.enable=NO") : "corba.nameservers=" + naming);
        m_process.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        m_process.start(QStringLiteral(RTMANAGER_PATH), args);
        QByteArray output;
        while (!output.contains("rtmanager ready") && m_process.waitForReadyRead(20000))
            output += m_process.readAllStandardOutput();
        CORBA::Object_var object =
            orb->string_to_object(QString("corbaloc:iiop:127.0.0.1:%1/manager").arg(port).toUtf8().constData());
        m_manager = RTM::Manager::_narrow(object);
    }
    ~Master()
    {
        m_process.kill();
        m_process.waitForFinished(10000);
    }
    RTM::Manager_ptr manager() { return m_manager.in(); }

private:
    QProcess m_process;
    RTM::Manager_var m_manager;
};

/// Milliseconds per component for creating @p count components; negative when a creation failed.
double measure(CORBA::ORB_ptr orb, const QString &naming, int count, bool separate)
{
    double best = -1;
    for (int run = 0; run < Runs; ++run) {
        Master master(orb, naming);
        QElapsedTimer timer;
        timer.start();
        for (int i = 0; i < count; ++i) {
            const QString request = separate ? QString("ConsoleIn?manager_name=bench%1").arg(i)
                                             : QString("ConsoleIn");
            RTC::RTObject_var created = master.manager()->create_component(request.toUtf8().constData());
            if (CORBA::is_nil(created))
                return -1;
        }
        const double perComponent = double(timer.nsecsElapsed()) / 1e6 / count;
        best = best < 0 ? perComponent : std::min(best, perComponent);
    }
    return best;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QString naming;
    const QStringList args = app.arguments();
    const int namingIndex = int(args.indexOf("--naming"));
    if (namingIndex >= 0 && namingIndex + 1 < args.size())
        naming = args.at(namingIndex + 1);
    int orbArgc = 0;
    CORBA::ORB_var orb = CORBA::ORB_init(orbArgc, nullptr);
    omniORB::setClientCallTimeout(30000);

    QTextStream out(stdout);
    out << "rtmanager create_component, best of " << Runs << " runs"
        << (naming.isEmpty() ? ", naming off" : ", naming on " + naming) << "\n\n";
    out << QString("%1 %2 %3 %4\n").arg("placement", -20).arg("components", 10).arg("ms/component", 13).arg("target", 8);
    for (bool separate : {false, true}) {
        // 1,000 in one process: a create's cost must not grow with the components already hosted.
        for (int count : separate ? std::vector<int> {1, 10} : std::vector<int> {1, 10, 1000}) {
            const double ms = measure(orb, naming, count, separate);
            out << QString("%1 %2 %3 %4\n")
                       .arg(separate ? "separate processes" : "same process", -20)
                       .arg(count, 10)
                       .arg(ms < 0 ? QString("failed") : QString::number(ms, 'f', 3), 13)
                       .arg(separate ? "<= 10" : "<= 1", 8);
            out.flush();
        }
    }
    orb->destroy();
    return 0;
}
