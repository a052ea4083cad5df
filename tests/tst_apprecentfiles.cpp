// SPDX-License-Identifier: MIT
// The recent-files list: newest first, no duplicates, bounded, missing files pruned.
#include "recentfiles.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace Studio;

class TestAppRecentFiles : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void newestFirstWithoutDuplicates();
    void keepsAtMostTheMaximum();
    void prunesMissingFiles();
    void removeAndClear();
    void survivesRestart();

private:
    QString touch(const QString &name);

    QTemporaryDir m_settingsDir;
    QTemporaryDir m_files;
};

void TestAppRecentFiles::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_apprecentfiles"));
}

void TestAppRecentFiles::init()
{
    QSettings().clear();
}

QString TestAppRecentFiles::touch(const QString &name)
{
    const QString path = m_files.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        qFatal("cannot create %s", qPrintable(path));
    return path;
}

void TestAppRecentFiles::newestFirstWithoutDuplicates()
{
    RecentFiles recent;
    QSignalSpy spy(&recent, &RecentFiles::changed);
    const QString a = touch(QStringLiteral("a.xml"));
    const QString b = touch(QStringLiteral("b.yaml"));
    recent.add(a);
    recent.add(b);
    recent.add(a);
    QCOMPARE(recent.files(), (QStringList {a, b}));
    QCOMPARE(spy.count(), 3);
    // A relative or unclean spelling of the same file is the same entry.
    recent.add(QDir(m_files.path()).filePath(QStringLiteral("./b.yaml")));
    QCOMPARE(recent.files(), (QStringList {b, a}));
}

void TestAppRecentFiles::keepsAtMostTheMaximum()
{
    RecentFiles recent;
    QCOMPARE(recent.maximum(), 10);
    QStringList added;
    for (int i = 0; i < 12; ++i) {
        added.prepend(touch(QStringLiteral("f%1.xml").arg(i)));
        recent.add(added.first());
    }
    QCOMPARE(recent.files(), added.mid(0, 10));
    recent.setMaximum(3);
    QCOMPARE(recent.files(), added.mid(0, 3));
}

void TestAppRecentFiles::prunesMissingFiles()
{
    RecentFiles recent;
    const QString kept = touch(QStringLiteral("kept.xml"));
    const QString gone = touch(QStringLiteral("gone.xml"));
    recent.add(kept);
    recent.add(gone);
    QVERIFY(QFile::remove(gone));
    QSignalSpy spy(&recent, &RecentFiles::changed);
    QCOMPARE(recent.files(), QStringList {kept});
    QCOMPARE(spy.count(), 1);
    QCOMPARE(QSettings().value(QStringLiteral("recentFiles")).toStringList(), QStringList {kept});
}

void TestAppRecentFiles::removeAndClear()
{
    RecentFiles recent;
    const QString a = touch(QStringLiteral("a.xml"));
    const QString b = touch(QStringLiteral("b.xml"));
    recent.add(a);
    recent.add(b);
    recent.remove(a);
    QCOMPARE(recent.files(), QStringList {b});
    recent.clear();
    QVERIFY(recent.files().isEmpty());
}

void TestAppRecentFiles::survivesRestart()
{
    const QString a = touch(QStringLiteral("a.xml"));
    {
        RecentFiles recent;
        recent.add(a);
    }
    RecentFiles again;
    QCOMPARE(again.files(), QStringList {a});
}

QTEST_GUILESS_MAIN(TestAppRecentFiles)
#include "tst_apprecentfiles.moc"
