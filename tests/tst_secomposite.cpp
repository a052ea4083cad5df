// SPDX-License-Identifier: MIT
// Composite components and the system clipboard on the canvas: grouping a selection through the
// canvas action (kind and exported ports), the composite drawn as a frame under its members,
// saved as compositeType + Participants + exported ports and reopened equal, decomposed, with
// undo/redo; copy to and paste from QGuiApplication::clipboard(), malformed clipboard content.
#include "componentitem.h"
#include "compositedialog.h"
#include "pastecommand.h"
#include "systemcanvas.h"
#include "systemfile.h"
#include "systemscene.h"
#include "systemview.h"
#include "tst_secanvassupport.h"

#include <QAction>
#include <QClipboard>
#include <QComboBox>
#include <QGuiApplication>
#include <QListWidget>
#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace SystemEditor;

class TestSeComposite : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void groupSaveReopenDecompose();
    void dialogOffersMembersPorts();
    void copyGoesToTheSystemClipboard();
    void pasteFromAnotherWindow();
    void malformedClipboard_data();
    void malformedClipboard();

private:
    void selectByClicks(const QStringList &names);
    CompositeDialog::Choice m_choice;
    std::unique_ptr<SystemModel> m_model;
    std::unique_ptr<QUndoStack> m_stack;
    std::unique_ptr<SystemCanvas> m_canvas;
};

void TestSeComposite::init()
{
    m_model = SeCanvasTest::loadModel();
    QVERIFY(m_model);
    m_stack = std::make_unique<QUndoStack>();
    m_canvas = std::make_unique<SystemCanvas>(m_model.get(), m_stack.get());
    m_canvas->resize(1000, 700);
    m_canvas->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_canvas.get()));
    m_canvas->setCompositeEditor(
        [this](const SystemModel &, const QStringList &) { return m_choice; });
}

void TestSeComposite::cleanup()
{
    m_canvas.reset();
    m_stack.reset();
    m_model.reset();
}

void TestSeComposite::selectByClicks(const QStringList &names)
{
    SystemView *view = m_canvas->view();
    for (int i = 0; i < names.size(); ++i) {
        const ComponentItem *item = m_canvas->scene()->componentItem(names.at(i));
        const QPointF title = item->mapToScene(item->bodyRect().topLeft() + QPointF(10, 6));
        QTest::mouseClick(view->viewport(), Qt::LeftButton,
                          i == 0 ? Qt::NoModifier : Qt::ControlModifier,
                          view->mapFromScene(title));
    }
    QCOMPARE(m_canvas->scene()->selectedComponents(), names);
}

void TestSeComposite::groupSaveReopenDecompose()
{
    const QStringList members {QStringLiteral("Sensor0"), QStringLiteral("Filter0")};
    selectByClicks(members);
    QAction *group = m_canvas->action(QStringLiteral("actionGroupComposite"));
    QAction *decompose = m_canvas->action(QStringLiteral("actionDecompose"));
    QVERIFY(group->isEnabled());
    QVERIFY(!decompose->isEnabled());
    m_choice = {QStringLiteral("PeriodicStateShared"),
                {{QStringLiteral("Filter0"), QStringLiteral("Filter0.out")}}};
    const QStringList before = m_model->componentIds();
    group->trigger();
    QCOMPARE(m_model->componentIds().size(), before.size() + 1);
    const QString name = m_model->componentIds().last();
    // A copy: saving rewrites the model's components (dates, pathUri), so a pointer would dangle.
    const std::optional<Profile::RtsComponent> composite = m_model->hasComponent(name)
        ? std::optional<Profile::RtsComponent>(*m_model->component(name))
        : std::nullopt;
    QVERIFY(composite);
    QCOMPARE(composite->compositeType, std::optional<QString>("PeriodicStateShared"));
    QCOMPARE(composite->participants.size(), 2);
    QCOMPARE(composite->dataPorts.size(), 1);
    QCOMPARE(composite->dataPorts.first().name, QStringLiteral("Filter0.out"));
    // Drawn as a frame around and under its members, with the exported port on it.
    ComponentItem *frame = m_canvas->scene()->componentItem(name);
    QVERIFY(frame->appearance().isComposite());
    QVERIFY(frame->zValue() < m_canvas->scene()->componentItem(members.first())->zValue());
    const QRectF frameBody = frame->mapRectToScene(frame->bodyRect());
    for (const QString &member : members) {
        const ComponentItem *item = m_canvas->scene()->componentItem(member);
        QVERIFY(frameBody.contains(item->mapRectToScene(item->bodyRect())));
    }
    QVERIFY(frame->portItem(QStringLiteral("Filter0.out")));
    QCOMPARE(m_canvas->scene()->selectedComponents(), QStringList {name});
    QVERIFY(decompose->isEnabled());

    // Saved and reopened equal.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("grouped.xml"));
    Profile::Diagnostics diagnostics;
    QVERIFY(saveSystemFile(*m_model, path, &diagnostics));
    const std::unique_ptr<SystemModel> reopened = SeCanvasTest::loadModel(path);
    QVERIFY(reopened);
    const Profile::RtsComponent *again = reopened->component(name);
    QVERIFY(again);
    QCOMPARE(again->compositeType, composite->compositeType);
    QCOMPARE(again->participants, composite->participants);
    QCOMPARE(again->dataPorts, composite->dataPorts);

    // Decompose, undo, redo.
    decompose->trigger();
    QCOMPARE(m_model->componentIds(), before);
    QVERIFY(!m_canvas->scene()->componentItem(name));
    m_stack->undo();
    QVERIFY(m_model->hasComponent(name));
    QVERIFY(m_canvas->scene()->componentItem(name)->appearance().isComposite());
    m_stack->undo();
    QCOMPARE(m_model->componentIds(), before);
    m_stack->redo();
    QVERIFY(m_model->hasComponent(name));
    m_stack->redo();
    QCOMPARE(m_model->componentIds(), before);
}

