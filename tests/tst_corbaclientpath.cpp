// SPDX-License-Identifier: MIT
#include "iorendpoint.h"
#include "rtpath.h"

#include <QSysInfo>
#include <QTest>

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>

using Corba::RtPath;

// rtshell path syntax: servers, contexts, objects, ports, '.', '..', relative paths, corbaloc.
class TestCorbaClientPath : public QObject
{
    Q_OBJECT

private slots:
    void parses_data();
    void parses();
    void rejects_data();
    void rejects();
    void nameServiceAddress_data();
    void nameServiceAddress();
    void corbalocAsksForGiop12_data();
    void corbalocAsksForGiop12();
    void referenceHost_data();
    void referenceHost();
    void isThisHost_data();
    void isThisHost();
    void isThisHostKnowsInterfaceAddresses();
};

void TestCorbaClientPath::parses_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("cwd");
    QTest::addColumn<QStringList>("elements");
    QTest::addColumn<QString>("port");
    QTest::addColumn<QString>("corbaloc");
    QTest::addColumn<QString>("printed");

    const QString none;
    QTest::newRow("root") << "/" << none << QStringList() << none << none << "/";
    QTest::newRow("server") << "/localhost" << none << QStringList {"localhost"} << none << none
                            << "/localhost";
    QTest::newRow("server with port is no port suffix")
        << "/localhost:2809" << none << QStringList {"localhost:2809"} << none << none
        << "/localhost:2809";
    QTest::newRow("component") << "/localhost/myhost.host_cxt/ConsoleIn0.rtc" << none
                               << QStringList {"localhost", "myhost.host_cxt", "ConsoleIn0.rtc"}
                               << none << none << "/localhost/myhost.host_cxt/ConsoleIn0.rtc";
    QTest::newRow("port") << "/localhost:2809/h.host_cxt/ConsoleIn0.rtc:out" << none
                          << QStringList {"localhost:2809", "h.host_cxt", "ConsoleIn0.rtc"} << "out"
                          << none << "/localhost:2809/h.host_cxt/ConsoleIn0.rtc:out";
    QTest::newRow("trailing slash")
        << "/localhost/h.host_cxt/" << none << QStringList {"localhost", "h.host_cxt"} << none
        << none << "/localhost/h.host_cxt";
    QTest::newRow("double slash") << "//localhost//h.host_cxt" << none
                                  << QStringList {"localhost", "h.host_cxt"} << none << none
                                  << "/localhost/h.host_cxt";
    QTest::newRow("dot") << "/localhost/./h.host_cxt/." << none
                         << QStringList {"localhost", "h.host_cxt"} << none << none
                         << "/localhost/h.host_cxt";
    QTest::newRow("dotdot") << "/localhost/h.host_cxt/../other.host_cxt" << none
                            << QStringList {"localhost", "other.host_cxt"} << none << none
                            << "/localhost/other.host_cxt";
    QTest::newRow("dotdot above root stays at root")
        << "/../.." << none << QStringList() << none << none << "/";
    QTest::newRow("relative") << "C0.rtc:in"
                              << "/localhost/h.host_cxt"
                              << QStringList {"localhost", "h.host_cxt", "C0.rtc"} << "in" << none
                              << "/localhost/h.host_cxt/C0.rtc:in";
    QTest::newRow("relative dotdot")
        << "../x.host_cxt/C0.rtc"
        << "/localhost/h.host_cxt" << QStringList {"localhost", "x.host_cxt", "C0.rtc"} << none
        << none << "/localhost/x.host_cxt/C0.rtc";
    QTest::newRow("relative from root")
        << "localhost" << none << QStringList {"localhost"} << none << none << "/localhost";
    QTest::newRow("dot is the cwd")
        << "."
        << "/localhost/h.host_cxt" << QStringList {"localhost", "h.host_cxt"} << none << none
        << "/localhost/h.host_cxt";
    QTest::newRow("absolute ignores cwd") << "/a"
                                          << "/b/c" << QStringList {"a"} << none << none << "/a";
    QTest::newRow("manager in tree") << "/localhost/h.host_cxt/manager.mgr" << none
                                     << QStringList {"localhost", "h.host_cxt", "manager.mgr"}
                                     << none << none << "/localhost/h.host_cxt/manager.mgr";
    QTest::newRow("corbaloc short") << "corbaloc::myhost" << none << QStringList() << none
                                    << "corbaloc:iiop:myhost:2810/manager"
                                    << "corbaloc:iiop:myhost:2810/manager";
    QTest::newRow("corbaloc port") << "corbaloc::127.0.0.1:4321" << none << QStringList() << none
                                   << "corbaloc:iiop:127.0.0.1:4321/manager"
                                   << "corbaloc:iiop:127.0.0.1:4321/manager";
    QTest::newRow("corbaloc full") << "corbaloc:iiop:h:2810/manager" << none << QStringList()
                                   << none << "corbaloc:iiop:h:2810/manager"
                                   << "corbaloc:iiop:h:2810/manager";
    QTest::newRow("corbaloc other key")
        << "corbaloc::h:1/other" << none << QStringList() << none << "corbaloc:iiop:h:1/other"
        << "corbaloc:iiop:h:1/other";
    // Each address of a list gets the default port; a GIOP version and IPv6 brackets stay.
    QTest::newRow("corbaloc several") << "corbaloc::a,iiop:b:2/k" << none << QStringList() << none
                                      << "corbaloc:iiop:a:2810,iiop:b:2/k"
                                      << "corbaloc:iiop:a:2810,iiop:b:2/k";
    QTest::newRow("corbaloc version")
        << "corbaloc:iiop:1.2@h/x" << none << QStringList() << none << "corbaloc:iiop:1.2@h:2810/x"
        << "corbaloc:iiop:1.2@h:2810/x";
    QTest::newRow("corbaloc IPv6")
        << "corbaloc::[::1]" << none << QStringList() << none << "corbaloc:iiop:[::1]:2810/manager"
        << "corbaloc:iiop:[::1]:2810/manager";
    QTest::newRow("corbaloc IPv6 port") << "corbaloc::[fe80::1]:5/" << none << QStringList() << none
                                        << "corbaloc:iiop:[fe80::1]:5/manager"
                                        << "corbaloc:iiop:[fe80::1]:5/manager";
}

