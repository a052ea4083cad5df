// SPDX-License-Identifier: MIT
// The document layer: loading, editing, saving and reloading profiles through the facade.
#include "documentloader.h"
#include "componentcommands.h"
#include "rtcdocument.h"
#include "rtscommands.h"
#include "common/tmpfsmount.h"
#include "xmlequivalence.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace Studio;

Q_DECLARE_METATYPE(Profile::ProfileKind)
Q_DECLARE_METATYPE(Profile::FileFormat)

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/app/")) + name;
}

QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// Copies a fixture into `dir` so that tests can save over it.
QString copyFixture(const QTemporaryDir &dir, const QString &name)
{
    const QString target = dir.filePath(name);
    QFile::copy(dataPath(name), target);
    QFile::setPermissions(target, QFile::ReadOwner | QFile::WriteOwner);
    return target;
}

std::unique_ptr<Document> load(const QString &path)
{
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> document = loadDocument(path, &diagnostics);
    if (!document)
        qWarning().noquote() << diagnostics.value(0).toString();
    return document;
}

/// Makes one edit through the undo stack, whatever kind the document is.
void editName(Document *document, const QString &name)
{
    if (auto *rtc = qobject_cast<RtcDocument *>(document)) {
        rtc->undoStack()->push(
            new Builder::SetBasicFieldCommand(rtc->model(), Builder::BasicField::Name, name));
    } else if (auto *rts = qobject_cast<RtsDocument *>(document)) {
        rts->undoStack()->push(
            new EditSystemInfoCommand(rts, RtsDocument::SystemField::Name, name));
    }
}

bool sameModel(const Document *a, const Document *b)
{
    const auto *rtcA = qobject_cast<const RtcDocument *>(a);
    const auto *rtcB = qobject_cast<const RtcDocument *>(b);
    if (rtcA && rtcB)
        return rtcA->profile() == rtcB->profile();
    const auto *rtsA = qobject_cast<const RtsDocument *>(a);
    const auto *rtsB = qobject_cast<const RtsDocument *>(b);
    return rtsA && rtsB && rtsA->profile() == rtsB->profile();
}

} // namespace

class TestDocument : public QObject
{
    Q_OBJECT

private slots:
    void loadsByContent_data();
    void loadsByContent();
    void editSaveReopen_data();
    void editSaveReopen();
    void saveAsChoosesFormatByExtension_data();
    void saveAsChoosesFormatByExtension();
    void savedXmlIsEquivalentToInput_data();
    void savedXmlIsEquivalentToInput();
    void failedLoadReportsWhere_data();
    void failedLoadReportsWhere();
    void failedSaveKeepsDocumentModified_data();
    void failedSaveKeepsDocumentModified();
    void untitledDocumentNeedsSaveAs();
    void failedSaveOnDiskKeepsOldFile_data();
    void failedSaveOnDiskKeepsOldFile();
};

void TestDocument::loadsByContent_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<Profile::ProfileKind>("kind");
    QTest::addColumn<Profile::FileFormat>("format");
    QTest::addColumn<QString>("name");
    QTest::newRow("rtc xml") << "component.xml" << Profile::ProfileKind::Rtc
                             << Profile::FileFormat::Xml << "RangeFilter";
    QTest::newRow("rtc yaml") << "component.yaml" << Profile::ProfileKind::Rtc
                              << Profile::FileFormat::Yaml << "Joystick2D";
    QTest::newRow("rts xml") << "system.xml" << Profile::ProfileKind::Rts
                             << Profile::FileFormat::Xml << "FilterDemo";
    QTest::newRow("rts yaml") << "system.yaml" << Profile::ProfileKind::Rts
                              << Profile::FileFormat::Yaml << "TeleopDemo";
}

void TestDocument::loadsByContent()
{
    QFETCH(QString, file);
    QFETCH(Profile::ProfileKind, kind);
    QFETCH(Profile::FileFormat, format);
    QFETCH(QString, name);
    // A misleading extension must not matter: the content decides.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("renamed.profile"));
    QVERIFY(QFile::copy(dataPath(file), path));

    std::unique_ptr<Document> document = load(path);
    QVERIFY(document);
    QCOMPARE(document->kind(), kind);
    QCOMPARE(document->format(), format);
    QCOMPARE(document->filePath(), path);
    QCOMPARE(document->displayName(), QStringLiteral("renamed.profile"));
    QVERIFY(!document->isModified());
    if (auto *rtc = qobject_cast<RtcDocument *>(document.get()))
        QCOMPARE(rtc->model()->basicField(Builder::BasicField::Name), name);
    else
        QCOMPARE(qobject_cast<RtsDocument *>(document.get())
                     ->systemField(RtsDocument::SystemField::Name),
                 name);
}

