// SPDX-License-Identifier: MIT
#include "rtcrepository.h"

#include <QAbstractItemModelTester>
#include <QFile>
#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace SystemEditor;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/systemeditor/")) + name;
}

QModelIndex category(const RtcRepository &repository, const QString &name)
{
    for (int row = 0; row < repository.rowCount(); ++row) {
        const QModelIndex index = repository.index(row, 0);
        if (index.data().toString() == name)
            return index;
    }
    return {};
}

QStringList childNames(const QModelIndex &parent)
{
    QStringList names;
    for (int row = 0; row < parent.model()->rowCount(parent); ++row)
        names << parent.model()->index(row, 0, parent).data().toString();
    return names;
}

} // namespace

class TestSeRepository : public QObject
{
    Q_OBJECT

private slots:
    void folderIsSearchedRecursively();
    void singleFilesAndErrors();
    void mimeDataCarriesFilePaths();
    void reloadSeesNewFiles();
    void removeSourceAndMissingPaths();
};

void TestSeRepository::folderIsSearchedRecursively()
{
    RtcRepository repository;
    QAbstractItemModelTester tester(&repository,
                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
    QVERIFY(repository.addSource(dataPath("rtcs")));
    // notaprofile.xml is skipped silently; the YAML profile in sub/ is found.
    QCOMPARE(repository.entries().size(), 5);
    QVERIFY(repository.errors().isEmpty());
    QCOMPARE(repository.rowCount(), 3);
    QCOMPARE(childNames(category(repository, "example")), QStringList({"ConsoleIn", "ConsoleOut"}));
    QCOMPARE(childNames(category(repository, "service")), QStringList({"Consumer", "Provider"}));
    QCOMPARE(childNames(category(repository, "yaml")), QStringList {"Yamlish"});
    const QModelIndex consoleIn = repository.index(0, 0, category(repository, "example"));
    QCOMPARE(consoleIn.data(RtcRepository::ComponentIdRole).toString(),
             QStringLiteral("RTC:TestVendor:example:ConsoleIn:1.0.0"));
    QVERIFY(category(repository, "example").data(RtcRepository::IsCategoryRole).toBool());
    QVERIFY(repository.profileForFile(dataPath("rtcs/ConsoleOut.xml")));
    QVERIFY(repository.flags(consoleIn) & Qt::ItemIsDragEnabled);
    QVERIFY(!(repository.flags(category(repository, "example")) & Qt::ItemIsDragEnabled));
}

void TestSeRepository::singleFilesAndErrors()
{
    RtcRepository repository;
    QAbstractItemModelTester tester(&repository,
                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy errorsChanged(&repository, &RtcRepository::errorsChanged);
    QVERIFY(repository.addSource(dataPath("rtcs/ConsoleIn.xml")));
    QVERIFY(repository.addSource(dataPath("broken/Broken.xml")));
    QVERIFY(repository.addSource(dataPath("rtcs/notaprofile.xml")));
    QCOMPARE(repository.entries().size(), 1);
    QCOMPARE(repository.errors().size(), 2);
    QCOMPARE(errorsChanged.size(), 2);
    const QModelIndex errors = category(repository, RtcRepository::errorCategoryName());
    QVERIFY(errors.isValid());
    QCOMPARE(childNames(errors), QStringList({"Broken.xml", "notaprofile.xml"}));
    const QString tip = repository.index(0, 0, errors).data(Qt::ToolTipRole).toString();
    // The reason names the file and the line of the fault.
    QVERIFY2(tip.contains("Broken.xml:"), qPrintable(tip));
    QVERIFY(!repository.entry(repository.index(0, 0, errors)));
    QVERIFY(!(repository.flags(repository.index(0, 0, errors)) & Qt::ItemIsDragEnabled));
}

void TestSeRepository::mimeDataCarriesFilePaths()
{
    RtcRepository repository;
    repository.addSource(dataPath("rtcs"));
    QCOMPARE(repository.mimeTypes(), QStringList {"application/x-rtstudio-rtc-profile"});
    const QModelIndex example = category(repository, "example");
    std::unique_ptr<QMimeData> mime(
        repository.mimeData({repository.index(0, 0, example), repository.index(1, 0, example)}));
    QVERIFY(mime);
    const QStringList paths =
        QString::fromUtf8(mime->data(RtcRepository::MimeType)).split(QLatin1Char('\n'));
    QCOMPARE(paths.size(), 2);
    QVERIFY(paths.at(0).endsWith("rtcs/ConsoleIn.xml"));
    QVERIFY(!repository.mimeData({example}));
}

void TestSeRepository::reloadSeesNewFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QFile::copy(dataPath("rtcs/ConsoleIn.xml"), dir.filePath("a.xml")));
    RtcRepository repository;
    QAbstractItemModelTester tester(&repository,
                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
    repository.addSource(dir.path());
    QCOMPARE(repository.entries().size(), 1);
    QVERIFY(QFile::copy(dataPath("rtcs/ConsoleOut.xml"), dir.filePath("b.xml")));
    QCOMPARE(repository.entries().size(), 1);
    repository.reload();
    QCOMPARE(repository.entries().size(), 2);
}

void TestSeRepository::removeSourceAndMissingPaths()
{
    RtcRepository repository;
    QVERIFY(!repository.addSource(dataPath("does-not-exist")));
    repository.addSource(dataPath("rtcs/ConsoleIn.xml"));
    repository.addSource(dataPath("rtcs/ConsoleIn.xml"));
    QCOMPARE(repository.sources().size(), 1);
    repository.removeSource(dataPath("rtcs/ConsoleIn.xml"));
    QCOMPARE(repository.rowCount(), 0);
    repository.addSource(dataPath("rtcs"));
    repository.clear();
    QVERIFY(repository.entries().isEmpty());
}

QTEST_GUILESS_MAIN(TestSeRepository)
#include "tst_serepository.moc"
