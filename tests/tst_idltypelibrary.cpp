// SPDX-License-Identifier: MIT
#include "idltypelibrary.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace Codegen;

namespace {

QString dataDir()
{
    return QStringLiteral(RTSTUDIO_TEST_DATA_DIR "/idl");
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

QTEST_GUILESS_MAIN(TestIdlTypeLibrary)
#include "tst_idltypelibrary.moc"