void TestSeComposite::dialogOffersMembersPorts()
{
    const QStringList members {QStringLiteral("Filter0")};
    CompositeDialog dialog(*m_model, members);
    QCOMPARE(dialog.kindBox()->count(), 3);
    QCOMPARE(dialog.portList()->count(), int(m_model->ports(QStringLiteral("Filter0")).size()));
    QVERIFY(dialog.choice().exportedPorts.isEmpty());
    dialog.kindBox()->setCurrentText(QStringLiteral("Grouping"));
    dialog.portList()->item(0)->setCheckState(Qt::Checked);
    const CompositeDialog::Choice choice = dialog.choice();
    QCOMPARE(choice.compositeType, QStringLiteral("Grouping"));
    QCOMPARE(choice.exportedPorts.size(), 1);
    QCOMPARE(choice.exportedPorts.first().instanceName, QStringLiteral("Filter0"));
}

void TestSeComposite::copyGoesToTheSystemClipboard()
{
    m_canvas->scene()->selectComponents({QStringLiteral("Sensor0"), QStringLiteral("Filter0")});
    m_canvas->action(QStringLiteral("actionCopy"))->trigger();
    const QMimeData *mime = QGuiApplication::clipboard()->mimeData();
    QVERIFY(mime->hasFormat(ComponentClipboard::MimeType));
    QVERIFY(mime->text().contains(QStringLiteral("rts:RtsProfile")));
    QVERIFY(mime->text().contains(QStringLiteral("Filter0")));
    QVERIFY(m_canvas->action(QStringLiteral("actionPaste"))->isEnabled());
    QString error;
    const std::optional<ComponentClipboard> read = ComponentClipboard::fromMimeData(mime, &error);
    QVERIFY2(read, qPrintable(error));
    QCOMPARE(read->components.size(), 2);
    QCOMPARE(read->dataConnectors.size(), 1);
    QCOMPARE(read->rtcProfiles.size(), 2);
}

void TestSeComposite::pasteFromAnotherWindow()
{
    m_canvas->scene()->selectComponents({QStringLiteral("Sensor0"), QStringLiteral("Filter0")});
    m_canvas->scene()->copySelection();
    // Another document in another window.
    const std::unique_ptr<SystemModel> other = SeCanvasTest::loadModel();
    QUndoStack otherStack;
    SystemCanvas otherCanvas(other.get(), &otherStack);
    otherCanvas.show();
    otherCanvas.action(QStringLiteral("actionPaste"))->trigger();
    QCOMPARE(other->componentIds().size(), 5);
    const QStringList pasted = otherCanvas.scene()->selectedComponents();
    QCOMPARE(pasted.size(), 2);
    for (const QString &name : pasted) {
        QVERIFY(!m_model->hasComponent(name)); // new unique names
        QVERIFY(otherCanvas.scene()->componentItem(name));
    }
    const QString source = pasted.first();
    QCOMPARE(other->layout(source).position,
             m_model->layout(QStringLiteral("Sensor0")).position + QPointF(40, 40));
    QCOMPARE(other->connectorIds().size(), 2);
    // The pasted components keep their port kinds (the RTC profiles came along).
    QVERIFY(other->rtcProfile(source));
    const QList<PortInfo> ports = other->ports(source);
    QCOMPARE(ports.size(), m_model->ports(QStringLiteral("Sensor0")).size());
    QVERIFY(!ports.isEmpty());
    QVERIFY(ports.first().kind != PortKind::Unknown);
    otherStack.undo();
    QCOMPARE(other->componentIds().size(), 3);
}

void TestSeComposite::malformedClipboard_data()
{
    QTest::addColumn<QString>("format");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<QString>("message");
    QTest::newRow("plain text") << "text/plain" << QByteArray("hello") << "no components";
    QTest::newRow("broken xml") << ComponentClipboard::MimeType
                                << QByteArray("<rts:RtsProfile xmlns:rts=") << "cannot be read";
    QTest::newRow("no components")
        << ComponentClipboard::MimeType
        << QByteArray("<?xml version=\"1.0\"?><rts:RtsProfile "
                      "xmlns:rts=\"http://www.openrtp.org/namespaces/rts\" rts:id=\"RTSystem:a:b:1\" "
                      "rts:version=\"0.2\" rts:creationDate=\"2020-01-01T00:00:00\" "
                      "rts:updateDate=\"2020-01-01T00:00:00\"/>")
        << "cannot be read";
}

void TestSeComposite::malformedClipboard()
{
    QFETCH(QString, format);
    QFETCH(QByteArray, data);
    QFETCH(QString, message);
    auto *mime = new QMimeData;
    mime->setData(format, data);
    QGuiApplication::clipboard()->setMimeData(mime);
    QSignalSpy messages(m_canvas.get(), &SystemCanvas::statusMessage);
    const QStringList before = m_model->componentIds();
    QVERIFY(!m_canvas->scene()->paste());
    QCOMPARE(m_model->componentIds(), before);
    QCOMPARE(m_stack->count(), 0);
    QVERIFY(!messages.isEmpty());
    QVERIFY2(messages.last().first().toString().contains(message),
             qPrintable(messages.last().first().toString()));
}

QTEST_MAIN(TestSeComposite)
#include "tst_secomposite.moc"
