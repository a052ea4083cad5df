// SPDX-License-Identifier: MIT
// rtctl node and rtmanager's package installer: a component generated and built against this
// build tree's SDK, packaged (rtctl package) in several versions and published in repositories
// signed with throwaway keys (rtctl repo), installed into a manager's own package store by file
// URL, over http and https (a certificate authority the manager is configured to trust) and by
// bytes pushed through the call; its type is loadable at once, created and run; two versions side
// by side, the newest used and version= picking the old; uninstall refused while an instance runs;
// what is installed survives a restart. Refused, each with the package
// and the reason and the store unchanged: a flipped byte, an unsigned repository, a key not in the
// keyring, another architecture, another SDK ABI, a missing Debian dependency, a full disk. A
// manager killed in the middle of unpacking leaves a staging folder that its next start deletes.
// rtctl node enable writes a systemd unit systemd-analyze accepts.
#include "livesystem.h"
#include "rtctlrunner.h"
#include "sdkproject.h"
#include "tmpfsmount.h"

#include <componentproxy.h>
#include <corbaerror.h>
#include <managerproxy.h>

#include <QDirIterator>
#include <QProcess>
#include <QtTest>

namespace {

const QString greeterFixture = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/sdk/SdkGreeter");
const QString package = QStringLiteral("rtc-rtstudiotests-test-sdkgreeter");

QString tool(const QString &program, const QStringList &arguments, int *code = nullptr)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    if (!process.waitForFinished(120000))
        process.kill();
    process.waitForFinished();
    if (code)
        *code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    return QString::fromUtf8(process.readAll());
}

bool writeFile(const QString &path, const QByteArray &data)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(data) == data.size();
}

QByteArray readFile(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// Every path below @p root, relative to it, sorted: what a refusal must leave as it was.
QStringList treeOf(const QString &root)
{
    QStringList paths;
    QDirIterator it(root, QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        paths << it.next().mid(root.size());
    paths.sort();
    return paths;
}

} // namespace

class TestManagerInstall : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void refused_data();
    void refused();
    void pushedRefused();
    void noInstallService();
    void allowUnsigned();
    void installByFileUrl();
    void installByPushedBytes();
    void versionsSideBySide();
    void uninstallRefusedWhileRunning();
    void restartKeepsPackages();
    void installOverHttp();
    void installOverHttps();
    void killedInstallLeavesNothing();
    void fullDiskWhileUnpacking();
    void systemdUnit();

private:
    /// A variant of the package: its control fields changed as given, rebuilt with dpkg-deb.
    QString variant(const QString &name, const QHash<QString, QString> &fields);
    /// A repository made with rtctl repo at @p dir, signed with a new key in @p gnupg (unsigned
    /// when empty), with @p debs published.
    void makeRepository(const QString &dir, const QString &gnupg, const QStringList &debs);
    /// The URL of @p deb in the pool of @p repo.
    QString poolUrl(const QString &repo, const QString &deb) const;
    bool startManager(const QStringList &extra = {});
    QString manager() const;
    Corba::ManagerProxy managerProxy() const
    {
        return Corba::ManagerProxy(QString::fromLatin1(LiveTest::managerLocation(m_port)),
                                   QStringLiteral("manager"));
    }
    RtctlResult node(const QStringList &arguments)
    {
        return runRtctl(QStringList {"node"} + arguments);
    }
    /// get_loadable_modules' module_file_path of @p type.
    QStringList loadable(const QString &type) const;
    /// The module a new instance of @p request was made from (the manager's loaded modules).
    QString createdFrom(const QString &request, QString *instance);
    QString create(const QString &request, QString *instance);
    /// Deletes every component of the manager.
    void deleteAll();

    QTemporaryDir m_work;
    QString m_arch;
    QString m_deb1; ///< version 1.0.0
    QString m_deb2; ///< version 2.0.0
    QString m_wrongArch;
    QString m_missingDep;
    QString m_otherSdk;
    QString m_repo;
    QString m_unsignedRepo;
    QString m_otherKeyRepo;
    QString m_flippedRepo;
    QString m_store;
    QStringList m_gnupgHomes;
    std::unique_ptr<LiveTest::LiveSystem> m_live;
    QProcess *m_manager = nullptr;
    quint16 m_port = 0;
};

