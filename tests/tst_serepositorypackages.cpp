// SPDX-License-Identifier: MIT
// The System Editor's Repository view over a component repository (`rtctl repo init` + publish):
// the newest version of each component package, its RTC profile read from the package and
// dragged like a local one; a package that cannot be read and a folder that is no readable
// repository are listed as errors naming the package or the file. Repositories are read in the
// background; one served over HTTP (busybox's web server) lists the same, and one that cannot be
// reached is an error naming the URL.
#include "livesystem.h"
#include "rtcrepository.h"
#include "rtctlrunner.h"

#include <QAbstractItemModelTester>
#include <QDir>
#include <QFile>
#include <QMimeData>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

using namespace SystemEditor;

namespace {

const QString pyFixture = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/packages/pycomp");
const QString pyPackage = QStringLiteral("rtc-rtstudiotests-packaging-pygreeter");

/// Copies the fixture's files into @p to, its version set to @p version ("v1_3").
bool copyWithVersion(const QString &to, const QString &version)
{
    if (!QDir().mkpath(to + QStringLiteral("/idl")))
        return false;
    const QDir from(pyFixture);
    for (const QString &name : {QStringLiteral("PyGreeter.conf"), QStringLiteral("PyGreeter.py"),
                                QStringLiteral("idl/Greeting.idl")}) {
        if (!QFile::copy(from.filePath(name), QDir(to).filePath(name)))
            return false;
    }
    QFile in(from.filePath(QStringLiteral("RTC.xml")));
    QFile out(QDir(to).filePath(QStringLiteral("RTC.xml")));
    if (!in.open(QIODevice::ReadOnly) || !out.open(QIODevice::WriteOnly))
        return false;
    const QByteArray xml = in.readAll().replace("v1_2", version.toUtf8());
    return out.write(xml) == xml.size();
}

/// Adds the component repository @p source and waits until its background read is done.
bool addAndRead(RtcRepository &repository, const QString &source)
{
    QSignalSpy read(&repository, &RtcRepository::repositoryRead);
    if (!repository.addSource(source) || !repository.isReading())
        return false;
    return read.wait(60000) && read.at(0).at(0).toString() == source && !repository.isReading();
}

} // namespace

class TestSeRepositoryPackages : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void listsTheNewestVersionOfEachPackage();
    void dragsThePackagedProfile();
    void unreadablePackageIsAnError();
    void brokenRepositoryIsAnError();
    void listsARepositoryServedOverHttp();
    void unreachableUrlIsAnError();
    void removesAPackageFromItsRepository();

private:
    /// `rtctl package` of @p project into the work folder; the .deb, or empty.
    QString package(const QString &project);

    QTemporaryDir m_work;
    QString m_repository;
};

QString TestSeRepositoryPackages::package(const QString &project)
{
    const RtctlResult r = runRtctl({"package", project, "-o", m_work.filePath("debs")});
    return r.code == 0 ? r.lines().value(0) : QString();
}

void TestSeRepositoryPackages::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QDir(RtcRepository::cacheFolder()).removeRecursively();
    QVERIFY(m_work.isValid());
    QVERIFY(QDir().mkpath(m_work.filePath("debs")));
    const QString v12 = package(pyFixture);
    QVERIFY(QFile::exists(v12));
    QVERIFY(copyWithVersion(m_work.filePath("v13"), "v1_3"));
    const QString v13 = package(m_work.filePath("v13"));
    QVERIFY(QFile::exists(v13));
    m_repository = m_work.filePath("repo");
    QCOMPARE(runRtctl({"repo", "init", m_repository}).code, 0);
    const RtctlResult published = runRtctl({"repo", "publish", m_repository, v13, v12});
    QVERIFY2(published.code == 0, qPrintable(published.err));
}

void TestSeRepositoryPackages::listsTheNewestVersionOfEachPackage()
{
    RtcRepository repository;
    QAbstractItemModelTester tester(&repository, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(addAndRead(repository, m_repository));
    QVERIFY(repository.errors().isEmpty());
    QCOMPARE(repository.entries().size(), 1);
    const RtcRepository::Entry entry = repository.entries().first();
    QCOMPARE(entry.package, pyPackage);
    QCOMPARE(entry.packageVersion, QStringLiteral("1.3"));
    QCOMPARE(entry.profile.basicInfo.name, QStringLiteral("PyGreeter"));
    QCOMPARE(entry.profile.basicInfo.version, QStringLiteral("v1_3"));
    QVERIFY(entry.filePath.startsWith(RtcRepository::cacheFolder()));
    // Category → component, the tool tip naming package, version and repository.
    QCOMPARE(repository.rowCount(), 1);
    const QModelIndex category = repository.index(0, 0);
    QCOMPARE(category.data().toString(), QStringLiteral("Packaging"));
    const QModelIndex component = repository.index(0, 0, category);
    QCOMPARE(component.data().toString(), QStringLiteral("PyGreeter"));
    const QString tip = component.data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(pyPackage + " 1.3") && tip.contains(m_repository), qPrintable(tip));
}

void TestSeRepositoryPackages::dragsThePackagedProfile()
{
    RtcRepository repository;
    QVERIFY(addAndRead(repository, m_repository));
    const QModelIndex component = repository.index(0, 0, repository.index(0, 0));
    std::unique_ptr<QMimeData> mime(repository.mimeData({component}));
    QVERIFY(mime && mime->hasFormat(RtcRepository::MimeType));
    const QString path = component.data(RtcRepository::FilePathRole).toString();
    QVERIFY(QString::fromUtf8(mime->data(RtcRepository::MimeType)).contains(path));
    QVERIFY(repository.profileForFile(path));
    QCOMPARE(repository.profileForFile(path)->id, QStringLiteral("RTC:RTStudioTests:Packaging:PyGreeter:v1_3"));
}

