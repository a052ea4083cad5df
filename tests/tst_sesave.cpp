// SPDX-License-Identifier: MIT
#include "systemfile.h"
#include "systemmodel.h"

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

using namespace Profile;
using namespace SystemEditor;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/systemeditor/")) + name;
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool copyTree(const QString &from, const QString &to)
{
    QDir().mkpath(to);
    const QDir source(from);
    for (const QFileInfo &info : source.entryInfoList(QDir::Files | QDir::Dirs | QDir::NoDotAndDotDot)) {
        const QString target = QDir(to).filePath(info.fileName());
        if (info.isDir() ? !copyTree(info.filePath(), target) : !QFile::copy(info.filePath(), target))
            return false;
    }
    return true;
}

std::optional<RtsProfile> reload(const QString &path)
{
    Diagnostics diagnostics;
    const std::optional<LoadedSystem> loaded = loadSystemFile(path, &diagnostics);
    if (!loaded)
        return std::nullopt;
    return loaded->profile;
}

} // namespace

class TestSeSave : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void offlineSaveCopiesRtcProfiles();
    void savedFileReadsBackTheSame();
    void datesAreStamped();
    void yamlSave();
    void failedSaveKeepsTheOldFile();
    void fileUriAndMissingPaths();
    void unreadableRtcProfileIsAWarning();
    void conformanceSystemsOpenAndSave_data();
    void conformanceSystemsOpenAndSave();

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<SystemModel> m_model;
};

void TestSeSave::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
    // The fixture refers to its RTC profiles by relative pathUri ("../rtcs/…").
    QVERIFY(copyTree(dataPath("system"), m_dir->filePath("in/system")));
    QVERIFY(copyTree(dataPath("rtcs"), m_dir->filePath("in/rtcs")));
    Diagnostics diagnostics;
    const std::optional<LoadedSystem> loaded =
        loadSystemFile(m_dir->filePath("in/system/system.xml"), &diagnostics);
    QVERIFY(loaded);
    QCOMPARE(loaded->rtcProfiles.size(), 2);
    m_model = std::make_unique<SystemModel>();
    m_model->setProfile(loaded->profile, loaded->rtcProfiles);
}

void TestSeSave::offlineSaveCopiesRtcProfiles()
{
    const QString path = m_dir->filePath("out/Demo/Demo.xml");
    QDir().mkpath(m_dir->filePath("out/Demo"));
    Diagnostics diagnostics;
    QSignalSpy changed(m_model.get(), &SystemModel::componentChanged);
    QVERIFY(saveSystemFile(*m_model, path, &diagnostics));
    QVERIFY(diagnostics.isEmpty());
    for (const QString &instance : {QStringLiteral("ConsoleIn0"), QStringLiteral("ConsoleOut0")}) {
        const QString copy = m_dir->filePath("out/Demo/RTCs/" + instance + ".xml");
        QVERIFY2(QFile::exists(copy), qPrintable(copy));
        const std::optional<LoadedProfile> rtc = loadProfileFile(copy, &diagnostics);
        QVERIFY(rtc && rtc->rtc);
        QCOMPARE(*rtc->rtc, *m_model->rtcProfile(instance));
        QCOMPARE(m_model->component(instance)->pathUri, "RTCs/" + instance + ".xml");
    }
    // A component without an RTC profile keeps its path (a naming-service path here).
    QCOMPARE(m_model->component("Mystery0")->pathUri, QStringLiteral("localhost/Mystery0.rtc"));
    QCOMPARE(changed.size(), 2);
    // The saved file opens again with its RTC profiles found next to it.
    Diagnostics warnings;
    const std::optional<LoadedSystem> again = loadSystemFile(path, &warnings);
    QVERIFY(again);
    QCOMPARE(again->rtcProfiles.size(), 2);
    QVERIFY(warnings.isEmpty());
}

void TestSeSave::savedFileReadsBackTheSame()
{
    const QString path = m_dir->filePath("Demo.xml");
    Diagnostics diagnostics;
    QVERIFY(saveSystemFile(*m_model, path, &diagnostics));
    const std::optional<RtsProfile> saved = reload(path);
    QVERIFY(saved);
    // Everything survives: ids, the connector and its unknown property and bend points,
    // groups, the StartUp sequence, unknown elements and properties.
    QCOMPARE(*saved, m_model->profile());
    QCOMPARE(saved->dataPortConnectors.at(0).connectorId, QStringLiteral("c-1"));
    QCOMPARE(rtsPropertyValue(saved->dataPortConnectors.at(0).properties, "vendor.custom"),
             std::optional<QString>("42"));
    QCOMPARE(saved->groups.size(), 1);
    QVERIFY(saved->startUp);
    QVERIFY(!saved->components.at(0).extras.isEmpty());
    QVERIFY(!saved->extras.isEmpty());
    QCOMPARE(rtsPropertyValue(saved->properties, "system.custom"), std::optional<QString>("yes"));
    QVERIFY(readAll(path).contains("RTSystem:TestVendor:Demo:1.0"));
}