QString TestManagerInstall::variant(const QString &name, const QHash<QString, QString> &fields)
{
    const QString tree = m_work.filePath("variants/" + name);
    QDir().mkpath(m_work.filePath("variants"));
    int code = 0;
    const QString raw = tool("dpkg-deb", {"-R", m_deb1, tree}, &code);
    if (code != 0)
        return raw;
    QByteArray control = readFile(tree + "/DEBIAN/control");
    for (auto it = fields.cbegin(); it != fields.cend(); ++it) {
        const QRegularExpression line("^" + it.key() + ": .*$",
                                      QRegularExpression::MultilineOption);
        const QString value = it.key() + ": " + it.value();
        control = QString::fromUtf8(control).contains(line)
            ? QString::fromUtf8(control).replace(line, value).toUtf8()
            : control + value.toUtf8() + '\n';
    }
    writeFile(tree + "/DEBIAN/control", control);
    const QString deb = m_work.filePath("debs/" + name + ".deb");
    tool("dpkg-deb", {"--root-owner-group", "--build", tree, deb}, &code);
    return code == 0 ? deb : QString();
}

void TestManagerInstall::makeRepository(const QString &dir, const QString &gnupg,
                                        const QStringList &debs)
{
    QStringList init {
        "repo", "init", dir, "--arch", m_arch, "--arch", m_arch == "arm64" ? "amd64" : "arm64"};
    if (!gnupg.isEmpty()) {
        init << "--new-key"
             << "--gnupg-home" << gnupg;
        m_gnupgHomes << gnupg;
    }
    const RtctlResult made = runRtctl(init);
    QVERIFY2(made.code == 0, qPrintable(made.err));
    const RtctlResult published = runRtctl(QStringList {"repo", "publish", dir} + debs);
    QVERIFY2(published.code == 0, qPrintable(published.err));
}

QString TestManagerInstall::poolUrl(const QString &repo, const QString &deb) const
{
    QDirIterator it(repo + "/pool", {QFileInfo(deb).fileName()}, QDir::Files,
                    QDirIterator::Subdirectories);
    return it.hasNext() ? QUrl::fromLocalFile(it.next()).toString() : QString();
}

