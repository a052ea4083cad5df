// SPDX-License-Identifier: MIT
// rtctl repo: a repository made in a temporary folder with a new signing key in a temporary GnuPG
// home, two packages published, listed, shown, refused twice, removed; then apt-get itself, with
// private state folders and the exported key as signed-by, updates from it and finds the packages,
// and refuses the index once a Packages file is changed, once it is unsigned, and when signed-by
// names another key. A signing failure leaves the repository as it was. The library's verifier
// (for managers that install) follows apt's order: InRelease through gpgv, then indexes, then
// packages, each refused when changed.
#include "rtctlrunner.h"

#include <releaseverifier.h>
#include <repository.h>

#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

namespace {

const QString fixtures = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/packages/");
const QString pyPackage = QStringLiteral("rtc-rtstudiotests-packaging-pygreeter");
const QString nativePackage = QStringLiteral("rtc-rtstudiotests-packaging-native");

struct ToolOutput
{
    int code = -1;
    QString out;
};

ToolOutput tool(const QString &program, const QStringList &arguments,
                const QString &cwd = QString())
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert("LC_ALL", "C");
    process.setProcessEnvironment(environment);
    process.setWorkingDirectory(cwd);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    if (!process.waitForFinished(120000))
        process.kill();
    process.waitForFinished();
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1,
            QString::fromUtf8(process.readAll())};
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool copyTree(const QString &from, const QString &to)
{
    return tool("cp", {"-a", from, to}).code == 0;
}

} // namespace

class TestComponentRepository : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void initCreatesSignedIndex();
    void publishAndList();
    void publishSameVersionRefused();
    void publishRefused_data();
    void publishRefused();
    void show();
    void failedSigningLeavesRepository();
    void aptReadsRepository();
    void aptRefusesChangedIndex();
    void aptRefusesUnsignedIndex();
    void aptRefusesOtherKey();
    void verifierFollowsTrust();
    void verifierRefuses_data();
    void verifierRefuses();
    void remove();

private:
    RtctlResult repo(const QStringList &arguments)
    {
        return runRtctl(QStringList {"repo"} + arguments);
    }
    /// apt-get update (and, when @p show is set, apt-cache show @p show) on @p repository with
    /// @p key as signed-by, in private state folders; the output of the last command run.
    ToolOutput apt(const QString &repository, const QString &key, const QString &show = QString(),
                   const QString &download = QString());

    QTemporaryDir m_work;
    QString m_repo;
    QString m_gnupg;
    QString m_otherGnupg;
    QString m_arch;
    QString m_pyDeb;
    QString m_nativeDeb;
};

void TestComponentRepository::initTestCase()
{
    QVERIFY(m_work.isValid());
    m_repo = m_work.filePath("repo");
    m_gnupg = m_work.filePath("gnupg");
    m_arch = tool("dpkg", {"--print-architecture"}).out.trimmed();
    // An Architecture: all package made by rtctl package, and one of this machine's architecture
    // made from a file tree with dpkg-deb.
    const RtctlResult py
        = runRtctl({"package", fixtures + "pycomp", "-o", m_work.filePath("debs")});
    QVERIFY2(py.code == 0, qPrintable(py.err));
    m_pyDeb = py.lines().value(0);
    const QString tree = m_work.filePath("nativetree");
    QVERIFY(copyTree(fixtures + "debtree", tree));
    QByteArray control = readAll(tree + "/DEBIAN/control").replace("@ARCH@", m_arch.toLatin1());
    QFile file(tree + "/DEBIAN/control");
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate)
            && file.write(control) == control.size());
    file.close();
    m_nativeDeb = m_work.filePath("debs/native.deb");
    const ToolOutput built = tool("dpkg-deb", {"--root-owner-group", "--build", tree, m_nativeDeb});
    QVERIFY2(built.code == 0, qPrintable(built.out));
}

void TestComponentRepository::cleanupTestCase()
{
    // gpg started an agent for each home; stop them.
    for (const QString &home : {m_gnupg, m_otherGnupg}) {
        if (!home.isEmpty() && QFileInfo::exists(home))
            tool("gpgconf", {"--homedir", home, "--kill", "all"});
    }
}

