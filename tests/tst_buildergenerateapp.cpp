// SPDX-License-Identifier: MIT
// The application gives every component editor its Generate: the editor a component document
// opens in owns a GenerateController over the document's model.
#include "componenteditor.h"
#include "editorfactory.h"
#include "generatecontroller.h"
#include "rtcdocument.h"
#include "rtsdocument.h"

#include <QTest>

#include <memory>

class TestBuilderGenerateApp : public QObject
{
    Q_OBJECT

private slots:
    void componentEditorsCanGenerate();
};

void TestBuilderGenerateApp::componentEditorsCanGenerate()
{
    Studio::RtcDocument document(Profile::RtcProfile::createDefault());
    std::unique_ptr<QWidget> widget(Studio::createEditor(&document));
    auto *editor = qobject_cast<Builder::ComponentEditor *>(widget.get());
    QVERIFY(editor);
    const QList<Builder::GenerateController *> controllers
        = editor->findChildren<Builder::GenerateController *>();
    QCOMPARE(controllers.size(), 1);
    // Deleting the editor takes its controller along (no dangling prompts).
    QPointer<Builder::GenerateController> controller(controllers.at(0));
    widget.reset();
    QVERIFY(controller.isNull());
}

QTEST_MAIN(TestBuilderGenerateApp)
#include "tst_buildergenerateapp.moc"
