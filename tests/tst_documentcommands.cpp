// SPDX-License-Identifier: MIT
// The undo commands of the document layer: state A, do → B, undo → A, redo → B, and merging.
#include "componentcommands.h"
#include "rtcdocument.h"
#include "rtscommands.h"

#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

using namespace Studio;
using Field = Builder::BasicField;
using Builder::SetBasicFieldCommand;
using SystemField = RtsDocument::SystemField;

Q_DECLARE_METATYPE(std::optional<QString>)

namespace {

RtcDocument *newComponent(QObject *parent)
{
    return new RtcDocument(Profile::RtcProfile::createDefault(), parent);
}

RtsDocument *newSystem(QObject *parent)
{
    return new RtsDocument(Profile::RtsProfile::createNew(QStringLiteral("Vendor"),
                                                          QStringLiteral("Demo"),
                                                          QStringLiteral("1.0")),
                           parent);
}

} // namespace

class TestDocumentCommands : public QObject
{
    Q_OBJECT

private slots:
    void basicFieldDoUndoRedo_data();
    void basicFieldDoUndoRedo();
    void basicFieldIdFollowsBasicInfo();
    void basicFieldKeepsHandWrittenId();
    void basicFieldTypingMerges();
    void basicFieldOtherFieldDoesNotMerge();
    void basicFieldEditBackToStartIsDropped();
    void basicFieldClearingOptional_data();
    void basicFieldClearingOptional();
    void basicFieldAnnouncesChanges();

    void systemInfoDoUndoRedo_data();
    void systemInfoDoUndoRedo();
    void systemInfoTypingMerges();
    void systemInfoRestoresMalformedId();
    void systemInfoClearingAbstract_data();
    void systemInfoClearingAbstract();
};

void TestDocumentCommands::basicFieldDoUndoRedo_data()
{
    QTest::addColumn<Field>("field");
    QTest::addColumn<std::optional<QString>>("value");
    const auto row = [](const char *name, Field field, const QString &value) {
        QTest::newRow(name) << field << std::optional<QString>(value);
    };
    row("name", Field::Name, QStringLiteral("Scanner"));
    row("description", Field::Description, QStringLiteral("Reads a laser scanner"));
    row("version", Field::Version, QStringLiteral("2.0.1"));
    row("vendor", Field::Vendor, QStringLiteral("AIST"));
    row("category", Field::Category, QStringLiteral("Sensor"));
    row("component type", Field::ComponentType, QStringLiteral("UNIQUE"));
    row("activity type", Field::ActivityType, QStringLiteral("EVENTDRIVEN"));
    row("max instances", Field::MaxInstances, QStringLiteral("0"));
    row("execution type", Field::ExecutionType, QStringLiteral("ExtTrigExecutionContext"));
    row("execution rate", Field::ExecutionRate, QStringLiteral("25.5"));
    QTest::newRow("description emptied") << Field::Description << std::optional<QString>(QString());
}

void TestDocumentCommands::basicFieldDoUndoRedo()
{
    QFETCH(Field, field);
    QFETCH(std::optional<QString>, value);
    QObject owner;
    RtcDocument *document = newComponent(&owner);
    const Profile::RtcProfile stateA = document->profile();
    QVERIFY(document->model()->basicField(field) != value);

    document->undoStack()->push(new SetBasicFieldCommand(document->model(), field, value));
    QCOMPARE(document->model()->basicField(field), value);
    const Profile::RtcProfile stateB = document->profile();
    QVERIFY(stateB != stateA);
    QVERIFY(document->isModified());
    QVERIFY(document->undoStack()->undoText().contains(Builder::ComponentModel::fieldLabel(field)));

    document->undoStack()->undo();
    QVERIFY(document->profile() == stateA);
    QVERIFY(!document->isModified());
    document->undoStack()->redo();
    QVERIFY(document->profile() == stateB);
}