void TestSeSave::datesAreStamped()
{
    const QString before = m_model->profile().updateDate;
    QVERIFY(saveSystemFile(*m_model, m_dir->filePath("Demo.xml"), nullptr));
    QCOMPARE(m_model->profile().creationDate, QStringLiteral("2024-01-02T03:04:05+09:00"));
    QVERIFY(m_model->profile().updateDate != before);
    const QDateTime stamped = QDateTime::fromString(m_model->profile().updateDate, Qt::ISODate);
    QVERIFY(stamped.isValid());
    QVERIFY(qAbs(stamped.secsTo(QDateTime::currentDateTime())) < 120);

    // A system that never had a creation date gets one.
    m_model->setProfile(RtsProfile(), {});
    QVERIFY(saveSystemFile(*m_model, m_dir->filePath("Empty.xml"), nullptr));
    QCOMPARE(m_model->profile().creationDate, m_model->profile().updateDate);
    QCOMPARE(m_model->profile().version, QStringLiteral("0.2"));
}

void TestSeSave::yamlSave()
{
    const QString path = m_dir->filePath("Demo.yaml");
    QVERIFY(saveSystemFile(*m_model, path, nullptr));
    QVERIFY(readAll(path).startsWith("rtsProfile:"));
    const std::optional<RtsProfile> saved = reload(path);
    QVERIFY(saved);
    QCOMPARE(saved->components.size(), 3);
    QCOMPARE(saved->components.at(0).pathUri, QStringLiteral("RTCs/ConsoleIn0.xml"));
    QCOMPARE(saved->dataPortConnectors.at(0).connectorId, QStringLiteral("c-1"));
}

void TestSeSave::failedSaveKeepsTheOldFile()
{
    const QString path = m_dir->filePath("Demo.xml");
    QFile old(path);
    QVERIFY(old.open(QIODevice::WriteOnly));
    old.write("old content");
    old.close();
    // A file where the RTCs folder must go makes the save fail before the system file.
    QFile blocker(m_dir->filePath("RTCs"));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    const RtsProfile before = m_model->profile();
    Diagnostics diagnostics;
    QVERIFY(!saveSystemFile(*m_model, path, &diagnostics));
    QVERIFY(!diagnostics.isEmpty());
    QCOMPARE(readAll(path), QByteArray("old content"));
    QCOMPARE(m_model->profile(), before);

    // Writing the system file itself fails (its path is a folder): nothing changes either.
    QDir().mkpath(m_dir->filePath("folder.xml"));
    diagnostics.clear();
    SaveOptions noCopies;
    noCopies.copyRtcProfiles = false;
    QVERIFY(!saveSystemFile(*m_model, m_dir->filePath("folder.xml"), &diagnostics, noCopies));
    QVERIFY(!diagnostics.isEmpty());
    QCOMPARE(m_model->profile(), before);
}

void TestSeSave::fileUriAndMissingPaths()
{
    const QString system = m_dir->filePath("in/system/system.xml");
    const QString rtc = m_dir->filePath("in/rtcs/ConsoleIn.xml");
    QCOMPARE(resolvePathUri(QUrl::fromLocalFile(rtc).toString(), system),
             QFileInfo(rtc).absoluteFilePath());
    QCOMPARE(resolvePathUri("../rtcs/ConsoleIn.xml", system), QFileInfo(rtc).absoluteFilePath());
    QCOMPARE(resolvePathUri(rtc, "/elsewhere/x.xml"), QFileInfo(rtc).absoluteFilePath());
    QVERIFY(resolvePathUri("localhost/ConsoleIn0.rtc", system).isEmpty());
    QVERIFY(resolvePathUri("", system).isEmpty());
    QVERIFY(resolvePathUri("../rtcs", system).isEmpty()); // a folder is no profile
}

void TestSeSave::unreadableRtcProfileIsAWarning()
{
    RtsProfile profile = RtsProfile::createNew("V", "S", "1");
    RtsComponent broken;
    broken.instanceName = "Broken0";
    broken.pathUri = dataPath("broken/Broken.xml");
    profile.components << broken;
    Diagnostics warnings;
    const QHash<QString, RtcProfile> found = resolveRtcProfiles(profile, dataPath("s.xml"), &warnings);
    QVERIFY(found.isEmpty());
    QVERIFY(!warnings.isEmpty());
    QCOMPARE(warnings.first().severity, Diagnostic::Severity::Warning);
    QVERIFY(warnings.first().message.contains("Broken0"));

    Diagnostics errors;
    QVERIFY(!loadSystemFile(dataPath("rtcs/ConsoleIn.xml"), &errors));
    QVERIFY(!errors.isEmpty());
}

void TestSeSave::conformanceSystemsOpenAndSave_data()
{
    QTest::addColumn<QString>("path");
    const QDir dir(RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/rts"));
    if (!dir.exists())
        QSKIP("The shared conformance folder is absent.");
    for (const QFileInfo &info : dir.entryInfoList(QDir::Files))
        QTest::newRow(qPrintable(info.fileName())) << info.filePath();
}

void TestSeSave::conformanceSystemsOpenAndSave()
{
    QFETCH(QString, path);
    Diagnostics diagnostics;
    const std::optional<LoadedSystem> loaded = loadSystemFile(path, &diagnostics);
    QVERIFY(loaded);
    SystemModel model;
    model.setProfile(loaded->profile, loaded->rtcProfiles);
    QVERIFY(!model.componentIds().isEmpty());
    for (const QString &name : model.componentIds())
        model.ports(name);
    const QString out = m_dir->filePath(QFileInfo(path).fileName());
    QVERIFY(saveSystemFile(model, out, &diagnostics));
    const std::optional<RtsProfile> saved = reload(out);
    QVERIFY(saved);
    QCOMPARE(*saved, model.profile());
}

QTEST_GUILESS_MAIN(TestSeSave)
#include "tst_sesave.moc"
