// SPDX-License-Identifier: MIT
#include "idltypelibrary.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace Codegen;

namespace {

QString dataDir()
{
    return RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/idl");
}

QStringList dataTypeNames(const IdlTypeLibrary &library, bool timedOnly = false)
{
    QStringList names;
    for (const IdlDataType &type : library.dataTypes()) {
        if (!timedOnly || type.timed)
            names.append(type.scopedName);
    }
    return names;
}

QStringList interfaceNames(const IdlTypeLibrary &library)
{
    QStringList names;
    for (const IdlInterface &interface : library.interfaces())
        names.append(interface.scopedName);
    return names;
}

bool writeFile(const QString &path, const QByteArray &text)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) == text.size();
}

} // namespace

class TestIdlTypeLibrary : public QObject
{
    Q_OBJECT

private slots:
    void listsDataTypesAndInterfacesSorted();
    void reloadsChangedFolders();
    void keepsGoingPastBrokenFiles();
    void readsEachFileNameOnceAcrossFolders();
    void bundledSetOffersOpenRtpTypes_data();
    void bundledSetOffersOpenRtpTypes();
};

void TestIdlTypeLibrary::listsDataTypesAndInterfacesSorted()
{
    const IdlTypeLibrary library({dataDir(), dataDir() + QStringLiteral("/include")});
    QVERIFY2(library.diagnostics().isEmpty(), qPrintable(library.diagnostics().value(0).toString()));
    QCOMPARE(dataTypeNames(library),
             (QStringList{"A::FromA", "B::FromB", "RTC::Point2D", "RTC::Pose3D", "RTC::Time", "RTC::TimedDouble",
                          "RTC::TimedLong", "RTC::TimedLongSeq", "RTC::TimedPoint2D", "RTC::TimedString"}));
    QCOMPARE(dataTypeNames(library, true),
             (QStringList{"RTC::TimedDouble", "RTC::TimedLong", "RTC::TimedLongSeq", "RTC::TimedPoint2D",
                          "RTC::TimedString"}));
    QCOMPARE(interfaceNames(library),
             (QStringList{"SimpleService::Base_", "SimpleService::Echo", "SimpleService::MyService"}));
    QVERIFY(library.fileOf(QStringLiteral("RTC::TimedLong")).endsWith(QLatin1String("include/BasicDataType.idl")));
    QVERIFY(library.fileOf(QStringLiteral("SimpleService::MyService")).endsWith(QLatin1String("MyService.idl")));
    QVERIFY(library.fileOf(QStringLiteral("No::Such")).isEmpty());
}

void TestIdlTypeLibrary::reloadsChangedFolders()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QFile::copy(dataDir() + QStringLiteral("/include/BasicDataType.idl"), dir.filePath("BasicDataType.idl")));
    IdlTypeLibrary library({dir.path()});
    QVERIFY(dataTypeNames(library).contains(QStringLiteral("RTC::TimedLong")));
    QVERIFY(interfaceNames(library).isEmpty());

    QVERIFY(writeFile(dir.filePath("Added.idl"), "#include \"BasicDataType.idl\"\n"
                                                 "module Added { struct TimedX { RTC::Time tm; long x; };\n"
                                                 "  interface Service { void run(in TimedX data); }; };\n"));
    QVERIFY(!dataTypeNames(library).contains(QStringLiteral("Added::TimedX")));
    library.reload();
    QVERIFY(library.diagnostics().isEmpty());
    QCOMPARE(dataTypeNames(library, true).first(), QStringLiteral("Added::TimedX"));
    QCOMPARE(interfaceNames(library), QStringList{QStringLiteral("Added::Service")});

    // An edited file is read again on reload.
    QVERIFY(writeFile(dir.filePath("Added.idl"), "module Added { interface Other { }; };\n"));
    library.reload();
    QCOMPARE(interfaceNames(library), QStringList{QStringLiteral("Added::Other")});
    QVERIFY(!dataTypeNames(library).contains(QStringLiteral("Added::TimedX")));

    library.setDirectories({});
    QVERIFY(library.dataTypes().isEmpty());
}

void TestIdlTypeLibrary::keepsGoingPastBrokenFiles()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeFile(dir.filePath("a_broken.idl"), "module Broken { struct S { long x } };\n"));
    QVERIFY(writeFile(dir.filePath("b_good.idl"), "module Good { struct Data { long x; }; };\n"));
    const IdlTypeLibrary library({dir.path()});
    QCOMPARE(dataTypeNames(library), QStringList{QStringLiteral("Good::Data")});
    QCOMPARE(library.diagnostics().size(), 1);
    QVERIFY2(library.diagnostics().first().toString().startsWith(dir.filePath("a_broken.idl") + QStringLiteral(":1:35:")),
             qPrintable(library.diagnostics().first().toString()));
}