void TestManagerInstall::initTestCase()
{
    QVERIFY(m_work.isValid());
    m_arch = tool("dpkg", {"--print-architecture"}).trimmed();
    // A component with a provided service of its own IDL, generated, built and packaged.
    const QString project = m_work.filePath("SdkGreeter");
    const RtctlResult generated = runRtctl({"gen", greeterFixture + "/RTC.xml", "--lang", "cpp",
                                            "-o", project, "--idl-dir", greeterFixture});
    QVERIFY2(generated.code == 0, qPrintable(generated.out + generated.err));
    QString log;
    QVERIFY2(SdkTest::buildProject(project, RTSTUDIO_BUILD_DIR, &log), qPrintable(log));
    const RtctlResult packaged = runRtctl({"package", project, "-o", m_work.filePath("debs")});
    QVERIFY2(packaged.code == 0, qPrintable(packaged.err));
    m_deb1 = packaged.lines().value(0);
    // The same component as version 2.0.0, for another architecture, needing a library no
    // Debian system has.
    m_deb2 = variant(package + "_2.0.0_" + m_arch, {{"Version", "2.0.0"}});
    const QString otherArch = m_arch == "arm64" ? "amd64" : "arm64";
    m_wrongArch = variant(package + "_1.0.0_" + otherArch, {{"Architecture", otherArch}});
    m_missingDep
        = variant(package + "_3.0.0_" + m_arch,
                  {{"Version", "3.0.0"}, {"Depends", "libc6, librtstudio-nowhere0 (>= 1.0)"}});
    m_otherSdk = variant(package + "_4.0.0_" + m_arch,
                         {{"Version", "4.0.0"}, {"X-RTStudio-SDK-ABI", "librtstudio_rtm.so.99"}});
    for (const QString &deb : {m_deb2, m_wrongArch, m_missingDep, m_otherSdk})
        QVERIFY2(QFile::exists(deb), qPrintable(deb));

    m_repo = m_work.filePath("repo");
    makeRepository(m_repo, m_work.filePath("gnupg"),
                   {m_deb1, m_deb2, m_wrongArch, m_missingDep, m_otherSdk});
    m_unsignedRepo = m_work.filePath("unsigned");
    makeRepository(m_unsignedRepo, QString(), {m_deb1});
    m_otherKeyRepo = m_work.filePath("otherkey");
    makeRepository(m_otherKeyRepo, m_work.filePath("othergnupg"), {m_deb1});
    // A copy of the signed repository whose package has one byte changed; its index is intact.
    m_flippedRepo = m_work.filePath("flipped");
    QCOMPARE(tool("cp", {"-a", m_repo, m_flippedRepo}), QString());
    const QString flipped = QUrl(poolUrl(m_flippedRepo, m_deb1)).toLocalFile();
    QByteArray data = readFile(flipped);
    QVERIFY(data.size() > 1000);
    data[data.size() / 2] = char(data.at(data.size() / 2) ^ 0x01);
    QVERIFY(writeFile(flipped, data));

    m_store = m_work.filePath("store");
    m_live = std::make_unique<LiveTest::LiveSystem>();
    m_port = LiveTest::freePort();
    QVERIFY(startManager());
}

void TestManagerInstall::cleanupTestCase()
{
    m_live.reset();
    for (const QString &home : std::as_const(m_gnupgHomes))
        tool("gpgconf", {"--homedir", home, "--kill", "all"});
}

bool TestManagerInstall::startManager(const QStringList &extra)
{
    if (m_manager)
        m_live->stop(m_manager);
    QString error;
    m_manager = m_live->startManager(
        RTMANAGER_PATH, m_port,
        QStringList {"naming.enable=NO", "manager.modules.load_path=" + m_work.filePath("none"),
                     "manager.modules.package_path=" + m_work.filePath("none"),
                     "manager.packages.store=" + m_store,
                     "manager.packages.keyring=" + m_repo + "/archive-key.gpg"}
            + extra,
        &error);
    if (!m_manager) {
        qWarning("%s", qPrintable(error));
        return false;
    }
    // This process's connection to the manager that ran before on the port is broken: the first
    // call finds out, the next connects anew (bounded).
    const Corba::ManagerProxy proxy = managerProxy();
    for (int attempt = 0; attempt < 3; ++attempt) {
        try {
            proxy.isMaster();
            return true;
        } catch (const Corba::Error &) { }
    }
    return false;
}

QString TestManagerInstall::manager() const
{
    return QStringLiteral("corbaloc::127.0.0.1:%1/manager").arg(m_port);
}

QStringList TestManagerInstall::loadable(const QString &type) const
{
    const Corba::ManagerProxy proxy = managerProxy();
    QStringList files;
    try {
        for (const Corba::Properties &module : proxy.loadableModules()) {
            if (Corba::propertyValue(module, "implementation_id") == type)
                files << Corba::propertyValue(module, "module_file_path");
        }
    } catch (const Corba::Error &e) {
        files << e.message();
    }
    return files;
}

QString TestManagerInstall::createdFrom(const QString &request, QString *instance)
{
    try {
        return create(request, instance);
    } catch (const Corba::Error &e) {
        return e.message();
    }
}