void TestDocumentCommands::basicFieldIdFollowsBasicInfo()
{
    QObject owner;
    RtcDocument *document = newComponent(&owner);
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:VenderName:Category:ModuleName:1.0.0"));
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Vendor, QStringLiteral("AIST")));
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:AIST:Category:ModuleName:1.0.0"));
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Name, QStringLiteral("Scanner")));
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:AIST:Category:Scanner:1.0.0"));
    document->undoStack()->undo();
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:AIST:Category:ModuleName:1.0.0"));
    document->undoStack()->undo();
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:VenderName:Category:ModuleName:1.0.0"));
}

void TestDocumentCommands::basicFieldKeepsHandWrittenId()
{
    // An id that does not follow the basic info is the file's business: edits leave it alone,
    // also when an edit happens to make the basic info match it.
    Profile::RtcProfile profile = Profile::RtcProfile::createDefault();
    profile.id = QStringLiteral("RTC:VenderName:Category:Other:1.0.0");
    QObject owner;
    auto *document = new RtcDocument(profile, &owner);
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Name, QStringLiteral("Other")));
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:VenderName:Category:Other:1.0.0"));
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Version, QStringLiteral("2.0.0")));
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:VenderName:Category:Other:2.0.0"));
    document->undoStack()->undo();
    document->undoStack()->undo();
    QVERIFY(document->profile() == profile);
}

void TestDocumentCommands::basicFieldTypingMerges()
{
    QObject owner;
    RtcDocument *document = newComponent(&owner);
    const Profile::RtcProfile stateA = document->profile();
    for (const char *text : {"S", "Sc", "Sca", "Scan"}) {
        document->undoStack()->push(
            new SetBasicFieldCommand(document->model(), Field::Name, QString::fromLatin1(text)));
    }
    QCOMPARE(document->undoStack()->count(), 1);
    QCOMPARE(document->model()->basicField(Field::Name), QStringLiteral("Scan"));
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:VenderName:Category:Scan:1.0.0"));
    document->undoStack()->undo();
    QVERIFY(document->profile() == stateA);
    document->undoStack()->redo();
    QCOMPARE(document->model()->basicField(Field::Name), QStringLiteral("Scan"));
    QCOMPARE(document->model()->componentId(), QStringLiteral("RTC:VenderName:Category:Scan:1.0.0"));
}

void TestDocumentCommands::basicFieldOtherFieldDoesNotMerge()
{
    QObject owner;
    RtcDocument *document = newComponent(&owner);
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Name, QStringLiteral("A")));
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Vendor, QStringLiteral("B")));
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Name, QStringLiteral("C")));
    QCOMPARE(document->undoStack()->count(), 3);
    document->undoStack()->undo();
    QCOMPARE(document->model()->basicField(Field::Name), QStringLiteral("A"));
    QCOMPARE(document->model()->basicField(Field::Vendor), QStringLiteral("B"));
}

void TestDocumentCommands::basicFieldEditBackToStartIsDropped()
{
    QObject owner;
    RtcDocument *document = newComponent(&owner);
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Name, QStringLiteral("ModuleNameX")));
    QCOMPARE(document->undoStack()->count(), 1);
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Name, QStringLiteral("ModuleName")));
    QCOMPARE(document->undoStack()->count(), 0);
    QVERIFY(!document->isModified());
}

void TestDocumentCommands::basicFieldClearingOptional_data()
{
    QTest::addColumn<std::optional<QString>>("original");
    QTest::addColumn<std::optional<QString>>("cleared");
    QTest::newRow("absent stays absent") << std::optional<QString>() << std::optional<QString>();
    QTest::newRow("empty stays empty")
        << std::optional<QString>(QString()) << std::optional<QString>(QString());
    QTest::newRow("text becomes empty")
        << std::optional<QString>(QStringLiteral("old")) << std::optional<QString>(QString());
}