void TestDocument::editSaveReopen_data()
{
    QTest::addColumn<QString>("file");
    for (const char *file : {"component.xml", "component.yaml", "system.xml", "system.yaml"})
        QTest::newRow(file) << QString::fromLatin1(file);
}

void TestDocument::editSaveReopen()
{
    QFETCH(QString, file);
    QTemporaryDir dir;
    const QString path = copyFixture(dir, file);
    std::unique_ptr<Document> document = load(path);
    QVERIFY(document);
    const Profile::FileFormat format = document->format();
    editName(document.get(), QStringLiteral("Edited_Name"));
    QVERIFY(document->isModified());

    Profile::Diagnostics diagnostics;
    QVERIFY2(document->save(&diagnostics), qPrintable(diagnostics.value(0).toString()));
    QVERIFY(!document->isModified());
    QCOMPARE(document->undoStack()->count(), 1); // saving keeps the history
    QCOMPARE(Profile::detectFormat(readAll(path)), format);

    std::unique_ptr<Document> reopened = load(path);
    QVERIFY(reopened);
    QVERIFY(sameModel(document.get(), reopened.get()));
    QVERIFY(readAll(path).contains("Edited_Name"));
}

void TestDocument::saveAsChoosesFormatByExtension_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("target");
    QTest::addColumn<Profile::FileFormat>("format");
    QTest::newRow("rtc xml → yaml") << "component.xml"
                                    << "out.yaml" << Profile::FileFormat::Yaml;
    QTest::newRow("rtc yaml → xml") << "component.yaml"
                                    << "RTC.xml" << Profile::FileFormat::Xml;
    QTest::newRow("rts xml → yml") << "system.xml"
                                   << "out.yml" << Profile::FileFormat::Yaml;
    QTest::newRow("rts yaml → xml") << "system.yaml"
                                    << "sys.xml" << Profile::FileFormat::Xml;
}

void TestDocument::saveAsChoosesFormatByExtension()
{
    QFETCH(QString, file);
    QFETCH(QString, target);
    QFETCH(Profile::FileFormat, format);
    QTemporaryDir dir;
    std::unique_ptr<Document> document = load(dataPath(file));
    QVERIFY(document);
    editName(document.get(), QStringLiteral("SavedAs"));
    const QString targetPath = dir.filePath(target);

    Profile::Diagnostics diagnostics;
    QVERIFY2(document->saveAs(targetPath, &diagnostics),
             qPrintable(diagnostics.value(0).toString()));
    QCOMPARE(document->filePath(), targetPath);
    QCOMPARE(document->format(), format);
    QCOMPARE(document->displayName(), target);
    QVERIFY(!document->isModified());
    QCOMPARE(Profile::detectFormat(readAll(targetPath)), format);

    std::unique_ptr<Document> reopened = load(targetPath);
    QVERIFY(reopened);
    QVERIFY(sameModel(document.get(), reopened.get()));
}

void TestDocument::savedXmlIsEquivalentToInput_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("rtc") << QStringLiteral("component.xml");
    QTest::newRow("rts") << QStringLiteral("system.xml");
}

void TestDocument::savedXmlIsEquivalentToInput()
{
    QFETCH(QString, file);
    QTemporaryDir dir;
    std::unique_ptr<Document> document = load(dataPath(file));
    QVERIFY(document);
    const QString savedPath = dir.filePath(file);
    Profile::Diagnostics diagnostics;
    QVERIFY(document->saveAs(savedPath, &diagnostics));

    const auto input = Profile::parseXml(readAll(dataPath(file)), file, &diagnostics);
    const auto saved = Profile::parseXml(readAll(savedPath), savedPath, &diagnostics);
    QVERIFY(input && saved);
    const QString difference = xmlDifference(*input, *saved);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
}

void TestDocument::failedLoadReportsWhere_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("hasLine");
    QTest::newRow("malformed xml") << QStringLiteral("broken.xml") << true;
    QTest::newRow("not a profile") << QStringLiteral("not-a-profile.xml") << false;
    QTest::newRow("missing file") << QStringLiteral("no-such-file.xml") << false;
}

