// SPDX-License-Identifier: MIT
// Diagram export of systems without saved positions (auto-laid-out, file untouched) from the
// command line and File ▸ Export Diagram…, and the System Editor's Auto Layout action.
#include "autolayout.h"
#include "componentitem.h"
#include "diagramexport.h"
#include "documentcontroller.h"
#include "mainwindow.h"
#include "rtsdocument.h"
#include "rtseditor.h"
#include "systemcanvas.h"
#include "systemfile.h"
#include "systemmodel.h"
#include "systemscene.h"
#include "userprompts.h"

#include <QAction>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>

#include <memory>

using namespace SystemEditor;
using namespace Studio;

namespace {

QString dataFile(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/")) + name;
}

QString unplacedSystem()
{
    return dataFile(QStringLiteral("seexportmenu/unplaced.xml"));
}

QString placedSystem()
{
    return dataFile(QStringLiteral("secanvas/system.xml"));
}

/// Answers only the export question; everything else is declined.
class ExportPrompts : public UserPrompts
{
public:
    QString exportFileName;
    QStringList suggestedExportPaths;
    int problemsShown = 0;

    SaveChoice askSaveChanges(const QString &) override { return SaveChoice::Discard; }
    QStringList askOpenFileNames(const QString &) override { return {}; }
    QString askSaveFileName(Profile::ProfileKind, const QString &) override { return {}; }
    void showProblems(const QString &, const QString &, const Profile::Diagnostics &) override
    {
        ++problemsShown;
    }
    void showAbout() override { }
    QString askExportFileName(const QString &suggestedPath) override
    {
        suggestedExportPaths << suggestedPath;
        return exportFileName;
    }
};

void loadInto(SystemModel &model, const QString &path)
{
    Profile::Diagnostics diagnostics;
    std::optional<LoadedSystem> loaded = loadSystemFile(path, &diagnostics);
    QVERIFY(loaded);
    model.setProfile(loaded->profile, loaded->rtcProfiles);
}

QHash<QString, QPointF> positions(const SystemModel &model)
{
    QHash<QString, QPointF> result;
    for (const QString &id : model.componentIds())
        result.insert(id, model.layout(id).position);
    return result;
}

} // namespace