QString TestManagerInstall::create(const QString &request, QString *instance)
{
    const Corba::ManagerProxy proxy = managerProxy();
    const QString ior = proxy.createComponent(request);
    const Corba::ComponentProxy component(ior, request);
    *instance = component.profile().instanceName;
    // It runs: activated in its execution context (polled for, a bounded while).
    component.activate();
    QDeadlineTimer deadline(5000);
    while (component.state() != Corba::LifeCycleState::Active && !deadline.hasExpired())
        QTest::qWait(10);
    if (component.state() != Corba::LifeCycleState::Active)
        return QStringLiteral("not active");
    QStringList files;
    for (const Corba::Properties &module : proxy.loadedModules())
        files << Corba::propertyValue(module, "file_path");
    return files.join('\n');
}

void TestManagerInstall::deleteAll()
{
    const Corba::ManagerProxy proxy = managerProxy();
    try {
        for (const QString &ior : proxy.components())
            proxy.deleteComponent(Corba::ComponentProxy(ior, "component").profile().instanceName);
    } catch (const Corba::Error &e) {
        QFAIL(qPrintable(e.message()));
    }
}

void TestManagerInstall::refused_data()
{
    QTest::addColumn<QString>("url");
    QTest::addColumn<QStringList>("message"); // parts of the message, in order

    QTest::newRow("one byte flipped")
        << poolUrl(m_flippedRepo, m_deb1)
        << QStringList {package + " 1.0.0", "does not match the index"};
    QTest::newRow("unsigned repository")
        << poolUrl(m_unsignedRepo, m_deb1)
        << QStringList {QFileInfo(m_deb1).fileName(), "unsigned", "allow_unsigned"};
    QTest::newRow("key not in the keyring")
        << poolUrl(m_otherKeyRepo, m_deb1)
        << QStringList {QFileInfo(m_deb1).fileName(), "signature is not trusted", "gpgv"};
    QTest::newRow("other architecture")
        << poolUrl(m_repo, m_wrongArch)
        << QStringList {package + " 1.0.0", "built for architecture", "this node is " + m_arch};
    QTest::newRow("missing Debian library")
        << poolUrl(m_repo, m_missingDep)
        << QStringList {package + " 3.0.0", "missing dependencies",
                        "librtstudio-nowhere0 (>= 1.0)"};
    QTest::newRow("another SDK") << poolUrl(m_repo, m_otherSdk)
                                 << QStringList {
                                        package + " 4.0.0",
                                        "built for the component SDK librtstudio_rtm.so.99",
                                        "this manager's SDK is librtstudio_rtm.so."};
}

void TestManagerInstall::refused()
{
    QFETCH(QString, url);
    QFETCH(QStringList, message);
    QVERIFY(!url.isEmpty());
    const QStringList before = treeOf(m_store);
    const RtctlResult r = node({"install", manager(), url});
    QCOMPARE(r.code, 1);
    qsizetype at = 0;
    for (const QString &part : message) {
        at = r.err.indexOf(part, at);
        QVERIFY2(at >= 0, qPrintable("'" + part + "' not in: " + r.err));
    }
    QCOMPARE(treeOf(m_store), before);
    QVERIFY(loadable("SdkGreeter").isEmpty());
}

void TestManagerInstall::pushedRefused()
{
    // Pushed through the call, the package meets the same checks: one byte changed, against the
    // intact repository's index.
    const QString flipped = QUrl(poolUrl(m_flippedRepo, m_deb1)).toLocalFile();
    const QStringList before = treeOf(m_store);
    const RtctlResult r = node({"install", manager(), flipped, "--repo", m_repo});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(package + " 1.0.0: ") && r.err.contains("does not match the index"),
             qPrintable(r.err));
    QCOMPARE(treeOf(m_store), before);
    // A repository folder that is none is named.
    const RtctlResult noRepo
        = node({"install", manager(), m_deb1, "--repo", m_work.filePath("none")});
    QCOMPARE(noRepo.code, 1);
    QVERIFY2(noRepo.err.contains(m_work.filePath("none")), qPrintable(noRepo.err));
}

