// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "corbaerror.h"
#include "errorof.h"
#include "namingbrowser.h"
#include "orb.h"
#include "roguereference.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTest>
#include <QtEndian>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <functional>
#include <mutex>
#include <thread>

using namespace Corba;
using LiveTest::kindOf;
using LiveTest::messageOf;

// The client library against peers that are not what they claim: servers answering with
// garbage, silence, or object references that do not decode.
class TestCorbaClientHostile : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void nameServerSpeakingGarbage_data();
    void nameServerSpeakingGarbage();
    void undecodableReferencesLeaveNoTrace();
    void typedUndecodableReferenceIsRefused();
};

namespace {

/**
 * A loopback TCP server standing in for a name server. It hands each connection it accepts, one
 * after another, to a handler on its own thread, which returns true to leave the connection open
 * (and silent) until the server is destroyed. It serves until destroyed.
 */
class FakeServer
{
public:
    using Handler = std::function<bool(int client)>;

    explicit FakeServer(Handler handler)
        : m_handler(std::move(handler))
    {
        m_socket = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address {};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        if (::bind(m_socket, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0
            && ::listen(m_socket, 8) == 0
            && ::getsockname(m_socket, reinterpret_cast<sockaddr *>(&address), &length) == 0)
            m_port = ntohs(address.sin_port);
        m_thread = std::thread([this] { serve(); });
    }
    ~FakeServer()
    {
        m_stopping = true;
        ::shutdown(m_socket, SHUT_RDWR);
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            if (m_current >= 0)
                ::shutdown(m_current, SHUT_RDWR);
        }
        m_thread.join();
        ::close(m_socket);
        for (int client : m_silent)
            ::close(client);
    }
    quint16 port() const { return m_port; }

    /// Answers each connection's first bytes with @p reply and closes it; an empty @p reply keeps
    /// the connection open and says nothing.
    static Handler replying(const QByteArray &reply)
    {
        return [reply](int client) {
            char request[4096];
            if (::recv(client, request, sizeof request, 0) <= 0 || reply.isEmpty())
                return true;
            ::send(client, reply.constData(), size_t(reply.size()), MSG_NOSIGNAL);
            return false;
        };
    }

private:
    void serve()
    {
        while (!m_stopping) {
            const int client = ::accept(m_socket, nullptr, nullptr);
            if (client < 0)
                return;
            {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_current = client;
            }
            const bool keep = m_handler(client);
            std::lock_guard<std::mutex> lock(m_mutex);
            m_current = -1;
            if (keep)
                m_silent.push_back(client);
            else
                ::close(client);
        }
    }