void TestCorbaClientPath::parses()
{
    QFETCH(QString, text);
    QFETCH(QString, cwd);
    QFETCH(QStringList, elements);
    QFETCH(QString, port);
    QFETCH(QString, corbaloc);
    QFETCH(QString, printed);
    QString error;
    const auto path = RtPath::parse(text, cwd, &error);
    QVERIFY2(path.has_value(), qPrintable(error));
    QCOMPARE(path->elements, elements);
    QCOMPARE(path->port, port);
    QCOMPARE(path->corbaloc, corbaloc);
    QCOMPARE(path->toString(), printed);
    QCOMPARE(path->isDirect(), !corbaloc.isEmpty());
    // Printing and parsing again gives the same path.
    const auto again = RtPath::parse(path->toString());
    QVERIFY(again.has_value());
    QCOMPARE(*again, *path);
}

void TestCorbaClientPath::rejects_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("cwd");
    QTest::addColumn<QString>("reason");
    QTest::newRow("empty port") << "/localhost/h.host_cxt/C0.rtc:" << QString() << "empty";
    QTest::newRow("empty object") << "/localhost/h.host_cxt/:out" << QString() << "empty";
    QTest::newRow("bad server port") << "/localhost:abc/x" << QString() << "name server";
    QTest::newRow("server port out of range") << "/localhost:70000" << QString() << "name server";
    QTest::newRow("relative cwd") << "x"
                                  << "relative/cwd"
                                  << "not absolute";
    QTest::newRow("corbaloc protocol") << "corbaloc:rir:/NameService" << QString() << "protocol";
    QTest::newRow("corbaloc port") << "corbaloc::h:zz/manager" << QString() << "bad host";
    QTest::newRow("corbaloc host") << "corbaloc:::2810" << QString() << "bad host";
    QTest::newRow("corbaloc second protocol") << "corbaloc::h,rir:/x" << QString() << "protocol";
    QTest::newRow("corbaloc second port") << "corbaloc::h,:g:0/x" << QString() << "bad host";
    QTest::newRow("corbaloc empty port") << "corbaloc::h:/x" << QString() << "bad host";
    QTest::newRow("corbaloc IPv6 port") << "corbaloc::[::1]x/x" << QString() << "bad host";
    QTest::newRow("corbaloc no protocol") << "corbaloc:h/x" << QString() << "protocol";
}