void TestManagerInstall::noInstallService()
{
    LiveTest::LiveSystem live;
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(live.startManager(RTMANAGER_PATH, port,
                               {"naming.enable=NO", "manager.packages.enable=NO"}, &error),
             qPrintable(error));
    const RtctlResult r
        = node({"packages", QStringLiteral("corbaloc::127.0.0.1:%1/manager").arg(port)});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("has no install service (manager.packages.enable is NO)"),
             qPrintable(r.err));
    // A manager of RTM::Manager alone, as OpenRTM-aist's, does not know the operation.
    quint16 peerPort = 0;
    QVERIFY2(live.startNameServer(&error), qPrintable(error));
    QVERIFY2(live.startPeer({}, &error, &peerPort), qPrintable(error));
    const RtctlResult openRtm
        = node({"install", QStringLiteral("corbaloc::127.0.0.1:%1/manager").arg(peerPort),
                poolUrl(m_repo, m_deb1)});
    QCOMPARE(openRtm.code, 1);
    QVERIFY2(openRtm.err.contains("has no install service (not an RT Studio manager)"),
             qPrintable(openRtm.err));
}

void TestManagerInstall::allowUnsigned()
{
    // A manager configured to take unsigned repositories and signatures it cannot check.
    LiveTest::LiveSystem live;
    const quint16 port = LiveTest::freePort();
    const QString store = m_work.filePath("unsignedstore");
    QString error;
    QVERIFY2(live.startManager(RTMANAGER_PATH, port,
                               {"naming.enable=NO", "manager.packages.store=" + store,
                                "manager.packages.allow_unsigned=YES"},
                               &error),
             qPrintable(error));
    const QString other = QStringLiteral("corbaloc::127.0.0.1:%1/manager").arg(port);
    const RtctlResult unsignedRepo = node({"install", other, poolUrl(m_unsignedRepo, m_deb1)});
    QVERIFY2(unsignedRepo.code == 0, qPrintable(unsignedRepo.err));
    QVERIFY(unsignedRepo.out.startsWith(package + " 1.0.0 "));
    const RtctlResult unknownKey = node({"install", other, m_deb2, "--repo", m_otherKeyRepo});
    QCOMPARE(unknownKey.code, 1); // 2.0.0 is not in that repository: the index still counts
    QVERIFY2(unknownKey.err.contains("not listed in the repository's index"),
             qPrintable(unknownKey.err));
    const RtctlResult removed = node({"uninstall", other, package});
    QVERIFY2(removed.code == 0, qPrintable(removed.err));
    const RtctlResult pushed = node({"install", other, m_deb1, "--repo", m_otherKeyRepo});
    QVERIFY2(pushed.code == 0, qPrintable(pushed.err));
}

void TestManagerInstall::installByFileUrl()
{
    const RtctlResult r = node({"install", manager(), poolUrl(m_repo, m_deb1)});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY2(r.out.startsWith(package + " 1.0.0 " + m_arch + " SdkGreeter " + m_store),
             qPrintable(r.out));
    // Loadable at once, from the store.
    const QStringList files = loadable("SdkGreeter");
    QCOMPARE(files.size(), 1);
    QVERIFY2(files.first().startsWith(m_store + "/" + package + "/1.0.0/"),
             qPrintable(files.first()));
    QString instance;
    const QString from = createdFrom("SdkGreeter", &instance);
    QVERIFY2(from.contains(m_store + "/" + package + "/1.0.0/"), qPrintable(from));
    deleteAll();
}

void TestManagerInstall::installByPushedBytes()
{
    const RtctlResult r = node({"install", manager(), m_deb2, "--repo", m_repo});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY2(r.out.startsWith(package + " 2.0.0 "), qPrintable(r.out));
    const RtctlResult listed = node({"packages", manager(), "--json"});
    QVERIFY2(listed.code == 0, qPrintable(listed.err));
    const QJsonArray all = listed.json().array();
    QCOMPARE(all.size(), 2);
    // The newest first.
    QCOMPARE(all.at(0)["version"].toString(), QStringLiteral("2.0.0"));
    QCOMPARE(all.at(1)["version"].toString(), QStringLiteral("1.0.0"));
    QCOMPARE(all.at(0)["types"].toArray().first().toString(), QStringLiteral("SdkGreeter"));
    QCOMPARE(loadable("SdkGreeter").size(), 2);
}