    Handler m_handler;
    int m_socket = -1;
    quint16 m_port = 0;
    std::atomic<bool> m_stopping {false};
    std::mutex m_mutex;
    int m_current = -1;
    std::vector<int> m_silent;
    std::thread m_thread;
};

bool readFully(int client, char *to, size_t size)
{
    while (size > 0) {
        const ssize_t got = ::recv(client, to, size, 0);
        if (got <= 0)
            return false;
        to += got;
        size -= size_t(got);
    }
    return true;
}

/// A GIOP 1.2 reply (little endian) to request @p requestId with @p status, its body written by @p body.
QByteArray giopReply(quint32 requestId, quint32 status, const std::function<void(QByteArray &)> &body)
{
    QByteArray message("GIOP\1\2\1\1", 8); // GIOP 1.2, little endian, Reply
    LiveTest::appendCdrULong(message, 0); // the size, written below
    LiveTest::appendCdrULong(message, requestId);
    LiveTest::appendCdrULong(message, status);
    LiveTest::appendCdrULong(message, 0); // no service contexts
    // The header ends on an 8-octet boundary, where a GIOP 1.2 body starts.
    body(message);
    qToLittleEndian(quint32(message.size() - 12), message.data() + 8);
    return message;
}

/**
 * A name server that narrows as one and answers every `resolve` with a reference whose profile
 * does not decode, carrying @p padding bytes; other operations get BAD_OPERATION. Speaks GIOP 1.2
 * only (what the client library asks for) and counts the references it sent in @p sent.
 */
FakeServer::Handler rogueNameServer(int padding, std::atomic<int> *sent)
{
    return [padding, sent](int client) {
        QByteArray header(12, '\0');
        while (readFully(client, header.data(), 12)) {
            const bool little = header.at(6) & 1;
            const auto uLong = [little](const QByteArray &bytes, qsizetype at) {
                const auto *p = bytes.constData() + at;
                return little ? qFromLittleEndian<quint32>(p) : qFromBigEndian<quint32>(p);
            };
            QByteArray message = header + QByteArray(qsizetype(uLong(header, 8)), '\0');
            if (!header.startsWith("GIOP\1\2") || !readFully(client, message.data() + 12, message.size() - 12))
                return false;
            if (message.at(7) != 0 || message.size() < 32) // only Requests are answered
                continue;
            const quint32 requestId = uLong(message, 12);
            const bool responseExpected = message.at(16) & 3;
            // After the target's discriminator (a short at 20, KeyAddr): the object key, then the operation.
            const quint32 keyLength = uLong(message, 24);
            const qsizetype operationAt = (28 + qsizetype(keyLength) + 3) / 4 * 4;
            if (operationAt + 4 > message.size())
                return false;
            const QByteArray operation = message.mid(operationAt + 4, qsizetype(uLong(message, operationAt)) - 1);
            QByteArray reply;
            if (operation == "_is_a") {
                reply = giopReply(requestId, 0, [](QByteArray &body) { body.append('\1'); });
            } else if (operation == "resolve") {
                reply = giopReply(requestId, 0, [padding](QByteArray &body) {
                    LiveTest::appendUndecodableReference(body, padding);
                });
                ++*sent;
            } else {
                reply = giopReply(requestId, 2, [](QByteArray &body) {
                    const QByteArray id("IDL:omg.org/CORBA/BAD_OPERATION:1.0");
                    LiveTest::appendCdrULong(body, quint32(id.size() + 1));
                    body.append(id).append('\0');
                    LiveTest::appendCdrULong(body, 0); // minor
                    LiveTest::appendCdrULong(body, 1); // COMPLETED_NO
                });
            }
            if (responseExpected && ::send(client, reply.constData(), size_t(reply.size()), MSG_NOSIGNAL) < 0)
                return false;
        }
        return false;
    };
}

} // namespace

void TestCorbaClientHostile::initTestCase()
{
    Orb::setCallTimeout(2000);
}

void TestCorbaClientHostile::nameServerSpeakingGarbage_data()
{
    QTest::addColumn<QByteArray>("reply");
    QTest::addColumn<int>("kind");
    QTest::newRow("http") << QByteArray("HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n")
                          << int(Error::Kind::CommFailure);
    // A GIOP header announcing a reply far longer than what follows.
    QTest::newRow("truncated giop") << QByteArray("GIOP\x01\x02\x01\x01\xff\xff\x00\x00\x00\x00", 14)
                                    << int(Error::Kind::CommFailure);
    QTest::newRow("random bytes") << QByteArray(64, '\xa5') << int(Error::Kind::CommFailure);
    QTest::newRow("silent") << QByteArray() << int(Error::Kind::Timeout);
}

void TestCorbaClientHostile::nameServerSpeakingGarbage()
{
    // Whatever a server at a name server's address sends, a listing ends within the call timeout
    // with a typed error naming the server, and a tree of the root shows it as a zombie.
    QFETCH(QByteArray, reply);
    QFETCH(int, kind);
    FakeServer server(FakeServer::replying(reply));
    QVERIFY(server.port() != 0);
    const int timeout = 700;
    Orb::setCallTimeout(timeout);
    struct Restore
    {
        ~Restore() { Orb::setCallTimeout(2000); }
    } restore;
    const QString address = QStringLiteral("127.0.0.1:%1").arg(server.port());
    QElapsedTimer timer;
    timer.start();
    const Error::Kind got = kindOf([&] { NamingBrowser::list(*RtPath::parse('/' + address)); });
    QVERIFY2(timer.elapsed() < timeout + 1500, qPrintable(QString::number(timer.elapsed())));
    QVERIFY2(int(got) == kind || (kind == int(Error::Kind::CommFailure) && got == Error::Kind::System),
             qPrintable(Error::kindName(got)));
    QVERIFY(messageOf([&] { NamingBrowser::list(*RtPath::parse('/' + address)); }).contains(address));
    const NamingNode root = NamingBrowser::tree(*RtPath::parse("/"), 2, {address});
    QCOMPARE(root.children.at(0).type, NodeType::Zombie);
}