void TestComponentRepository::initCreatesSignedIndex()
{
    const RtctlResult r = repo({"init", m_repo, "--new-key", "--gnupg-home", m_gnupg});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    for (const char *file :
         {"conf/repository", "archive-key.asc", "archive-key.gpg", "dists/stable/Release",
          "dists/stable/InRelease", "dists/stable/Release.gpg"})
        QVERIFY2(QFile::exists(m_repo + '/' + file), file);
    QVERIFY(QFile::exists(m_repo + "/dists/stable/main/binary-" + m_arch + "/Packages.gz"));
    // Debian's gpgv, with only the exported key, accepts both signatures.
    const QString keyring = m_repo + "/archive-key.gpg";
    ToolOutput v = tool("gpgv", {"--keyring", keyring, m_repo + "/dists/stable/InRelease"});
    QVERIFY2(v.code == 0, qPrintable(v.out));
    v = tool("gpgv",
             {"--keyring", keyring, m_repo + "/dists/stable/Release.gpg",
              m_repo + "/dists/stable/Release"});
    QVERIFY2(v.code == 0, qPrintable(v.out));
    QVERIFY(
        readAll(m_repo + "/dists/stable/Release").contains("Architectures: " + m_arch.toLatin1()));

    const RtctlResult again = repo({"init", m_repo});
    QCOMPARE(again.code, 1);
    QVERIFY2(again.err.contains("already a repository"), qPrintable(again.err));
}

void TestComponentRepository::publishAndList()
{
    const RtctlResult r = repo({"publish", m_repo, m_pyDeb, m_nativeDeb});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    const RtctlResult listed = repo({"list", m_repo});
    QCOMPARE(listed.code, 0);
    QCOMPARE(listed.lines(),
             (QStringList {nativePackage + " 2.0.0 " + m_arch + " NativeProbe",
                           pyPackage + " 1.2 all PyGreeter"}));
    QVERIFY(QFile::exists(m_repo + "/pool/main/r/" + pyPackage + "/" + pyPackage + "_1.2_all.deb"));
    // The architecture's index lists the Architecture: all package too.
    const QByteArray packages
        = readAll(m_repo + "/dists/stable/main/binary-" + m_arch + "/Packages");
    QVERIFY(packages.contains("Package: " + pyPackage.toLatin1()));
    QVERIFY(packages.contains("Package: " + nativePackage.toLatin1()));
}

void TestComponentRepository::publishSameVersionRefused()
{
    const QByteArray release = readAll(m_repo + "/dists/stable/Release");
    const RtctlResult r = repo({"publish", m_repo, m_pyDeb});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(pyPackage + " 1.2 all is already in the repository"),
             qPrintable(r.err));
    QCOMPARE(readAll(m_repo + "/dists/stable/Release"), release);
    const RtctlResult replaced = repo({"publish", m_repo, m_pyDeb, "--replace"});
    QVERIFY2(replaced.code == 0, qPrintable(replaced.err));
    QCOMPARE(repo({"list", m_repo}).lines().size(), 2);
}

void TestComponentRepository::publishRefused_data()
{
    QTest::addColumn<QStringList>("files");
    QTest::addColumn<QString>("message");
    const QString profile = fixtures + "pycomp/RTC.xml";
    QTest::newRow("not a package") << QStringList {profile} << profile + ": not a Debian package";
    QTest::newRow("missing file") << QStringList {fixtures + "none.deb"}
                                  << fixtures + "none.deb: not a Debian package";
    QTest::newRow("given twice") << QStringList {m_nativeDeb, m_nativeDeb}
                                 << m_nativeDeb + ": " + nativePackage + " 2.0.0 " + m_arch
            + " is given twice";
}

void TestComponentRepository::publishRefused()
{
    QFETCH(QStringList, files);
    QFETCH(QString, message);
    const QByteArray release = readAll(m_repo + "/dists/stable/Release");
    const RtctlResult r = repo(QStringList {"publish", m_repo, "--replace"} + files);
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(readAll(m_repo + "/dists/stable/Release"), release);
}

