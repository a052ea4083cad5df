// SPDX-License-Identifier: MIT
// Every real RTC/RTS file of the conformance folder opens in the application: it loads into a
// document, gets an editor, and a system's outline passes QAbstractItemModelTester.
#include "documentloader.h"
#include "editorfactory.h"
#include "rtsdocument.h"
#include "systemoutlinemodel.h"

#include <QAbstractItemModelTester>
#include <QDir>
#include <QTest>
#include <QUndoStack>

using namespace Studio;

class TestAppConformance : public QObject
{
    Q_OBJECT

private slots:
    void opensInTheApplication_data();
    void opensInTheApplication();
};

void TestAppConformance::opensInTheApplication_data()
{
    QTest::addColumn<QString>("path");
    const QDir root(RTSTUDIO_CONFORMANCE_DIR);
    if (!root.exists())
        QSKIP("The conformance folder is not present beside the project.");
    for (const char *folder : {"rtc", "rtc-yaml", "rts"}) {
        const QDir dir(root.filePath(QLatin1String(folder)));
        const QStringList files = dir.entryList({QStringLiteral("*.xml"), QStringLiteral("*.yaml")},
                                                QDir::Files, QDir::Name);
        for (const QString &file : files) {
            const QString name = QLatin1String(folder) + QLatin1Char('/') + file;
            QTest::newRow(qPrintable(name)) << dir.filePath(file);
        }
    }
}

void TestAppConformance::opensInTheApplication()
{
    QFETCH(QString, path);
    Profile::Diagnostics diagnostics;
    std::unique_ptr<Document> document = loadDocument(path, &diagnostics);
    QVERIFY2(document, qPrintable(diagnostics.value(0).toString()));
    QVERIFY(!document->isModified());

    std::unique_ptr<QWidget> editor(createEditor(document.get()));
    QVERIFY(editor);
    QCOMPARE(document->undoStack()->count(), 0); // showing a file never edits it

    if (auto *system = qobject_cast<RtsDocument *>(document.get())) {
        SystemOutlineModel model(system);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.rowCount(model.index(0, 0)), int(system->profile().components.size()));
    }
}

QTEST_MAIN(TestAppConformance)
#include "tst_appconformance.moc"