void TestSeRepositoryPackages::unreadablePackageIsAnError()
{
    // A copy of the repository (its own cache) whose newest .deb is cut short.
    const QString copy = m_work.filePath("cut");
    QCOMPARE(QProcess::execute("cp", {"-a", m_repository, copy}), 0);
    QDir pool(copy + "/pool/main/r/" + pyPackage);
    const QStringList debs = pool.entryList({"*1.3_all.deb"});
    QCOMPARE(debs.size(), 1);
    QFile deb(pool.filePath(debs.first()));
    QVERIFY(deb.resize(100));
    RtcRepository repository;
    QVERIFY(addAndRead(repository, copy));
    QVERIFY(repository.entries().isEmpty());
    QCOMPARE(repository.errors().size(), 1);
    const QString message = repository.errors().first().diagnostics.value(0).message;
    QVERIFY2(message.contains(pyPackage + " 1.3"), qPrintable(message));
}

void TestSeRepositoryPackages::brokenRepositoryIsAnError()
{
    const QString broken = m_work.filePath("broken");
    QVERIFY(QDir().mkpath(broken + "/conf"));
    QFile conf(broken + "/conf/repository");
    QVERIFY(conf.open(QIODevice::WriteOnly));
    conf.write("no fields here\n");
    conf.close();
    RtcRepository repository;
    QVERIFY(addAndRead(repository, broken));
    QVERIFY(repository.entries().isEmpty());
    QCOMPARE(repository.errors().size(), 1);
    const QString message = repository.errors().first().diagnostics.value(0).message;
    QVERIFY2(message.contains(broken + "/conf/repository"), qPrintable(message));
}

void TestSeRepositoryPackages::listsARepositoryServedOverHttp()
{
    const QString busybox = QStandardPaths::findExecutable(QStringLiteral("busybox"));
    if (busybox.isEmpty())
        QSKIP("no busybox to serve the repository (scripts/install-deps.sh installs it)");
    LiveTest::LiveSystem live;
    const quint16 port = LiveTest::freePort();
    const auto serving = [port] {
        QTcpSocket socket;
        socket.connectToHost(QStringLiteral("127.0.0.1"), port);
        return socket.waitForConnected(200);
    };
    QString error;
    QVERIFY2(live.startRegistered(busybox, {"httpd", "-f", "-p", QStringLiteral("127.0.0.1:%1").arg(port), "-h", m_repository},
                                  serving, &error),
             qPrintable(error));
    const QString url = QStringLiteral("http://127.0.0.1:%1/").arg(port);
    RtcRepository repository;
    QAbstractItemModelTester tester(&repository, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(addAndRead(repository, url));
    QVERIFY2(repository.errors().isEmpty(), qPrintable(repository.errors().value(0).diagnostics.value(0).message));
    QCOMPARE(repository.entries().size(), 1);
    const RtcRepository::Entry entry = repository.entries().first();
    QCOMPARE(entry.package, pyPackage);
    QCOMPARE(entry.packageVersion, QStringLiteral("1.3"));
    QCOMPARE(entry.repository, url);
    QCOMPARE(entry.profile.id, QStringLiteral("RTC:RTStudioTests:Packaging:PyGreeter:v1_3"));
    const QModelIndex component = repository.index(0, 0, repository.index(0, 0));
    QCOMPARE(component.data().toString(), QStringLiteral("PyGreeter"));
}

void TestSeRepositoryPackages::unreachableUrlIsAnError()
{
    const QString url = QStringLiteral("http://127.0.0.1:%1/repo/").arg(LiveTest::freePort());
    RtcRepository repository;
    QVERIFY(addAndRead(repository, url));
    QVERIFY(repository.entries().isEmpty());
    QCOMPARE(repository.errors().size(), 1);
    const QString message = repository.errors().first().diagnostics.value(0).message;
    QVERIFY2(message.contains(url + "dists/stable/Release"), qPrintable(message));
}

// The Repository view's Remove Package from Repository (rtctl repo remove NAME=VERSION): the
// newest version goes, the one before it is listed again, and a URL's package cannot be removed.
void TestSeRepositoryPackages::removesAPackageFromItsRepository()
{
    const QString copy = m_work.filePath("removing");
    QCOMPARE(QProcess::execute("cp", {"-a", m_repository, copy}), 0);
    RtcRepository repository;
    QVERIFY(addAndRead(repository, copy));
    QCOMPARE(repository.entries().value(0).packageVersion, QStringLiteral("1.3"));
    QSignalSpy removed(&repository, &RtcRepository::packageRemoved);
    QSignalSpy read(&repository, &RtcRepository::repositoryRead);
    QVERIFY(repository.removePackage(repository.index(0, 0, repository.index(0, 0))));
    QVERIFY(removed.wait(30000));
    QCOMPARE(removed.at(0).at(0).toString(), pyPackage + " 1.3");
    QCOMPARE(removed.at(0).at(1).toString(), QString());
    QVERIFY(read.wait(30000));
    QCOMPARE(repository.entries().size(), 1);
    QCOMPARE(repository.entries().first().packageVersion, QStringLiteral("1.2"));
    const RtctlResult listed = runRtctl({"repo", "list", copy});
    QVERIFY2(listed.out.contains("1.2") && !listed.out.contains("1.3"), qPrintable(listed.out));
    // A category row is no package.
    QVERIFY(!repository.removePackage(repository.index(0, 0)));
}

QTEST_GUILESS_MAIN(TestSeRepositoryPackages)
#include "tst_serepositorypackages.moc"