void TestDocument::failedLoadReportsWhere()
{
    QFETCH(QString, file);
    QFETCH(bool, hasLine);
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> document = loadDocument(dataPath(file), &diagnostics);
    QVERIFY(!document);
    QVERIFY(Profile::hasErrors(diagnostics));
    const Profile::Diagnostic &first = diagnostics.first();
    QVERIFY2(first.file.endsWith(file), qPrintable(first.toString()));
    QVERIFY2(first.toString().contains(file + QLatin1Char(':')), qPrintable(first.toString()));
    if (hasLine)
        QVERIFY2(first.line > 0, qPrintable(first.toString()));
}

void TestDocument::failedSaveKeepsDocumentModified_data()
{
    QTest::addColumn<QString>("target"); // relative to a scratch folder
    QTest::newRow("missing folder") << QStringLiteral("missing/RTC.xml");
    QTest::newRow("folder is a file") << QStringLiteral("plain-file/RTC.xml");
    QTest::newRow("target is a folder") << QStringLiteral("folder");
    // A read-only folder stops only users without the power to override it (not root), so the
    // row is there where it can fail.
    QTemporaryDir probeDir;
    QFile::setPermissions(probeDir.path(), QFile::ReadOwner | QFile::ExeOwner);
    QFile probe(probeDir.filePath(QStringLiteral("probe")));
    const bool readOnlyHolds = !probe.open(QIODevice::WriteOnly);
    QFile::setPermissions(probeDir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    if (readOnlyHolds)
        QTest::newRow("read-only folder") << QStringLiteral("readonly/RTC.xml");
}

void TestDocument::failedSaveKeepsDocumentModified()
{
    QFETCH(QString, target);
    QTemporaryDir dir;
    QFile plain(dir.filePath(QStringLiteral("plain-file")));
    QVERIFY(plain.open(QIODevice::WriteOnly));
    plain.close();
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder")));
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("readonly")));
    QFile::setPermissions(dir.filePath(QStringLiteral("readonly")),
                          QFile::ReadOwner | QFile::ExeOwner);

    const QString original = copyFixture(dir, QStringLiteral("component.xml"));
    const QByteArray originalBytes = readAll(original);
    std::unique_ptr<Document> document = load(original);
    QVERIFY(document);
    editName(document.get(), QStringLiteral("Unsaved"));

    Profile::Diagnostics diagnostics;
    QVERIFY(!document->saveAs(dir.filePath(target), &diagnostics));
    QVERIFY(Profile::hasErrors(diagnostics));
    QVERIFY(document->isModified());
    QCOMPARE(document->filePath(), original);
    QCOMPARE(document->undoStack()->count(), 1);
    QCOMPARE(qobject_cast<RtcDocument *>(document.get())
                 ->model()
                 ->basicField(Builder::BasicField::Name),
             QStringLiteral("Unsaved"));
    QCOMPARE(readAll(original), originalBytes);
    QFile::setPermissions(dir.filePath(QStringLiteral("readonly")),
                          QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
}

void TestDocument::untitledDocumentNeedsSaveAs()
{
    RtcDocument document(Profile::RtcProfile::createDefault());
    document.setUntitledName(QStringLiteral("New Component 1"));
    QVERIFY(document.isUntitled());
    QCOMPARE(document.displayName(), QStringLiteral("New Component 1"));
    Profile::Diagnostics diagnostics;
    QVERIFY(!document.save(&diagnostics));
    QVERIFY(Profile::hasErrors(diagnostics));
    QVERIFY(document.isUntitled());
}

void TestDocument::failedSaveOnDiskKeepsOldFile_data()
{
    TestDisk::addSpoiledDiskRows();
}

void TestDocument::failedSaveOnDiskKeepsOldFile()
{
    QFETCH(bool, readOnly);
    QTemporaryDir dir;
    TestDisk::TmpfsMount disk;
    TESTDISK_MOUNT_OR_SKIP(disk, dir.path());
    const QString path = copyFixture(dir, QStringLiteral("component.xml"));
    const QByteArray before = readAll(path);
    std::unique_ptr<Document> document = load(path);
    QVERIFY(document);
    editName(document.get(), QStringLiteral("Unsaved"));
    QString why;
    QVERIFY2(disk.spoil(readOnly, &why), qPrintable(why));

    Profile::Diagnostics diagnostics;
    QVERIFY(!document->save(&diagnostics));
    QVERIFY(Profile::hasErrors(diagnostics));
    QVERIFY2(diagnostics.first().toString().contains(path), qPrintable(diagnostics.first().toString()));
    QVERIFY(document->isModified());
    QCOMPARE(document->filePath(), path);
    QCOMPARE(readAll(path), before);
}

QTEST_GUILESS_MAIN(TestDocument)
#include "tst_document.moc"