void TestCorbaClientPath::rejects()
{
    QFETCH(QString, text);
    QFETCH(QString, cwd);
    QFETCH(QString, reason);
    QString error;
    const auto path = RtPath::parse(text, cwd, &error);
    QVERIFY(!path.has_value());
    QVERIFY2(error.contains(reason), qPrintable(error));
}

void TestCorbaClientPath::nameServiceAddress_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("address");
    QTest::newRow("default port") << "/localhost/x"
                                  << "corbaloc:iiop:localhost:2809/NameService";
    QTest::newRow("given port") << "/127.0.0.1:5005"
                                << "corbaloc:iiop:127.0.0.1:5005/NameService";
}

void TestCorbaClientPath::nameServiceAddress()
{
    QFETCH(QString, text);
    QFETCH(QString, address);
    const auto path = RtPath::parse(text);
    QVERIFY(path.has_value());
    QCOMPARE(path->nameServiceAddress(), address);
}

void TestCorbaClientPath::corbalocAsksForGiop12_data()
{
    QTest::addColumn<QString>("reference");
    QTest::addColumn<QString>("sent");
    QTest::newRow("iiop") << "corbaloc:iiop:127.0.0.1:2809/NameService"
                          << "corbaloc:iiop:1.2@127.0.0.1:2809/NameService";
    QTest::newRow("empty protocol") << "corbaloc::host:2810/manager"
                                    << "corbaloc::1.2@host:2810/manager";
    QTest::newRow("no key") << "corbaloc:iiop:host" << "corbaloc:iiop:1.2@host";
    QTest::newRow("several addresses") << "corbaloc:iiop:a:1,:1.0@b:2,iiop:c:3/k"
                                       << "corbaloc:iiop:1.2@a:1,:1.0@b:2,iiop:1.2@c:3/k";
    QTest::newRow("own version") << "corbaloc:iiop:1.1@host:2809/k" << "corbaloc:iiop:1.1@host:2809/k";
    QTest::newRow("key with @ and :") << "corbaloc:iiop:host:1/a@b:c" << "corbaloc:iiop:1.2@host:1/a@b:c";
    QTest::newRow("rir") << "corbaloc:rir:/NameService" << "corbaloc:rir:/NameService";
    QTest::newRow("corbaname") << "corbaname::host:2809#a/b" << "corbaname::host:2809#a/b";
    QTest::newRow("IOR") << "IOR:0100" << "IOR:0100";
}

void TestCorbaClientPath::corbalocAsksForGiop12()
{
    QFETCH(QString, reference);
    QFETCH(QString, sent);
    QCOMPARE(Corba::corbalocWithGiop12(reference), sent);
}