void TestManagerInstall::versionsSideBySide()
{
    const Corba::ManagerProxy proxy = managerProxy();
    QString newest;
    const QString fromNewest = createdFrom("SdkGreeter", &newest);
    QVERIFY2(fromNewest.contains(m_store + "/" + package + "/2.0.0/"), qPrintable(fromNewest));
    QString old;
    const QString fromOld = createdFrom("SdkGreeter?version=1.0.0", &old);
    QVERIFY2(fromOld.contains(m_store + "/" + package + "/1.0.0/"), qPrintable(fromOld));
    QVERIFY(newest != old);
    try {
        proxy.deleteComponent(newest);
    } catch (const Corba::Error &e) {
        QFAIL(qPrintable(e.message()));
    }
    // A version not installed is refused with the reason.
    QString none;
    const QString refusal = createdFrom("SdkGreeter?version=9.9", &none);
    QVERIFY2(refusal.contains("no installed package of version 9.9"), qPrintable(refusal));
}

void TestManagerInstall::uninstallRefusedWhileRunning()
{
    // The instance of 1.0.0 made in versionsSideBySide() runs.
    const RtctlResult refused = node({"uninstall", manager(), package + "=1.0.0"});
    QCOMPARE(refused.code, 1);
    QVERIFY2(refused.err.contains(package + " 1.0.0") && refused.err.contains("running"),
             qPrintable(refused.err));
    QVERIFY(QFileInfo::exists(m_store + "/" + package + "/1.0.0"));
    deleteAll();
    // Nor while one runs in a slave process, which uses the same store.
    QString inSlave;
    const QString slaveCreated
        = createdFrom("SdkGreeter?version=1.0.0&manager_name=packages_slave", &inSlave);
    QVERIFY2(!slaveCreated.contains("could not create") && slaveCreated != "not active",
             qPrintable(slaveCreated));
    const RtctlResult refusedForSlave = node({"uninstall", manager(), package + "=1.0.0"});
    QCOMPARE(refusedForSlave.code, 1);
    QVERIFY2(refusedForSlave.err.contains("SdkGreeter components are running in a slave manager"),
             qPrintable(refusedForSlave.err));
    try {
        managerProxy().deleteComponent(inSlave);
    } catch (const Corba::Error &e) {
        QFAIL(qPrintable(e.message()));
    }
    const RtctlResult removed = node({"uninstall", manager(), package + "=1.0.0"});
    QVERIFY2(removed.code == 0, qPrintable(removed.err));
    QVERIFY(!QFileInfo::exists(m_store + "/" + package + "/1.0.0"));
    QCOMPARE(loadable("SdkGreeter").size(), 1);
    // Its module is no longer used, though still loaded.
    QString none;
    const QString refusal = createdFrom("SdkGreeter?version=1.0.0", &none);
    QVERIFY2(refusal.contains("no installed package of version 1.0.0"), qPrintable(refusal));
}

void TestManagerInstall::restartKeepsPackages()
{
    QVERIFY(startManager());
    const RtctlResult listed = node({"packages", manager()});
    QVERIFY2(listed.code == 0, qPrintable(listed.err));
    QCOMPARE(listed.lines().size(), 1);
    QVERIFY2(listed.out.startsWith(package + " 2.0.0 "), qPrintable(listed.out));
    QString instance;
    const QString from = createdFrom("SdkGreeter", &instance);
    QVERIFY2(from.contains(m_store + "/" + package + "/2.0.0/"), qPrintable(from));
    deleteAll();
}