// omniORB 4.2.5 refuses a reply carrying a reference whose profile does not decode with MARSHAL,
// and loses the reference with every byte of its profile: a server answering so could grow a
// long-running rtstudio's memory without end. The client takes such a reference as one to no
// object instead.
void TestCorbaClientHostile::undecodableReferencesLeaveNoTrace()
{
    std::atomic<int> sent {0};
    FakeServer server(rogueNameServer(128 * 1024, &sent));
    QVERIFY(server.port() != 0);
    const RtPath path = *RtPath::parse(QStringLiteral("/127.0.0.1:%1/Rogue0.rtc").arg(server.port()));
    QString ior;
    QCOMPARE(messageOf([&] { ior = NamingBrowser::resolve(path); }), QString());
    QCOMPARE(sent.load(), 1);
    QVERIFY2(ior.startsWith("IOR:") && ior.size() > 256 * 1024, qPrintable(ior.left(80)));
    // Using it says what is wrong with it, without a call to anyone.
    const ComponentProxy rogue(ior, path.toString());
    QCOMPARE(kindOf([&] { rogue.profile(); }), Error::Kind::BadPath);
    QVERIFY2(messageOf([&] { rogue.profile(); }).contains("does not decode"), qPrintable(messageOf([&] {
                 rogue.profile();
             })));

    const qint64 before = LiveTest::residentKiB(QCoreApplication::applicationPid());
    QVERIFY(before > 0);
    // 1,000 replies carrying 128 KiB each: 128 MiB if the client kept what it read.
    for (int i = 0; i < 1000; ++i) {
        try {
            NamingBrowser::resolve(path);
        } catch (const Error &e) {
            QFAIL(qPrintable(QStringLiteral("reply %1: %2").arg(i).arg(e.message())));
        }
    }
    QCOMPARE(sent.load(), 1001);
#if defined(__SANITIZE_ADDRESS__)
    // AddressSanitizer keeps freed memory in a quarantine, which shows as growth; its leak check at
    // exit finds what omniORB would have lost instead.
    Q_UNUSED(before)
#else
    const qint64 after = LiveTest::residentKiB(QCoreApplication::applicationPid());
    QVERIFY2(after - before < 32 * 1024,
             qPrintable(QStringLiteral("the client grew from %1 KiB to %2 KiB").arg(before).arg(after)));
#endif
}

void TestCorbaClientHostile::typedUndecodableReferenceIsRefused()
{
    // A reference given as text (a user's, or one from a file) that does not decode is refused
    // with a message saying so, shortened to a line.
    const QString typed = QString::fromLatin1(LiveTest::undecodableReference(4096));
    const ComponentProxy proxy(typed, QStringLiteral("typed"));
    QCOMPARE(kindOf([&] { proxy.profile(); }), Error::Kind::BadPath);
    const QString message = messageOf([&] { proxy.profile(); });
    QVERIFY2(message.startsWith("typed: not an object reference (its profile does not decode): IOR:"),
             qPrintable(message));
    QVERIFY2(message.size() < 300, qPrintable(message));
    // Text that is no reference at all keeps its own message.
    const ComponentProxy garbage(QStringLiteral("IOR:nothex"), QStringLiteral("typed"));
    QCOMPARE(messageOf([&] { garbage.profile(); }), QStringLiteral("typed: not an object reference: IOR:nothex"));
}

QTEST_GUILESS_MAIN(TestCorbaClientHostile)
#include "tst_corbaclienthostile.moc"