void TestComponentRepository::show()
{
    const RtctlResult r = repo({"show", m_repo, pyPackage});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QVERIFY(r.out.contains("X-RTC-Profile-Id: RTC:RTStudioTests:Packaging:PyGreeter:v1_2\n"));
    QVERIFY(r.out.contains("X-RTC-Types: PyGreeter\n"));
    QVERIFY(
        r.out.contains("Filename: pool/main/r/" + pyPackage + "/" + pyPackage + "_1.2_all.deb\n"));
    QVERIFY(r.out.contains(QRegularExpression("\nSHA256: [0-9a-f]{64}\n")));
    const RtctlResult missing = repo({"show", m_repo, "rtc-nobody-none-nothing"});
    QCOMPARE(missing.code, 1);
    QVERIFY2(missing.err.contains("no package rtc-nobody-none-nothing"), qPrintable(missing.err));
}

void TestComponentRepository::failedSigningLeavesRepository()
{
    const QString suite = m_repo + "/dists/stable/";
    const QByteArray inRelease = readAll(suite + "InRelease");
    const QByteArray packages = readAll(suite + "main/binary-" + m_arch + "/Packages");
    const RtctlResult r
        = repo({"publish", m_repo, m_pyDeb, "--replace", "--key", "0000000000000000DEADBEEF"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("signing InRelease") && r.err.contains("0000000000000000DEADBEEF"),
             qPrintable(r.err));
    QCOMPARE(readAll(suite + "InRelease"), inRelease);
    QCOMPARE(readAll(suite + "main/binary-" + m_arch + "/Packages"), packages);
    // The package kept aside for the replacement is back, nothing half-written is left.
    const QString pool = m_repo + "/pool/main/r/" + pyPackage;
    QCOMPARE(QDir(pool).entryList(QDir::Files), QStringList {pyPackage + "_1.2_all.deb"});
    QVERIFY(QDir(m_repo + "/dists").entryList(QDir::Dirs | QDir::NoDotAndDotDot | QDir::Hidden)
            == QStringList {"stable"});
}

ToolOutput TestComponentRepository::apt(const QString &repository, const QString &key,
                                        const QString &show, const QString &download)
{
    // Fresh state and cache for every run: lists of an earlier run must not hide a refusal.
    static int run = 0;
    const QString root = m_work.filePath(QStringLiteral("apt%1").arg(++run));
    for (const char *dir : {"etc/sources.list.d", "etc/trusted.gpg.d", "etc/preferences.d",
                            "state/lists/partial", "cache/archives/partial", "download"})
        QDir().mkpath(root + '/' + dir);
    QFile sources(root + "/etc/sources.list");
    if (!sources.open(QIODevice::WriteOnly)
        || sources.write(QStringLiteral("deb [signed-by=%1] file:%2 stable main\n")
                             .arg(key, repository)
                             .toUtf8())
            < 0)
        return {};
    sources.close();
    const QString user = tool("id", {"-un"}).out.trimmed();
    // Everything apt keeps goes below root: no change to /etc or /var, no root needed.
    const QStringList options {"-o", "Dir::Etc=" + root + "/etc",
                               "-o", "Dir::Etc::sourcelist=" + root + "/etc/sources.list",
                               "-o", "Dir::Etc::sourceparts=" + root + "/etc/sources.list.d",
                               "-o", "Dir::Etc::trustedparts=" + root + "/etc/trusted.gpg.d",
                               "-o", "Dir::State=" + root + "/state",
                               "-o", "Dir::Cache=" + root + "/cache",
                               "-o", "Dir::State::status=/dev/null",
                               "-o", "APT::Get::List-Cleanup=0",
                               "-o", "APT::Sandbox::User=" + user,
                               "-o", "Debug::NoLocking=1"};
    ToolOutput update = tool("apt-get", options + QStringList {"update"});
    if (update.code != 0 || show.isEmpty())
        return update;
    if (!download.isEmpty()) {
        const ToolOutput fetched
            = tool("apt-get", options + QStringList {"download", download}, root + "/download");
        if (fetched.code != 0)
            return fetched;
        if (QDir(root + "/download").entryList({"*.deb"}, QDir::Files).size() != 1)
            return {1, "apt-get download fetched no .deb"};
    }
    return tool("apt-cache", options + QStringList {"show", show});
}

void TestComponentRepository::aptReadsRepository()
{
    const QString key = m_repo + "/archive-key.gpg";
    ToolOutput r = apt(m_repo, key, pyPackage, pyPackage);
    QVERIFY2(r.code == 0, qPrintable(r.out));
    QVERIFY2(r.out.contains("Package: " + pyPackage + "\n"), qPrintable(r.out));
    QVERIFY2(r.out.contains("X-RTC-Profile-Id: RTC:RTStudioTests:Packaging:PyGreeter:v1_2"),
             qPrintable(r.out));
    r = apt(m_repo, key, nativePackage);
    QVERIFY2(r.code == 0, qPrintable(r.out));
    QVERIFY2(r.out.contains("X-RTC-Types: NativeProbe"), qPrintable(r.out));
}

void TestComponentRepository::aptRefusesChangedIndex()
{
    const QString copy = m_work.filePath("changed");
    QVERIFY(copyTree(m_repo, copy));
    // A Packages file (and its compressed copies) that no longer matches the signed Release.
    const QString folder = copy + "/dists/stable/main/binary-" + m_arch + "/";
    QByteArray packages = readAll(folder + "Packages").replace("Version: 1.2", "Version: 9.9");
    QFile file(folder + "Packages");
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate)
            && file.write(packages) == packages.size());
    file.close();
    QVERIFY(tool("sh", {"-c", "gzip -9nc Packages > Packages.gz && xz -c Packages > Packages.xz"},
                 folder)
                .code
            == 0);
    const ToolOutput r = apt(copy, copy + "/archive-key.gpg", pyPackage);
    QVERIFY2(r.code != 0, qPrintable(r.out));
    QVERIFY2(r.out.contains("Hash Sum mismatch") || r.out.contains("unexpected size"),
             qPrintable(r.out));
}