void TestManagerInstall::installOverHttp()
{
    const quint16 port = LiveTest::freePort();
    QString error;
    QProcess *server = m_live->startProcess("python3",
                                            {"-u", "-m", "http.server", "--bind", "127.0.0.1",
                                             QString::number(port), "--directory", m_repo},
                                            "Serving HTTP", &error);
    QVERIFY2(server, qPrintable(error));
    const QString path = QUrl(poolUrl(m_repo, m_deb1)).toLocalFile().mid(m_repo.size());
    const RtctlResult r
        = node({"install", manager(), QStringLiteral("http://127.0.0.1:%1%2").arg(port).arg(path)});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY2(r.out.startsWith(package + " 1.0.0 "), qPrintable(r.out));
    m_live->stop(server);
    const RtctlResult removed = node({"uninstall", manager(), package + "=1.0.0"});
    QVERIFY2(removed.code == 0, qPrintable(removed.err));
}

void TestManagerInstall::installOverHttps()
{
    // A repository behind https with a certificate of its own, which a manager trusts only when
    // configured to.
    const QString cert = m_work.filePath("cert.pem");
    const QString key = m_work.filePath("key.pem");
    int code = -1;
    const QString made
        = tool("openssl",
               {"req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", key, "-out", cert,
                "-days", "1", "-subj", "/CN=127.0.0.1", "-addext", "subjectAltName=IP:127.0.0.1"},
               &code);
    QVERIFY2(code == 0, qPrintable(made));
    const quint16 port = LiveTest::freePort();
    QString error;
    const QString server = QStringLiteral(
        "import functools, http.server, ssl, sys\n"
        "context = ssl.SSLContext(ssl.PROTOCOL_TLS_SERVER)\n"
        "context.load_cert_chain(sys.argv[1], sys.argv[2])\n"
        "handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=sys.argv[3])\n"
        "httpd = http.server.HTTPServer(('127.0.0.1', int(sys.argv[4])), handler)\n"
        "httpd.socket = context.wrap_socket(httpd.socket, server_side=True)\n"
        "print('Serving HTTPS', flush=True)\n"
        "httpd.serve_forever()\n");
    QVERIFY2(m_live->startProcess("python3",
                                  {"-c", server, cert, key, m_repo, QString::number(port)},
                                  "Serving HTTPS", &error),
             qPrintable(error));
    const QString url = QStringLiteral("https://127.0.0.1:%1%2")
                            .arg(port)
                            .arg(QUrl(poolUrl(m_repo, m_deb1)).toLocalFile().mid(m_repo.size()));
    const RtctlResult untrusted = node({"install", manager(), url});
    QCOMPARE(untrusted.code, 1);
    QVERIFY2(untrusted.err.contains("cannot fetch https://127.0.0.1"), qPrintable(untrusted.err));
    LiveTest::LiveSystem live;
    const quint16 managerPort = LiveTest::freePort();
    QVERIFY2(live.startManager(RTMANAGER_PATH, managerPort,
                               {"naming.enable=NO",
                                "manager.packages.store=" + m_work.filePath("httpsstore"),
                                "manager.packages.keyring=" + m_repo + "/archive-key.gpg",
                                "manager.packages.ca_certificates=" + cert},
                               &error),
             qPrintable(error));
    const RtctlResult trusted
        = node({"install", QStringLiteral("corbaloc::127.0.0.1:%1/manager").arg(managerPort), url});
    QVERIFY2(trusted.code == 0, qPrintable(trusted.err));
    QVERIFY2(trusted.out.startsWith(package + " 1.0.0 "), qPrintable(trusted.out));
}