void TestDocumentCommands::basicFieldClearingOptional()
{
    QFETCH(std::optional<QString>, original);
    QFETCH(std::optional<QString>, cleared);
    Profile::RtcProfile profile = Profile::RtcProfile::createDefault();
    profile.basicInfo.description = original;
    QObject owner;
    auto *document = new RtcDocument(profile, &owner);
    // Typing a character and deleting it again, as a user does in the form.
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Description, QStringLiteral("oldx")));
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Description, std::nullopt));
    QCOMPARE(document->model()->basicField(Field::Description), cleared);
    document->undoStack()->undo();
    QCOMPARE(document->model()->basicField(Field::Description), original);
}

void TestDocumentCommands::basicFieldAnnouncesChanges()
{
    QObject owner;
    RtcDocument *document = newComponent(&owner);
    QSignalSpy fieldSpy(document->model(), &Builder::ComponentModel::basicFieldChanged);
    QSignalSpy idSpy(document->model(), &Builder::ComponentModel::componentIdChanged);
    QSignalSpy modifiedSpy(document, &Document::modifiedChanged);
    document->undoStack()->push(
        new SetBasicFieldCommand(document->model(), Field::Category, QStringLiteral("Sensor")));
    QCOMPARE(fieldSpy.count(), 1);
    QCOMPARE(fieldSpy.at(0).at(0).value<Field>(), Field::Category);
    QCOMPARE(idSpy.count(), 1);
    QCOMPARE(idSpy.at(0).at(0).toString(),
             QStringLiteral("RTC:VenderName:Sensor:ModuleName:1.0.0"));
    QCOMPARE(modifiedSpy.count(), 1);
    QCOMPARE(modifiedSpy.at(0).at(0).toBool(), true);
    document->undoStack()->undo();
    QCOMPARE(fieldSpy.count(), 2);
    QCOMPARE(modifiedSpy.count(), 2);
    QCOMPARE(modifiedSpy.at(1).at(0).toBool(), false);
}

void TestDocumentCommands::systemInfoDoUndoRedo_data()
{
    QTest::addColumn<SystemField>("field");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("idAfter");
    QTest::addColumn<std::optional<QString>>("abstractAfter");
    const std::optional<QString> none;
    QTest::newRow("vendor") << SystemField::Vendor << QStringLiteral("AIST")
                            << QStringLiteral("RTSystem:AIST:Demo:1.0") << none;
    QTest::newRow("name") << SystemField::Name << QStringLiteral("Patrol")
                          << QStringLiteral("RTSystem:Vendor:Patrol:1.0") << none;
    QTest::newRow("version") << SystemField::Version << QStringLiteral("2.3")
                             << QStringLiteral("RTSystem:Vendor:Demo:2.3") << none;
    QTest::newRow("abstract") << SystemField::Abstract << QStringLiteral("Two robots")
                              << QStringLiteral("RTSystem:Vendor:Demo:1.0")
                              << std::optional<QString>(QStringLiteral("Two robots"));
}

void TestDocumentCommands::systemInfoDoUndoRedo()
{
    QFETCH(SystemField, field);
    QFETCH(QString, value);
    QFETCH(QString, idAfter);
    QFETCH(std::optional<QString>, abstractAfter);
    QObject owner;
    RtsDocument *document = newSystem(&owner);
    const Profile::RtsProfile stateA = document->profile();
    QSignalSpy spy(document, &RtsDocument::systemInfoChanged);

    document->undoStack()->push(new EditSystemInfoCommand(document, field, value));
    QCOMPARE(document->systemId(), idAfter);
    QCOMPARE(document->abstract(), abstractAfter);
    QCOMPARE(document->systemField(field), value);
    QCOMPARE(spy.count(), 1);
    const Profile::RtsProfile stateB = document->profile();
    QVERIFY(stateB != stateA);
    QVERIFY(document->undoStack()->undoText().contains(RtsDocument::fieldLabel(field)));

    document->undoStack()->undo();
    QVERIFY(document->profile() == stateA);
    QCOMPARE(spy.count(), 2);
    document->undoStack()->redo();
    QVERIFY(document->profile() == stateB);
}

