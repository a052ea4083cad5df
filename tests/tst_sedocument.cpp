// SPDX-License-Identifier: MIT
// The application's system documents edit and save through the System Editor model.
// builder/ has a componentcommands.h too; compositecommands.h includes the System Editor's own.
#include "compositecommands.h"
#include "documentloader.h"
#include "rtscommands.h"
#include "rtsdocument.h"
#include "systemmodel.h"
#include "systemoutlinemodel.h"

#include <QAbstractItemModelTester>
#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace Studio;

namespace {

QString dataPath(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/systemeditor/")) + name;
}

} // namespace

class TestSeDocument : public QObject
{
    Q_OBJECT

private slots:
    void loadedSystemKnowsItsComponents();
    void systemInfoEditsGoThroughTheModel();
    void outlineFollowsModelEdits();
    void saveCopiesRtcProfilesAndStampsEditedSystems();
};

void TestSeDocument::loadedSystemKnowsItsComponents()
{
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> document = loadDocument(dataPath("system/system.xml"), &diagnostics);
    auto *system = qobject_cast<RtsDocument *>(document.get());
    QVERIFY(system);
    QVERIFY(system->model()->rtcProfile("ConsoleIn0"));
    QCOMPARE(system->model()->ports("ConsoleIn0").at(0).kind, SystemEditor::PortKind::DataOut);
    QVERIFY(!system->isModified());
    QCOMPARE(system->undoStack()->count(), 0);
}

void TestSeDocument::systemInfoEditsGoThroughTheModel()
{
    RtsDocument document(Profile::RtsProfile::createNew("V", "S", "1"));
    QSignalSpy modelSpy(document.model(), &SystemEditor::SystemModel::systemInfoChanged);
    QSignalSpy documentSpy(&document, &RtsDocument::systemInfoChanged);
    document.undoStack()->push(
        new EditSystemInfoCommand(&document, RtsDocument::SystemField::Vendor, "W"));
    QCOMPARE(document.model()->profile().id, QStringLiteral("RTSystem:W:S:1"));
    QCOMPARE(modelSpy.size(), 1);
    QCOMPARE(documentSpy.size(), 1);
    document.undoStack()->undo();
    QCOMPARE(document.systemId(), QStringLiteral("RTSystem:V:S:1"));
}

void TestSeDocument::outlineFollowsModelEdits()
{
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> document = loadDocument(dataPath("system/system.xml"), &diagnostics);
    auto *system = qobject_cast<RtsDocument *>(document.get());
    QVERIFY(system);
    SystemOutlineModel outline(system);
    QAbstractItemModelTester tester(&outline,
                                    QAbstractItemModelTester::FailureReportingMode::QtTest);
    const QModelIndex components = outline.index(0, 0);
    QCOMPARE(outline.rowCount(components), 3);
    system->undoStack()->push(
        new SystemEditor::RemoveComponentsCommand(system->model(), {"Mystery0"}));
    QCOMPARE(outline.rowCount(outline.index(0, 0)), 2);
    QVERIFY(system->isModified());
    system->undoStack()->undo();
    QCOMPARE(outline.rowCount(outline.index(0, 0)), 3);
}

void TestSeDocument::saveCopiesRtcProfilesAndStampsEditedSystems()
{
    QTemporaryDir dir;
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> document = loadDocument(dataPath("system/system.xml"), &diagnostics);
    auto *system = qobject_cast<RtsDocument *>(document.get());
    QVERIFY(system);
    const QString path = dir.filePath("Demo.xml");
    // Unedited: saved as read, dates included.
    QVERIFY(system->saveAs(path, &diagnostics));
    QCOMPARE(system->profile().updateDate, QStringLiteral("2024-01-02T03:04:05+09:00"));
    QVERIFY(QFile::exists(dir.filePath("RTCs/ConsoleIn0.xml")));
    QCOMPARE(system->profile().components.at(0).pathUri, QStringLiteral("RTCs/ConsoleIn0.xml"));
    // Edited: the update date moves on.
    system->undoStack()->push(
        new SystemEditor::MoveComponentsCommand(system->model(), {{"ConsoleIn0", QPointF(1, 1)}}));
    QVERIFY(system->save(&diagnostics));
    QVERIFY(system->profile().updateDate != QStringLiteral("2024-01-02T03:04:05+09:00"));
    QVERIFY(!system->isModified());
    std::unique_ptr<Document> reopened = loadDocument(path, &diagnostics);
    auto *again = qobject_cast<RtsDocument *>(reopened.get());
    QVERIFY(again);
    QCOMPARE(again->profile(), system->profile());
    QVERIFY(again->model()->rtcProfile("ConsoleOut0"));
}

QTEST_MAIN(TestSeDocument)
#include "tst_sedocument.moc"
