// SPDX-License-Identifier: MIT
// RT Studio over TLS: Online → Start Local Runtime with TLS makes the runtime's certificates and
// presents the user's; the Name Service view shows per server that the connection is encrypted and
// who the server proved to be, for the local runtime and for a name server and manager of a fleet,
// and groups objects by their TLS endpoints.
#include "iorendpoint.h"
#include "livesystem.h"
#include "localruntime.h"
#include "mainwindow.h"
#include "nameservicemodel.h"
#include "nameserviceview.h"
#include "onlinedocks.h"
#include "onlinesession.h"
#include "orb.h"
#include "rtctlrunner.h"

#include <QAction>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace SystemEditor;
using Studio::MainWindow;

class TestOnlineTls : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void startsTheLocalRuntimeWithTls();
    void nameServiceShowsEncryptionAndIdentity();

private:
    QTemporaryDir m_runtime {QDir::tempPath() + QStringLiteral("/rtonlinetlsXXXXXX")};
    QTemporaryDir m_settings;
    LiveTest::LiveSystem m_live;
};

void TestOnlineTls::initTestCase()
{
    QVERIFY(m_runtime.isValid() && m_settings.isValid());
    QFile::setPermissions(m_runtime.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    qputenv("XDG_RUNTIME_DIR", m_runtime.path().toLocal8Bit());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_onlinetls"));
    QVERIFY(!Corba::Orb::isInitialised());
}

void TestOnlineTls::cleanupTestCase()
{
    Deploy::LocalRuntime().stop(nullptr);
}

void TestOnlineTls::startsTheLocalRuntimeWithTls()
{
    MainWindow window;
    auto *start = window.findChild<QAction *>(QStringLiteral("actionStartLocalRuntimeTls"));
    QVERIFY(start);
    start->trigger();
    auto *label = window.findChild<QLabel *>(QStringLiteral("localRuntimeStatus"));
    QVERIFY(label);
    QTRY_VERIFY2_WITH_TIMEOUT(label->text().startsWith("Local runtime (TLS)"), qPrintable(label->text()), 30000);
    QVERIFY(Corba::Orb::usesTls());
    QVERIFY(Deploy::LocalRuntime().tls().enabled);

    // The view lists the runtime's name server through TLS, and names who answered.
    auto *view = window.findChild<NameServiceView *>();
    QVERIFY(view);
    NameServiceModel *model = view->model();
    QTRY_VERIFY_WITH_TIMEOUT(model->rowCount() == 1, 10000);
    QTRY_COMPARE_WITH_TIMEOUT(model->index(0, 1).data().toString(), QStringLiteral("TLS: localhost"), 20000);
}

void TestOnlineTls::nameServiceShowsEncryptionAndIdentity()
{
    // A fleet's name server and manager with certificates of the same authority (the runtime's here,
    // which this process trusts since the test before).
    const QString authority = Deploy::LocalRuntime().status().folder + QStringLiteral("/tls");
    const RtctlResult issued = runRtctl({"tls", "issue", authority, "robot1", "--host", "127.0.0.1"});
    QVERIFY2(issued.code == 0, qPrintable(issued.err));
    QString error;
    QVERIFY2(m_live.startTlsNameServer(authority + "/ca.pem", authority + "/robot1.pem", &error), qPrintable(error));
    const quint16 managerPort = LiveTest::freePort();
    QVERIFY2(m_live.startManager(RTMANAGER_PATH, managerPort,
                                 {"corba.nameservers=" + m_live.namingServer(), "naming.formats=robot1.host_cxt/%n.rtc",
                                  "manager.naming_formats=robot1.host_cxt/%n.mgr", "manager.components.precreate=ConsoleIn",
                                  "corba.ssl.certificate_authority_file=" + authority + "/ca.pem",
                                  "corba.ssl.key_file=" + authority + "/robot1.pem"},
                                 &error),
             qPrintable(error));

    OnlineSession session;
    NameServiceView view(&session, nullptr);
    QVERIFY(view.addServer(m_live.namingServer()));
    QSignalSpy refreshed(&view, &NameServiceView::serverRefreshed);
    QVERIFY(refreshed.wait(15000));
    NameServiceModel *model = view.model();
    const QString component = QStringLiteral("/%1/robot1.host_cxt/ConsoleIn0.rtc").arg(m_live.namingServer());
    QTRY_VERIFY_WITH_TIMEOUT(model->indexOfPath(component).isValid(), 10000);

    const QModelIndex server = model->index(0, 0);
    QCOMPARE(server.siblingAtColumn(1).data().toString(), QStringLiteral("TLS: robot1"));
    QVERIFY2(server.data(Qt::ToolTipRole).toString().contains("Encrypted with TLS; the server proved to be \"robot1\""),
             qPrintable(server.data(Qt::ToolTipRole).toString()));
    // Objects are grouped by the process serving them: its TLS port, not the 0 a TLS-only profile carries.
    const QString ior = model->indexOfPath(component).data(NameServiceModel::IorRole).toString();
    QCOMPARE(Corba::iorEndpoint(ior), QStringLiteral("127.0.0.1:%1").arg(managerPort));
    QTRY_COMPARE_WITH_TIMEOUT(model->indexOfPath(component).siblingAtColumn(1).data().toString(),
                              QStringLiteral("Inactive"), 10000);
}

QTEST_MAIN(TestOnlineTls)
#include "tst_onlinetls.moc"