class TestExportMenu : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void unplacedSystemIsLaidOutForExportOnly()
    {
        SystemModel model;
        loadInto(model, unplacedSystem());
        QVERIFY(!DiagramExport::hasPositions(model));
        const Profile::RtsProfile before = model.profile();

        // What the export should draw: the components moved apart by the auto-layout, sized as
        // drawn so that none overlaps another.
        SystemModel expected;
        expected.setProfile(model.profile(), model.rtcProfiles());
        {
            const SystemScene measuring(&expected, nullptr);
            const QHash<QString, QPointF> laidOut
                = computeAutoLayout(expected, DiagramExport::drawnLayoutOptions(measuring));
            QCOMPARE(laidOut.size(), 3);
            for (auto it = laidOut.cbegin(); it != laidOut.cend(); ++it)
                expected.moveComponent(it.key(), it.value());
        }
        const SystemScene scene(&expected, nullptr);
        QList<QRectF> bodies;
        for (const QString &name : expected.componentIds()) {
            const ComponentItem *item = scene.componentItem(name);
            bodies << item->mapRectToScene(item->bodyRect());
        }
        for (int i = 0; i < bodies.size(); ++i) {
            for (int j = i + 1; j < bodies.size(); ++j)
                QVERIFY2(!bodies.at(i).intersects(bodies.at(j)), qPrintable(QString::number(j)));
        }

        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("unplaced.png"));
        QString error;
        QVERIFY2(DiagramExport::exportLaidOut(model, out, &error), qPrintable(error));
        const QImage image(out);
        QCOMPARE(image.size(), DiagramExport::renderImage(expected).size());
        QVERIFY(image.size() != DiagramExport::renderImage(model).size()); // not drawn stacked
        QCOMPARE(model.profile(), before);
        QVERIFY(!DiagramExport::hasPositions(model));
    }

    void placedSystemKeepsItsPositions()
    {
        SystemModel model;
        loadInto(model, placedSystem());
        QVERIFY(DiagramExport::hasPositions(model));
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("placed.png"));
        QVERIFY(DiagramExport::exportLaidOut(model, out, nullptr));
        QCOMPARE(QImage(out).size(), DiagramExport::renderImage(model).size());
    }

    void commandLineLaysOutUnplacedSystems()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("cli.png"));
        QProcess process;
        process.start(RTSTUDIO_PATH,
                      {QStringLiteral("--export-diagram"), unplacedSystem(),
                       QStringLiteral("--output"), out});
        QVERIFY(process.waitForFinished(60000));
        QCOMPARE(process.exitCode(), 0);
        SystemModel model;
        loadInto(model, unplacedSystem());
        const QImage image(out);
        QVERIFY(!image.isNull());
        QVERIFY(image.size() != DiagramExport::renderImage(model).size()); // not drawn stacked
    }

    void fileMenuExportsTheActiveSystem()
    {
        MainWindow window;
        auto prompts = std::make_unique<ExportPrompts>();
        ExportPrompts *answers = prompts.get();
        window.setPrompts(std::move(prompts));
        auto *exportAction = window.findChild<QAction *>(QStringLiteral("actionExportDiagram"));
        QVERIFY(exportAction);

        window.documents()->newComponent();
        QVERIFY(!exportAction->isEnabled()); // components have no diagram

        QVERIFY(window.openFiles({unplacedSystem()}));
        QTRY_VERIFY(exportAction->isEnabled());
        auto *document = qobject_cast<RtsDocument *>(window.activeDocument());
        QVERIFY(document);

        // Cancelled: nothing written, nothing reported.
        exportAction->trigger();
        QCOMPARE(answers->suggestedExportPaths.size(), 1);
        QCOMPARE(QFileInfo(answers->suggestedExportPaths.first()).fileName(),
                 QStringLiteral("unplaced.png"));

        QTemporaryDir dir;
        answers->exportFileName = dir.filePath(QStringLiteral("menu.svg"));
        exportAction->trigger();
        QVERIFY(QFileInfo(answers->exportFileName).size() > 0);
        QCOMPARE(answers->problemsShown, 0);
        QVERIFY(!document->isModified());
        QCOMPARE(document->undoStack()->count(), 0);
        QVERIFY(!DiagramExport::hasPositions(*document->model()));

        answers->exportFileName = dir.filePath(QStringLiteral("menu.nosuchformat"));
        exportAction->trigger();
        QCOMPARE(answers->problemsShown, 1);
    }

    void autoLayoutActionIsOneUndoStep()
    {
        SystemModel model;
        loadInto(model, placedSystem());
        QUndoStack stack;
        SystemCanvas canvas(&model, &stack);
        const QHash<QString, QPointF> a = positions(model);
        QAction *autoLayout = canvas.action(QStringLiteral("actionAutoLayout"));
        QVERIFY(autoLayout);
        autoLayout->trigger();
        QCOMPARE(stack.count(), 1);
        const QHash<QString, QPointF> b = positions(model);
        QVERIFY(a != b);
        stack.undo();
        QCOMPARE(positions(model), a);
        stack.redo();
        QCOMPARE(positions(model), b);
    }

    void systemEditorToolBarOffersAutoLayout()
    {
        MainWindow window;
        window.setPrompts(std::make_unique<ExportPrompts>());
        QVERIFY(window.openFiles({unplacedSystem()}));
        auto *editor = window.findChild<RtsEditor *>();
        QVERIFY(editor);
        auto *toolBar = editor->findChild<QToolBar *>(QStringLiteral("systemEditorToolBar"));
        QVERIFY(toolBar);
        QAction *autoLayout = editor->canvas()->action(QStringLiteral("actionAutoLayout"));
        QVERIFY(toolBar->actions().contains(autoLayout));
        auto *document = editor->document();
        autoLayout->trigger();
        QCOMPARE(document->undoStack()->count(), 1);
        QVERIFY(document->isModified());
        QVERIFY(DiagramExport::hasPositions(*document->model()));
        document->undoStack()->undo();
        QVERIFY(!document->isModified());
    }
};

QTEST_MAIN(TestExportMenu)
#include "tst_seexportmenu.moc"