void TestManagerInstall::killedInstallLeavesNothing()
{
    // A dpkg-deb that unpacks a little, says so, and then waits for the manager to die.
    const QString bin = m_work.filePath("slowbin");
    const QString marker = m_work.filePath("unpacking");
    QDir().mkpath(bin);
    QVERIFY(writeFile(bin + "/dpkg-deb",
                      "#!/bin/sh\n"
                      "if [ \"$1\" = -x ]; then\n"
                      "  mkdir -p \"$3\" && echo partial > \"$3/partial\" && touch '"
                          + marker.toUtf8()
                          + "'\n"
                            "  exec tail -f /dev/null --pid=$PPID\n"
                            "fi\n"
                            "exec /usr/bin/dpkg-deb \"$@\"\n"));
    QVERIFY(QFile::setPermissions(bin + "/dpkg-deb",
                                  QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner));
    const QByteArray path = qgetenv("PATH");
    qputenv("PATH", QFile::encodeName(bin) + ':' + path);
    const bool started = startManager();
    qputenv("PATH", path);
    QVERIFY(started);
    // rtctl gives up after its timeout; the manager goes on into unpacking, where it is killed.
    const RtctlResult timedOut
        = node({"install", manager(), poolUrl(m_repo, m_deb1), "--timeout", "1000"});
    QCOMPARE(timedOut.code, 1);
    QVERIFY2(timedOut.err.contains("no reply within 1000 ms"), qPrintable(timedOut.err));
    QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(marker), 30000);
    QVERIFY(treeOf(m_store).filter(".staging-").size() > 0);
    m_live->stop(m_manager);
    m_manager = nullptr;
    QVERIFY(startManager());
    QVERIFY2(treeOf(m_store).filter(".staging-").isEmpty(), qPrintable(treeOf(m_store).join('\n')));
    const RtctlResult listed = node({"packages", manager()});
    QVERIFY2(!listed.out.contains(" 1.0.0 "), qPrintable(listed.out));
    QVERIFY2(listed.out.startsWith(package + " 2.0.0 "), qPrintable(listed.out));
}

void TestManagerInstall::fullDiskWhileUnpacking()
{
    // A store on a file system smaller than the package unpacked (303 KiB).
    const QString store = m_work.filePath("smallstore");
    QDir().mkpath(store);
    TestDisk::TmpfsMount disk;
    TESTDISK_MOUNT_OR_SKIP(disk, store);
    LiveTest::LiveSystem live;
    const quint16 port = LiveTest::freePort();
    QString error;
    QVERIFY2(live.startManager(RTMANAGER_PATH, port,
                               {"naming.enable=NO", "manager.packages.store=" + store,
                                "manager.packages.keyring=" + m_repo + "/archive-key.gpg"},
                               &error),
             qPrintable(error));
    const QStringList before = treeOf(store);
    const RtctlResult r
        = node({"install", QStringLiteral("corbaloc::127.0.0.1:%1/manager").arg(port),
                poolUrl(m_repo, m_deb1)});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(package + " 1.0.0: unpacking") && r.err.contains("No space left"),
             qPrintable(r.err));
    QCOMPARE(treeOf(store), before);
}

void TestManagerInstall::systemdUnit()
{
    const QString units = m_work.filePath("units");
    const QString config = m_work.filePath("rtc.conf");
    QVERIFY(writeFile(config, "manager.packages.store: " + m_store.toUtf8() + "\n"));
    const RtctlResult enabled
        = node({"enable", "--config", config, "--unit-dir", units, "--program", RTMANAGER_PATH});
    QVERIFY2(enabled.code == 0, qPrintable(enabled.err));
    const QString unit = units + "/rtmanager.service";
    QCOMPARE(enabled.out.trimmed(), unit);
    const QString text = QString::fromUtf8(readFile(unit));
    QVERIFY2(text.contains((QStringLiteral("ExecStart=") + RTMANAGER_PATH + QStringLiteral(" -f ")) + config),
             qPrintable(text));
    if (QStandardPaths::findExecutable("systemd-analyze").isEmpty())
        QSKIP("systemd-analyze is not installed");
    int code = -1;
    const QString verified = tool("systemd-analyze", {"verify", unit}, &code);
    QVERIFY2(code == 0, qPrintable(verified));
    const RtctlResult disabled = node({"disable", "--unit-dir", units});
    QVERIFY2(disabled.code == 0, qPrintable(disabled.err));
    QVERIFY(!QFileInfo::exists(unit));
    const RtctlResult again = node({"disable", "--unit-dir", units});
    QCOMPARE(again.code, 1);
    QVERIFY2(again.err.contains("no unit to remove"), qPrintable(again.err));
}

QTEST_GUILESS_MAIN(TestManagerInstall)
#include "tst_managerinstall.moc"