void TestDocumentCommands::systemInfoTypingMerges()
{
    QObject owner;
    RtsDocument *document = newSystem(&owner);
    const Profile::RtsProfile stateA = document->profile();
    for (const char *text : {"D", "De", "Dem", "Demo2"}) {
        document->undoStack()->push(
            new EditSystemInfoCommand(document, SystemField::Name, QString::fromLatin1(text)));
    }
    document->undoStack()->push(
        new EditSystemInfoCommand(document, SystemField::Version, QStringLiteral("1.1")));
    QCOMPARE(document->undoStack()->count(), 2);
    QCOMPARE(document->systemId(), QStringLiteral("RTSystem:Vendor:Demo2:1.1"));
    document->undoStack()->undo();
    QCOMPARE(document->systemId(), QStringLiteral("RTSystem:Vendor:Demo2:1.0"));
    document->undoStack()->undo();
    QVERIFY(document->profile() == stateA);

    // Typing back to where it started leaves nothing to undo.
    document->undoStack()->push(
        new EditSystemInfoCommand(document, SystemField::Name, QStringLiteral("Dem")));
    document->undoStack()->push(
        new EditSystemInfoCommand(document, SystemField::Name, QStringLiteral("Demo")));
    QCOMPARE(document->undoStack()->count(), 0);
}

void TestDocumentCommands::systemInfoRestoresMalformedId()
{
    Profile::RtsProfile profile = Profile::RtsProfile::createNew(
        QStringLiteral("V"), QStringLiteral("N"), QStringLiteral("1"));
    profile.id = QStringLiteral("not-a-system-id");
    QObject owner;
    auto *document = new RtsDocument(profile, &owner);
    QVERIFY(!document->hasWellFormedId());
    QCOMPARE(document->systemField(SystemField::Vendor), QString());
    document->undoStack()->push(
        new EditSystemInfoCommand(document, SystemField::Vendor, QStringLiteral("AIST")));
    QCOMPARE(document->systemId(), QStringLiteral("RTSystem:AIST::"));
    QCOMPARE(document->systemField(SystemField::Vendor), QStringLiteral("AIST"));
    document->undoStack()->undo();
    QCOMPARE(document->systemId(), QStringLiteral("not-a-system-id"));
}

void TestDocumentCommands::systemInfoClearingAbstract_data()
{
    QTest::addColumn<std::optional<QString>>("original");
    QTest::addColumn<std::optional<QString>>("cleared");
    QTest::newRow("absent stays absent") << std::optional<QString>() << std::optional<QString>();
    QTest::newRow("text becomes empty")
        << std::optional<QString>(QStringLiteral("old")) << std::optional<QString>(QString());
}

void TestDocumentCommands::systemInfoClearingAbstract()
{
    QFETCH(std::optional<QString>, original);
    QFETCH(std::optional<QString>, cleared);
    Profile::RtsProfile profile = Profile::RtsProfile::createNew(
        QStringLiteral("V"), QStringLiteral("N"), QStringLiteral("1"));
    profile.abstract = original;
    QObject owner;
    auto *document = new RtsDocument(profile, &owner);
    document->undoStack()->push(
        new EditSystemInfoCommand(document, SystemField::Abstract, QStringLiteral("x")));
    document->undoStack()->push(
        new EditSystemInfoCommand(document, SystemField::Abstract, QString()));
    QCOMPARE(document->abstract(), cleared);
    QCOMPARE(document->undoStack()->count(), original ? 1 : 0);
    if (document->undoStack()->canUndo())
        document->undoStack()->undo();
    QCOMPARE(document->abstract(), original);
}

QTEST_GUILESS_MAIN(TestDocumentCommands)
#include "tst_documentcommands.moc"
