// SPDX-License-Identifier: MIT
#include "iorendpoint.h"
#include "rtpath.h"

#include <QTest>

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
    void corbalocOverTls_data();
    void corbalocOverTls();
    void tlsServersEndpointIsItsTlsPort();
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
    // What corbaloc's grammar does not have is refused, so that what is accepted prints back the same.
    QTest::newRow("corbaloc empty version") << "corbaloc::@@h/x" << QString() << "GIOP version";
    QTest::newRow("corbaloc bad version") << "corbaloc:iiop:one@h/x" << QString() << "GIOP version";
    QTest::newRow("corbaloc host character") << "corbaloc::h$st/x" << QString() << "bad host";
    QTest::newRow("corbaloc tab in key") << "corbaloc::h/a\tb" << QString()
                                         << "character U+0009 at position 14";
    QTest::newRow("corbaloc NUL") << QStringLiteral("corbaloc::h\0/x") << QString()
                                  << "character U+0000 at position 12";
    QTest::newRow("corbaloc invalid UTF-8")
        << QString::fromUtf8("corbaloc::\x98h") << QString() << "character U+fffd at position 11";
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

void TestCorbaClientPath::corbalocOverTls_data()
{
    QTest::addColumn<QString>("reference");
    QTest::addColumn<QString>("sent");
    QTest::newRow("iiop") << "corbaloc:iiop:127.0.0.1:2809/NameService" << "corbaloc:ssliop:127.0.0.1:2809/NameService";
    QTest::newRow("empty protocol") << "corbaloc::host:2810/manager" << "corbaloc:ssliop:host:2810/manager";
    QTest::newRow("version dropped") << "corbaloc:iiop:1.2@host:1/k" << "corbaloc:ssliop:host:1/k";
    QTest::newRow("several addresses") << "corbaloc:iiop:a:1,:b:2/k" << "corbaloc:ssliop:a:1,ssliop:b:2/k";
    QTest::newRow("ssliop already") << "corbaloc:ssliop:host:1/k" << "corbaloc:ssliop:host:1/k";
    QTest::newRow("rir") << "corbaloc:rir:/NameService" << "corbaloc:rir:/NameService";
    QTest::newRow("IOR") << "IOR:0100" << "IOR:0100";
}

void TestCorbaClientPath::corbalocOverTls()
{
    QFETCH(QString, reference);
    QFETCH(QString, sent);
    QCOMPARE(Corba::corbalocOverTls(reference), sent);
}

void TestCorbaClientPath::tlsServersEndpointIsItsTlsPort()
{
    // omniNames serving on giop:ssl:127.0.0.1:2809 only: its IIOP profile says port 0, the
    // TAG_SSL_SEC_TRANS component 2809 (0x0af9).
    const QString ior = QStringLiteral(
        "IOR:010000002b00000049444c3a6f6d672e6f72672f436f734e616d696e672f4e616d696e67436f6e746578744578743a312e3000"
        "0001000000000000007c000000010102000a0000003132372e302e302e310000000b0000004e616d655365727669636500040000"
        "0000000000080000000100000000545441010000001c000000010000000100010001000000010001050901010001000000090101"
        "001400000008000000010066006600f90a03545441080000000b2b0c6b010002d3");
    QCOMPARE(Corba::iorEndpoint(ior), QStringLiteral("127.0.0.1:2809"));
    // Cut inside the components: no endpoint rather than a wrong one.
    QCOMPARE(Corba::iorEndpoint(ior.left(ior.size() - 40)), QString());
}

QTEST_GUILESS_MAIN(TestCorbaClientPath)
#include "tst_corbaclientpath.moc"