// rtctl mgr sends creates side by side two at a time to a manager on this machine, eight to one
// elsewhere: which host a reference points at, and whether that is this machine.
void TestCorbaClientPath::referenceHost_data()
{
    QTest::addColumn<QString>("reference");
    QTest::addColumn<QString>("host");
    // An IOR with one IIOP 1.2 profile for 203.0.113.9:2810 (object key "key", no components).
    QTest::newRow("IOR")
        << "IOR:"
           "010000003500000049444c3a6f70656e72746d2e616973742e676f2e6a702f4f70656e52544d2f446174614"
           "66c6f77436f6d706f6e656e743a312e3000000000010000000000000024000000010102000c000000323033"
           "2e302e3131332e3900fa0a0000030000006b65790000000000"
        << "203.0.113.9";
    QTest::newRow("normalised corbaloc") << "corbaloc:iiop:127.0.0.1:12810/manager"
                                         << "127.0.0.1";
    QTest::newRow("GIOP version") << "corbaloc:iiop:1.2@somehost:2810/manager"
                                  << "somehost";
    QTest::newRow("empty protocol, no port") << "corbaloc::somehost/manager"
                                             << "somehost";
    QTest::newRow("IPv6") << "corbaloc:iiop:1.2@[::1]:2810/manager"
                          << "::1";
    QTest::newRow("first of several") << "corbaloc:iiop:a:1,iiop:b:2/k"
                                      << "a";
    QTest::newRow("rir") << "corbaloc:rir:/NameService" << QString();
    QTest::newRow("scheme in capitals") << "CORBALOC::host:2810/manager"
                                        << "host";
    QTest::newRow("unreadable IOR") << "IOR:0102" << QString();
    QTest::newRow("no reference") << "manager.mgr" << QString();
}

void TestCorbaClientPath::referenceHost()
{
    QFETCH(QString, reference);
    QFETCH(QString, host);
    QCOMPARE(Corba::referenceHost(reference), host);
}

void TestCorbaClientPath::isThisHost_data()
{
    QTest::addColumn<QString>("host");
    QTest::addColumn<bool>("local");
    QTest::newRow("localhost") << "localhost" << true;
    QTest::newRow("LOCALHOST") << "LOCALHOST" << true;
    QTest::newRow("loopback") << "127.0.0.1" << true;
    QTest::newRow("other loopback") << "127.1.2.3" << true;
    QTest::newRow("IPv6 loopback") << "::1" << true;
    QTest::newRow("host name") << QSysInfo::machineHostName() << true;
    QTest::newRow("documentation address") << "203.0.113.9" << false;
    QTest::newRow("IPv6 documentation address") << "2001:db8::9" << false;
    QTest::newRow("other name") << "no-such-host.invalid" << false;
    QTest::newRow("empty") << QString() << false;
}

void TestCorbaClientPath::isThisHost()
{
    QFETCH(QString, host);
    QFETCH(bool, local);
    QCOMPARE(Corba::isThisHost(host), local);
}

void TestCorbaClientPath::isThisHostKnowsInterfaceAddresses()
{
    // A manager listening on every interface publishes one of their addresses in its references.
    ifaddrs *interfaces = nullptr;
    QCOMPARE(getifaddrs(&interfaces), 0);
    QStringList addresses;
    for (const ifaddrs *i = interfaces; i; i = i->ifa_next) {
        char text[INET6_ADDRSTRLEN] = {};
        if (i->ifa_addr && i->ifa_addr->sa_family == AF_INET)
            inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in *>(i->ifa_addr)->sin_addr, text,
                      sizeof text);
        else if (i->ifa_addr && i->ifa_addr->sa_family == AF_INET6)
            inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6 *>(i->ifa_addr)->sin6_addr,
                      text, sizeof text);
        if (text[0])
            addresses << QString::fromLatin1(text);
    }
    freeifaddrs(interfaces);
    QVERIFY(!addresses.isEmpty());
    for (const QString &address : std::as_const(addresses))
        QVERIFY2(Corba::isThisHost(address), qPrintable(address));
}

QTEST_GUILESS_MAIN(TestCorbaClientPath)
#include "tst_corbaclientpath.moc"