void TestComponentRepository::aptRefusesUnsignedIndex()
{
    const QString copy = m_work.filePath("unsigned");
    QVERIFY(copyTree(m_repo, copy));
    QVERIFY(QFile::remove(copy + "/dists/stable/InRelease"));
    QVERIFY(QFile::remove(copy + "/dists/stable/Release.gpg"));
    const ToolOutput r = apt(copy, copy + "/archive-key.gpg", pyPackage);
    QVERIFY2(r.code != 0, qPrintable(r.out));
    QVERIFY2(r.out.contains("is not signed"), qPrintable(r.out));
}

void TestComponentRepository::aptRefusesOtherKey()
{
    // A second repository's key as signed-by: the signature is good, but not by the key trusted.
    m_otherGnupg = m_work.filePath("othergnupg");
    const QString other = m_work.filePath("otherrepo");
    QVERIFY(repo({"init", other, "--new-key", "--gnupg-home", m_otherGnupg}).code == 0);
    const ToolOutput r = apt(m_repo, other + "/archive-key.gpg", pyPackage);
    QVERIFY2(r.code != 0, qPrintable(r.out));
    QVERIFY2(r.out.contains("NO_PUBKEY") || r.out.contains("not signed"), qPrintable(r.out));
}

void TestComponentRepository::verifierFollowsTrust()
{
    QString error;
    const std::optional<Packages::VerifiedRelease> release = Packages::VerifiedRelease::verify(
        readAll(m_repo + "/dists/stable/InRelease"), m_repo + "/archive-key.gpg", &error);
    QVERIFY2(release, qPrintable(error));
    QCOMPARE(release->value("Suite"), QStringLiteral("stable"));
    const QString index = "main/binary-" + m_arch + "/Packages";
    QVERIFY2(release->check(index, readAll(m_repo + "/dists/stable/" + index), &error),
             qPrintable(error));
    // The library reads the same entries, and the pool's file matches its entry.
    Packages::Repository repository(m_repo);
    QVERIFY2(repository.open(&error), qPrintable(error));
    const std::optional<QList<Packages::IndexEntry>> entries = repository.packages(&error);
    QVERIFY2(entries && entries->size() == 2, qPrintable(error));
    for (const Packages::IndexEntry &entry : *entries)
        QVERIFY2(Packages::checkPackageFile(entry, m_repo + '/' + entry.filename(), &error),
                 qPrintable(error));
}

