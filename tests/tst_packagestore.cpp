// SPDX-License-Identifier: MIT
// The package store of managers that install without root, and the node's dependency check:
// versions listed newest first, a staging folder committed in one rename or discarded, leftovers
// of an interrupted install deleted by prepare(), a version removed; Depends entries met by
// Debian packages installed here (dpkg-query) or by component packages in the store, with
// alternatives and version relations, and those not met named as written.
#include <dependencycheck.h>
#include <packagestore.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

namespace {

/// Commits a package version with only its control data into @p store.
bool addVersion(const Packages::PackageStore &store, const QString &name, const QString &version,
                QString *error)
{
    const std::optional<QString> staging = store.createStaging(error);
    if (!staging)
        return false;
    QFile control(*staging + "/control");
    const QByteArray text = "Package: " + name.toUtf8() + "\nVersion: " + version.toUtf8()
        + "\nArchitecture: all\nX-RTC-Types: A, B\n";
    if (!control.open(QIODevice::WriteOnly) || control.write(text) != text.size())
        return false;
    control.close();
    QDir().mkpath(*staging + "/root/usr/lib/rtstudio/components/" + name);
    return store.commit(*staging, name, version, error);
}

} // namespace

class TestPackageStore : public QObject
{
    Q_OBJECT

private slots:
    void versionsNewestFirst();
    void commitRefusesInstalledVersion();
    void prepareDeletesLeftovers();
    void removeVersion();
    void dependencies_data();
    void dependencies();
    void relations_data();
    void relations();
};

void TestPackageStore::versionsNewestFirst()
{
    QTemporaryDir dir;
    const Packages::PackageStore store(dir.filePath("store"));
    QString error;
    for (const char *version : {"1.0", "1.10", "1.2~rc1", "1.2"})
        QVERIFY2(addVersion(store, "rtc-a", version, &error), qPrintable(error));
    QStringList versions;
    for (const Packages::InstalledPackage &package : store.versions("rtc-a"))
        versions << package.version;
    QCOMPARE(versions, QStringList({"1.10", "1.2", "1.2~rc1", "1.0"}));
    const Packages::InstalledPackage newest = store.versions("rtc-a").first();
    QCOMPARE(newest.componentTypes, QStringList({"A", "B"}));
    QCOMPARE(newest.path, dir.filePath("store/rtc-a/1.10"));
    QCOMPARE(newest.moduleDirs(),
             QStringList {newest.path + "/root/usr/lib/rtstudio/components/rtc-a"});
    QCOMPARE(store.moduleDirs("1.0").size(), 1);
    QCOMPARE(store.moduleDirs(QString()).first(), newest.moduleDirs().first());
}

void TestPackageStore::commitRefusesInstalledVersion()
{
    QTemporaryDir dir;
    const Packages::PackageStore store(dir.filePath("store"));
    QString error;
    QVERIFY(addVersion(store, "rtc-a", "1.0", &error));
    QVERIFY(!addVersion(store, "rtc-a", "1.0", &error));
    QVERIFY2(error.contains("rtc-a 1.0 is already installed"), qPrintable(error));
}

void TestPackageStore::prepareDeletesLeftovers()
{
    QTemporaryDir dir;
    const Packages::PackageStore store(dir.filePath("store"));
    QString error;
    QVERIFY(store.prepare(&error)); // no store yet: nothing to do, nothing made
    QVERIFY(!QFileInfo::exists(store.root()));
    QVERIFY(addVersion(store, "rtc-a", "1.0", &error));
    const std::optional<QString> staging = store.createStaging(&error);
    QVERIFY(staging);
    QVERIFY(QDir().mkpath(*staging + "/root/usr"));
    QVERIFY(QDir().mkpath(store.root() + "/rtc-empty"));
    QVERIFY(store.prepare(&error));
    QVERIFY(!QFileInfo::exists(*staging));
    QVERIFY(!QFileInfo::exists(store.root() + "/rtc-empty"));
    QCOMPARE(store.installed().size(), 1);
}

void TestPackageStore::removeVersion()
{
    QTemporaryDir dir;
    const Packages::PackageStore store(dir.filePath("store"));
    QString error;
    QVERIFY(addVersion(store, "rtc-a", "1.0", &error));
    QVERIFY(addVersion(store, "rtc-a", "2.0", &error));
    QVERIFY2(store.remove(store.versions("rtc-a").last(), &error), qPrintable(error));
    QCOMPARE(store.versions("rtc-a").size(), 1);
    QCOMPARE(store.versions("rtc-a").first().version, QStringLiteral("2.0"));
    QVERIFY(store.remove(store.versions("rtc-a").first(), &error));
    QVERIFY(store.installed().isEmpty());
    QCOMPARE(QDir(store.root()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
             QStringList());
}

void TestPackageStore::dependencies_data()
{
    QTest::addColumn<QString>("depends");
    QTest::addColumn<QStringList>("unmet");

    // dpkg itself is on every Debian system.
    QTest::newRow("none") << QString() << QStringList();
    QTest::newRow("installed") << "dpkg" << QStringList();
    QTest::newRow("with arch and version") << "dpkg:any (>= 1.0)" << QStringList();
    QTest::newRow("too old") << "dpkg (>= 999)" << QStringList {"dpkg (>= 999)"};
    QTest::newRow("missing") << "dpkg, librtstudio-nowhere0"
                             << QStringList {"librtstudio-nowhere0"};
    QTest::newRow("alternative met") << "librtstudio-nowhere0 | dpkg" << QStringList();
    QTest::newRow("component package in the store") << "rtc-b (>= 1.0)" << QStringList();
    QTest::newRow("component package too old")
        << "rtc-b (>> 1.5), librtstudio-nowhere0 | rtc-c"
        << QStringList {"rtc-b (>> 1.5)", "librtstudio-nowhere0 | rtc-c"};
}

void TestPackageStore::dependencies()
{
    QFETCH(QString, depends);
    QFETCH(QStringList, unmet);
    QTemporaryDir dir;
    const Packages::PackageStore store(dir.filePath("store"));
    QString error;
    QVERIFY(addVersion(store, "rtc-b", "1.5", &error));
    QCOMPARE(Packages::unmetDependencies(depends, store), unmet);
}

void TestPackageStore::relations_data()
{
    QTest::addColumn<QString>("version");
    QTest::addColumn<QString>("relation");
    QTest::addColumn<QString>("wanted");
    QTest::addColumn<bool>("satisfied");

    QTest::newRow("any") << "1.0"
                         << ""
                         << "" << true;
    QTest::newRow("<< yes") << "1.0"
                            << "<<"
                            << "1.1" << true;
    QTest::newRow("<< equal") << "1.0"
                              << "<<"
                              << "1.0" << false;
    QTest::newRow("<= equal") << "1.0"
                              << "<="
                              << "1.0" << true;
    QTest::newRow("= tilde") << "1.0~rc1"
                             << "="
                             << "1.0" << false;
    QTest::newRow(">= epoch") << "1:0.1"
                              << ">="
                              << "2.0" << true;
    QTest::newRow(">> no") << "2.0"
                           << ">>"
                           << "2.0" << false;
}

void TestPackageStore::relations()
{
    QFETCH(QString, version);
    QFETCH(QString, relation);
    QFETCH(QString, wanted);
    QFETCH(bool, satisfied);
    QCOMPARE(Packages::versionSatisfies(version, relation, wanted), satisfied);
}

QTEST_GUILESS_MAIN(TestPackageStore)
#include "tst_packagestore.moc"