void TestIdlTypeLibrary::readsEachFileNameOnceAcrossFolders()
{
    // The project folder has a space in its path and a copy of a standard file, as OpenRTP projects do.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString standard = dir.filePath(QStringLiteral("standard idl"));
    const QString project = dir.filePath(QStringLiteral("my project/idl"));
    QVERIFY(QDir().mkpath(standard));
    QVERIFY(QDir().mkpath(project));
    QVERIFY(QFile::copy(dataDir() + QStringLiteral("/include/BasicDataType.idl"), standard + "/BasicDataType.idl"));
    QVERIFY(QFile::copy(dataDir() + QStringLiteral("/include/BasicDataType.idl"), project + "/BasicDataType.idl"));
    QVERIFY(writeFile(project + "/Sensor.idl", "#include <BasicDataType.idl>\n"
                                               "module Sensor { struct TimedRange { RTC::Time tm; double r; }; };\n"));
    const IdlTypeLibrary library({standard, project});
    QVERIFY2(library.diagnostics().isEmpty(), qPrintable(library.diagnostics().value(0).toString()));
    QVERIFY(dataTypeNames(library, true).contains(QStringLiteral("Sensor::TimedRange")));
    QVERIFY(library.fileOf(QStringLiteral("RTC::TimedLong")).startsWith(standard));
    QCOMPARE(library.model().files.size(), 2);
}

void TestIdlTypeLibrary::bundledSetOffersOpenRtpTypes_data()
{
    QTest::addColumn<QString>("type");
    QTest::addColumn<bool>("dataType");
    QTest::addColumn<bool>("timed");
    QTest::addColumn<QString>("file");
    // What OpenRTP offers from OpenRTM-aist's IDL folder, the extensions included.
    const auto data = [](const char *type, bool timed, const char *file) {
        QTest::newRow(type) << QString::fromLatin1(type) << true << timed << QString::fromLatin1(file);
    };
    const auto service = [](const char *type, const char *file) {
        QTest::newRow(type) << QString::fromLatin1(type) << false << false << QString::fromLatin1(file);
    };
    data("RTC::TimedLong", true, "BasicDataType.idl");
    data("RTC::TimedPose3D", true, "ExtendedDataTypes.idl");
    data("RTC::RangeData", true, "InterfaceDataTypes.idl");
    data("Img::TimedCameraImage", true, "CameraCommonInterface.idl");
    data("Img::TimedMultiCameraImage", true, "CameraCommonInterface.idl");
    data("Img::CameraDeviceProfile", false, "CameraCommonInterface.idl");
    data("JARA_ARM::TimedJointPos", true, "ManipulatorCommonInterface_DataTypes.idl");
    data("JARA_ARM::ManipInfo", false, "ManipulatorCommonInterface_Common.idl");
    data("JARA_ARM::CarPosWithElbow", false, "ManipulatorCommonInterface_Middle.idl");
    data("RTC::FsmStructure", false, "ExtendedFsmService.idl");
    service("Img::CameraCaptureService", "CameraCommonInterface.idl");
    service("JARA_ARM::ManipulatorCommonInterface_Common", "ManipulatorCommonInterface_Common.idl");
    service("JARA_ARM::ManipulatorCommonInterface_Middle", "ManipulatorCommonInterface_Middle.idl");
    service("RTC::ExtendedFsmService", "ExtendedFsmService.idl");
    service("RTC::DataPushService", "DataPort.idl");
    service("OpenRTM::InPortCdr", "DataPort_OpenRTM.idl");
    service("OpenRTM::PortSharedMemory", "SharedMemory.idl");
}

// The Builder's catalogue is this library over the IDL folder the application bundles.
void TestIdlTypeLibrary::bundledSetOffersOpenRtpTypes()
{
    QFETCH(QString, type);
    QFETCH(bool, dataType);
    QFETCH(bool, timed);
    QFETCH(QString, file);
    const IdlTypeLibrary library({RTSTUDIO_IDL_DIR});
    // SDOPackage.idl's #include <orb.idl> (omniORB's folder) is the one thing the folder lacks.
    for (const Profile::Diagnostic &diagnostic : library.diagnostics())
        QVERIFY2(diagnostic.toString().contains(QLatin1String("orb.idl")), qPrintable(diagnostic.toString()));
    QCOMPARE(dataTypeNames(library).contains(type), dataType);
    QCOMPARE(dataTypeNames(library, true).contains(type), timed);
    QCOMPARE(interfaceNames(library).contains(type), !dataType);
    QCOMPARE(QFileInfo(library.fileOf(type)).fileName(), file);
}

QTEST_GUILESS_MAIN(TestIdlTypeLibrary)
#include "tst_idltypelibrary.moc"