void TestComponentRepository::verifierRefuses_data()
{
    QTest::addColumn<QString>("change"); // what is altered
    QTest::addColumn<QString>("message");
    QTest::newRow("InRelease changed") << "inrelease"
                                       << "BAD signature";
    QTest::newRow("another key") << "key"
                                 << "gpgv";
    QTest::newRow("Packages changed") << "packages"
                                      << "does not match Release";
    QTest::newRow("package byte flipped") << "deb"
                                          << "does not match the index";
}

void TestComponentRepository::verifierRefuses()
{
    QFETCH(QString, change);
    QFETCH(QString, message);
    QString error;
    QByteArray inRelease = readAll(m_repo + "/dists/stable/InRelease");
    if (change == "inrelease")
        inRelease.replace("Suite: stable", "Suite: stabel");
    const QString keyring = change == "key" ? m_work.filePath("otherrepo/archive-key.gpg")
                                            : m_repo + "/archive-key.gpg";
    const std::optional<Packages::VerifiedRelease> release
        = Packages::VerifiedRelease::verify(inRelease, keyring, &error);
    if (change == "inrelease" || change == "key") {
        QVERIFY(!release);
        QVERIFY2(error.contains(message) && error.contains(keyring), qPrintable(error));
        return;
    }
    QVERIFY2(release, qPrintable(error));
    const QString index = "main/binary-" + m_arch + "/Packages";
    QByteArray packages = readAll(m_repo + "/dists/stable/" + index);
    if (change == "packages") {
        packages.replace("Version: 2.0.0", "Version: 2.0.1");
        QVERIFY(!release->check(index, packages, &error));
        QVERIFY2(error.contains(index) && error.contains(message), qPrintable(error));
        return;
    }
    const std::optional<QList<Packages::DebControl>> paragraphs
        = Packages::DebControl::parseAll(packages);
    QVERIFY(paragraphs && !paragraphs->isEmpty());
    const Packages::IndexEntry entry {paragraphs->first()};
    QByteArray deb = readAll(m_repo + '/' + entry.filename());
    deb[deb.size() / 2] = char(deb.at(deb.size() / 2) ^ 1);
    const QString flipped = m_work.filePath("flipped.deb");
    QFile file(flipped);
    QVERIFY(file.open(QIODevice::WriteOnly) && file.write(deb) == deb.size());
    file.close();
    QVERIFY(!Packages::checkPackageFile(entry, flipped, &error));
    QVERIFY2(error.contains(entry.package()) && error.contains(message), qPrintable(error));
}

void TestComponentRepository::remove()
{
    RtctlResult r = repo({"remove", m_repo, pyPackage + "=1.2"});
    QVERIFY2(r.code == 0, qPrintable(r.err));
    QCOMPARE(r.lines(), QStringList {"removed " + pyPackage + " 1.2 all"});
    QCOMPARE(repo({"list", m_repo}).lines(),
             QStringList {nativePackage + " 2.0.0 " + m_arch + " NativeProbe"});
    QVERIFY(!QFileInfo::exists(m_repo + "/pool/main/r/" + pyPackage));
    r = repo({"remove", m_repo, pyPackage});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("no package " + pyPackage), qPrintable(r.err));
    // apt sees it gone, the other still there.
    const QString key = m_repo + "/archive-key.gpg";
    QVERIFY(apt(m_repo, key, pyPackage).code != 0);
    const ToolOutput native = apt(m_repo, key, nativePackage);
    QVERIFY2(native.code == 0, qPrintable(native.out));
}

QTEST_GUILESS_MAIN(TestComponentRepository)
#include "tst_componentrepository.moc"
