// SPDX-License-Identifier: MIT
// The canvas widgets: the connector dialog's enabling rules and validation, the properties
// panel editing configuration through undo, the repository view's drag onto the canvas, the
// canvas actions, find bar and overview.
#include "tst_secanvassupport.h"

#include "instancecommands.h"
#include "componentitem.h"
#include "configurationseteditor.h"
#include "connectordialog.h"
#include "connectoritem.h"
#include "overviewwidget.h"
#include "parametereditor.h"
#include "propertiespanel.h"
#include "serviceconnectordialog.h"
#include "repositoryview.h"
#include "rtcrepository.h"
#include "systemcanvas.h"
#include "systemscene.h"
#include "systemview.h"

#include <QAction>
#include <QApplication>
#include <QWhatsThis>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTreeView>
#include <QUndoStack>

using namespace SystemEditor;
using SeCanvasTest::loadModel;

namespace {

QComboBox *combo(const QDialog &dialog, const char *name)
{
    return dialog.findChild<QComboBox *>(QLatin1String(name));
}

QLineEdit *edit(const QDialog &dialog, const char *name)
{
    return dialog.findChild<QLineEdit *>(QLatin1String(name));
}

QPushButton *okButton(const QDialog &dialog)
{
    return dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
}

ConnectorSettings defaults()
{
    return ConnectorSettings::defaults(QStringLiteral("Sensor0.out"), QStringLiteral("Filter0.in"),
                                       QStringLiteral("RTC::TimedLong"));
}

} // namespace

class TestSeCanvasWidgets : public QObject
{
    Q_OBJECT

private slots:
    void dialogShowsDefaults();
    void dialogExplainsEverySetting();
    void dialogEnablingRules_data();
    void dialogEnablingRules();
    void dialogValidation_data();
    void dialogValidation();
    void dialogRoundTripsSettings();
    void dialogOffersGivenChoices();
    void serviceDialogMapsAndWarns();
    void propertiesEditConfigurationThroughUndo();
    void propertiesActivateCopyDeleteSets();
    void propertiesShowConnector();
    void repositoryDragCreatesInstance();
    void canvasActionsAndFindBar();
    void overviewShowsWhenDiagramIsLarge();
};

void TestSeCanvasWidgets::dialogShowsDefaults()
{
    ConnectorDialog dialog(defaults());
    QCOMPARE(edit(dialog, "name")->text(), QStringLiteral("out_in"));
    QCOMPARE(edit(dialog, "dataType")->text(), QStringLiteral("RTC::TimedLong"));
    QCOMPARE(combo(dialog, "interfaceType")->currentText(), QStringLiteral("corba_cdr"));
    QCOMPARE(combo(dialog, "dataflowType")->currentText(), QStringLiteral("push"));
    QCOMPARE(combo(dialog, "subscriptionType")->currentText(), QStringLiteral("flush"));
    QCOMPARE(edit(dialog, "pushRate")->text(), QStringLiteral("1000.0"));
    // Settings left to the ports say "default", combo boxes as well as fields.
    for (const char *name : {"marshalingType", "outFullPolicy", "inEmptyPolicy"}) {
        QCOMPARE(combo(dialog, name)->currentText(), QString());
        QCOMPARE(combo(dialog, name)->lineEdit()->placeholderText(), QStringLiteral("default"));
    }
    QCOMPARE(edit(dialog, "outBufferLength")->placeholderText(), QStringLiteral("default"));
    QVERIFY(okButton(dialog)->isEnabled());
    QCOMPARE(dialog.settings(), defaults());
}

// What's This on every setting says what it is; on each dataport.* / buffer.* field it names that key.
void TestSeCanvasWidgets::dialogExplainsEverySetting()
{
    ConnectorDialog dialog(defaults());
    const QList<std::pair<const char *, const char *>> settings = {
        {"name", "The connector's name"}, {"connectDirection", "Which port calls connect()"},
        {"properties", "Properties without a field"},
        {"interfaceType", "dataport.interface_type"}, {"marshalingType", "dataport.marshaling_type"},
        {"dataflowType", "dataport.dataflow_type"}, {"subscriptionType", "dataport.subscription_type"},
        {"pushRate", "dataport.push_rate"}, {"pushPolicy", "dataport.publisher.push_policy"}, {"skipCount", "dataport.publisher.skip_count"},
        {"timestampPolicy", "dataport.timestamp_policy"}, {"outBufferLength", "buffer.length"},
        {"inBufferLength", "buffer.length"}, {"outFullPolicy", "buffer.write.full_policy"}, {"inEmptyPolicy", "buffer.read.empty_policy"},
        {"outWriteTimeout", "buffer.write.timeout"}, {"inReadTimeout", "buffer.read.timeout"}};
    for (const auto &[name, key] : settings) {
        auto *widget = dialog.findChild<QWidget *>(QLatin1String(name));
        QVERIFY2(widget, name);
        QVERIFY2(widget->whatsThis().startsWith(QLatin1String(key)), qPrintable(QLatin1String(name) + ": " + widget->whatsThis()));
    }
    // Shift+F1 in a field shows its text.
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QLineEdit *length = edit(dialog, "outBufferLength");
    length->setFocus();
    QTRY_VERIFY(length->hasFocus());
    QTest::keyClick(length, Qt::Key_F1, Qt::ShiftModifier);
    const auto shown = [] {
        for (QWidget *window : QApplication::topLevelWidgets()) {
            if (window->inherits("QWhatsThat") && window->isVisible())
                return true;
        }
        return false;
    };
    QTRY_VERIFY(shown());
    QWhatsThis::hideText();
}

void TestSeCanvasWidgets::dialogEnablingRules_data()
{
    QTest::addColumn<QString>("dataflow");
    QTest::addColumn<QString>("subscription");
    QTest::addColumn<QString>("policy");
    QTest::addColumn<bool>("subscriptionEnabled");
    QTest::addColumn<bool>("rateEnabled");
    QTest::addColumn<bool>("policyEnabled");
    QTest::addColumn<bool>("skipEnabled");
    QTest::newRow("push flush") << "push" << "flush" << "all" << true << false << false << false;
    QTest::newRow("push new") << "push" << "new" << "all" << true << false << true << false;
    QTest::newRow("push new skip") << "push" << "new" << "skip" << true << false << true << true;
    QTest::newRow("push periodic") << "push" << "periodic" << "fifo" << true << true << true
                                   << false;
    QTest::newRow("pull") << "pull" << "periodic" << "skip" << false << false << false << false;
}

void TestSeCanvasWidgets::dialogEnablingRules()
{
    QFETCH(QString, dataflow);
    QFETCH(QString, subscription);
    QFETCH(QString, policy);
    QFETCH(bool, subscriptionEnabled);
    QFETCH(bool, rateEnabled);
    QFETCH(bool, policyEnabled);
    QFETCH(bool, skipEnabled);
    ConnectorDialog dialog(defaults());
    // Driven as a user would: through the widgets.
    combo(dialog, "subscriptionType")->setCurrentText(subscription);
    combo(dialog, "pushPolicy")->setCurrentText(policy);
    combo(dialog, "dataflowType")->setCurrentText(dataflow);
    QCOMPARE(combo(dialog, "subscriptionType")->isEnabled(), subscriptionEnabled);
    QCOMPARE(edit(dialog, "pushRate")->isEnabled(), rateEnabled);
    QCOMPARE(combo(dialog, "pushPolicy")->isEnabled(), policyEnabled);
    QCOMPARE(edit(dialog, "skipCount")->isEnabled(), skipEnabled);
}

void TestSeCanvasWidgets::dialogValidation_data()
{
    QTest::addColumn<QString>("widget");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("problem");
    QTest::newRow("empty name") << "name" << "" << "name";
    QTest::newRow("long name") << "name" << QString(256, QLatin1Char('n')) << "255";
    QTest::newRow("zero push rate") << "pushRate" << "0" << "push rate";
    QTest::newRow("text push rate") << "pushRate" << "fast" << "push rate";
    QTest::newRow("negative skip") << "skipCount" << "-1" << "skip count";
    QTest::newRow("buffer length") << "outBufferLength" << "0" << "buffer length";
    QTest::newRow("read timeout") << "inReadTimeout" << "soon" << "read timeout";
}

void TestSeCanvasWidgets::dialogValidation()
{
    QFETCH(QString, widget);
    QFETCH(QString, value);
    QFETCH(QString, problem);
    ConnectorSettings settings = defaults();
    settings.subscriptionType = QStringLiteral("periodic");
    settings.pushPolicy = QStringLiteral("skip");
    ConnectorDialog dialog(settings);
    QVERIFY(dialog.problems().isEmpty());
    QLineEdit *field = dialog.findChild<QLineEdit *>(widget);
    QVERIFY(field);
    field->setText(value);
    QVERIFY(!okButton(dialog)->isEnabled());
    QVERIFY2(dialog.problems().join(QLatin1Char(' ')).contains(problem, Qt::CaseInsensitive),
             qPrintable(dialog.problems().join(QLatin1Char(' '))));
    const QLabel *shown = dialog.findChild<QLabel *>(QStringLiteral("problems"));
    QVERIFY(shown->text().contains(problem, Qt::CaseInsensitive));
    dialog.accept();
    QCOMPARE(dialog.result(), int(QDialog::Rejected));
}

void TestSeCanvasWidgets::dialogRoundTripsSettings()
{
    ConnectorSettings settings = defaults();
    settings.name = QStringLiteral("link");
    settings.interfaceType = QStringLiteral("shared_memory");
    settings.marshalingType = QStringLiteral("cdr");
    settings.subscriptionType = QStringLiteral("new");
    settings.pushPolicy = QStringLiteral("skip");
    settings.skipCount = QStringLiteral("3");
    settings.timestampPolicy = QStringLiteral("on_send");
    settings.outBuffer = {QStringLiteral("8"), QStringLiteral("overwrite"), QStringLiteral("1.5"),
                          QStringLiteral("readback"), QStringLiteral("2")};
    settings.inBuffer.length = QStringLiteral("4");
    settings.freeProperties = {{QStringLiteral("my.key"), QStringLiteral("value")}};
    ConnectorDialog dialog(settings);
    QCOMPARE(dialog.settings(), settings);
    // A duplicate free property name is a problem.
    dialog.addFreeProperty(QStringLiteral("my.key"), QStringLiteral("other"));
    QVERIFY(!okButton(dialog)->isEnabled());
    dialog.removeCurrentFreeProperty();
    QVERIFY(okButton(dialog)->isEnabled());
    dialog.accept();
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
    QCOMPARE(dialog.settings(), settings);
}

void TestSeCanvasWidgets::dialogOffersGivenChoices()
{
    ConnectorDialog::Choices choices;
    choices.dataflowTypes = {QStringLiteral("pull")};
    ConnectorDialog dialog(defaults(), choices);
    QComboBox *dataflow = combo(dialog, "dataflowType");
    QCOMPARE(dataflow->count(), 1);
    QCOMPARE(dataflow->itemText(0), QStringLiteral("pull"));
}

void TestSeCanvasWidgets::serviceDialogMapsAndWarns()
{
    const auto interface = [](const char *name, const char *type, const char *instance,
                              Profile::RtcDirection polarity) {
        InterfaceInfo info;
        info.name = QLatin1String(name);
        info.type = QLatin1String(type);
        info.instanceName = QLatin1String(instance);
        info.polarity = polarity;
        return info;
    };
    using Profile::RtcDirection;
    const QList<InterfaceInfo> provider {interface("ctrl", "Demo::Control", "control",
                                                   RtcDirection::Provided),
                                         interface("log", "Demo::Log", "log",
                                                   RtcDirection::Provided)};
    const QList<InterfaceInfo> consumer {interface("ctrl", "Demo::OldControl", "control",
                                                   RtcDirection::Required)};
    ServiceConnectorDialog dialog(QStringLiteral("a_b"), provider, consumer);
    QCOMPARE(dialog.mappingTable()->rowCount(), 1);
    // The consumer column holds the required side whichever port came first.
    QVERIFY(dialog.mappingTable()->item(0, 0)->text().contains(QStringLiteral("OldControl")));
    const QString warnings = dialog.warnings().join(QLatin1Char('\n'));
    QVERIFY2(warnings.contains(QStringLiteral("Demo::OldControl")), qPrintable(warnings));
    QVERIFY2(warnings.contains(QStringLiteral("\"log\"")), qPrintable(warnings));
    QCOMPARE(dialog.warnings().size(), 2);
    QPushButton *ok = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    QVERIFY(ok->isEnabled());
    dialog.setName(QString());
    QVERIFY(!ok->isEnabled());
    dialog.setName(QStringLiteral("link"));
    dialog.accept();
    QCOMPARE(dialog.result(), int(QDialog::Accepted));
    QCOMPARE(dialog.name(), QStringLiteral("link"));
}

void TestSeCanvasWidgets::propertiesEditConfigurationThroughUndo()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QUndoStack stack;
    PropertiesPanel panel(model.get(), &stack);
    panel.showComponent(QStringLiteral("Filter0"));
    QCOMPARE(panel.field(QStringLiteral("typeName"))->text(), QStringLiteral("Filter"));
    QCOMPARE(panel.field(QStringLiteral("pathUri"))->text(), QStringLiteral("RTCs/Filter0.xml"));
    QCOMPARE(panel.field(QStringLiteral("componentId"))->text(),
             QStringLiteral("RTC:Test:canvas:Filter:1.0.0"));
    QCOMPARE(panel.shownSet(), QStringLiteral("default"));
    const auto gain = [&] {
        return model->component(QStringLiteral("Filter0"))->configurationSets.at(0).data.at(0).data;
    };
    const auto shownGain = [&] {
        return panel.configurationEditor()->parameterEditor(QStringLiteral("gain"))->value();
    };
    QCOMPARE(shownGain(), QStringLiteral("1.0"));
    // Edited in the value's widget as a user does (no profile constraint: plain text).
    auto *edit = qobject_cast<QLineEdit *>(
        panel.configurationEditor()->parameterEditor(QStringLiteral("gain"))->input());
    QVERIFY(edit);
    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("2.5"));
    QCOMPARE(gain(), QStringLiteral("2.5"));
    QCOMPARE(stack.count(), 1);
    stack.undo();
    QCOMPARE(gain(), QStringLiteral("1.0"));
    QCOMPARE(shownGain(), QStringLiteral("1.0"));
    stack.redo();
    QCOMPARE(gain(), QStringLiteral("2.5"));
    QCOMPARE(shownGain(), QStringLiteral("2.5"));
    // The other set shows its own values.
    panel.setShownSet(QStringLiteral("precise"));
    QCOMPARE(shownGain(), QStringLiteral("0.5"));
}

void TestSeCanvasWidgets::propertiesActivateCopyDeleteSets()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QUndoStack stack;
    PropertiesPanel panel(model.get(), &stack);
    panel.showComponent(QStringLiteral("Filter0"));
    const auto component = [&] { return model->component(QStringLiteral("Filter0")); };
    panel.setShownSet(QStringLiteral("precise"));
    panel.activateShownSet();
    QCOMPARE(component()->activeConfigurationSet, QStringLiteral("precise"));
    QVERIFY(panel.setCombo()->currentText().contains(QStringLiteral("active")));
    panel.addSetCopy();
    QCOMPARE(component()->configurationSets.size(), 3);
    QCOMPARE(component()->configurationSets.last().id, QStringLiteral("precise_copy"));
    QCOMPARE(component()->configurationSets.last().data,
             component()->configurationSets.at(1).data);
    QCOMPARE(panel.shownSet(), QStringLiteral("precise_copy"));
    panel.setShownSet(QStringLiteral("precise"));
    panel.deleteShownSet();
    QCOMPARE(component()->configurationSets.size(), 2);
    // The active set was deleted: the first remaining one becomes active.
    QCOMPARE(component()->activeConfigurationSet, QStringLiteral("default"));
    QCOMPARE(stack.count(), 3);
    stack.undo();
    stack.undo();
    stack.undo();
    QCOMPARE(component()->activeConfigurationSet, QStringLiteral("default"));
    QCOMPARE(component()->configurationSets.size(), 2);
    QCOMPARE(component()->configurationSets.at(1).id, QStringLiteral("precise"));
}

void TestSeCanvasWidgets::propertiesShowConnector()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QUndoStack stack;
    SystemScene scene(model.get(), &stack);
    PropertiesPanel panel(model.get(), &stack);
    panel.followScene(&scene);
    QVERIFY(panel.shownComponent().isEmpty());
    scene.componentItem(QStringLiteral("Sink0"))->setSelected(true);
    QCOMPARE(panel.shownComponent(), QStringLiteral("Sink0"));
    scene.clearSelection();
    scene.connectorItem(QStringLiteral("c-sensor-filter"))->setSelected(true);
    QCOMPARE(panel.shownConnector(), QStringLiteral("c-sensor-filter"));
    QCOMPARE(panel.field(QStringLiteral("connectorSource"))->text(), QStringLiteral("Sensor0.out"));
    QCOMPARE(panel.field(QStringLiteral("connectorName"))->text(), QStringLiteral("out_in"));
    const QList<QTableWidgetItem *> rows
        = panel.connectorTable()->findItems(QStringLiteral("dataport.dataflow_type"),
                                            Qt::MatchExactly);
    QCOMPARE(rows.size(), 1);
    QSignalSpy edit(&panel, &PropertiesPanel::editConnectorRequested);
    panel.findChild<QPushButton *>(QStringLiteral("editConnector"))->click();
    QCOMPARE(edit.size(), 1);
    QCOMPARE(edit.first().first().toString(), QStringLiteral("c-sensor-filter"));
    // Deleting what is shown empties the panel.
    scene.deleteSelection();
    QVERIFY(panel.shownConnector().isEmpty());
}

void TestSeCanvasWidgets::repositoryDragCreatesInstance()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QUndoStack stack;
    SystemCanvas canvas(model.get(), &stack);
    canvas.resize(900, 600);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));
    RtcRepository repository;
    RepositoryView view(&repository);
    view.addSources({SeCanvasTest::dataPath(QStringLiteral("RTCs"))});
    QCOMPARE(repository.entries().size(), 3);
    // What the tree would drag for the Sink component.
    QModelIndex sink;
    for (int c = 0; c < repository.rowCount(); ++c) {
        const QModelIndex category = repository.index(c, 0);
        for (int r = 0; r < repository.rowCount(category); ++r) {
            const QModelIndex row = repository.index(r, 0, category);
            if (row.data(RtcRepository::ComponentIdRole).toString().contains(QLatin1String("Sink")))
                sink = row;
        }
    }
    QVERIFY(sink.isValid());
    QVERIFY(view.treeView()->dragEnabled());
    std::unique_ptr<QMimeData> mime(repository.mimeData({sink}));
    QVERIFY(mime);
    QWidget *viewport = canvas.view()->viewport();
    const QPoint at(200, 300);
    QDragEnterEvent enter(at, Qt::CopyAction, mime.get(), Qt::LeftButton, {});
    QApplication::sendEvent(viewport, &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(at, Qt::CopyAction, mime.get(), Qt::LeftButton, {});
    QApplication::sendEvent(viewport, &drop);
    QVERIFY(model->hasComponent(QStringLiteral("Sink1")));
    QVERIFY(canvas.scene()->componentItem(QStringLiteral("Sink1")));
    QCOMPARE(model->layout(QStringLiteral("Sink1")).position, canvas.view()->mapToScene(at));
    QCOMPARE(model->ports(QStringLiteral("Sink1")).size(), 1);
    QCOMPARE(canvas.scene()->selectedComponents(), QStringList {QStringLiteral("Sink1")});
    stack.undo();
    QVERIFY(!model->hasComponent(QStringLiteral("Sink1")));
}

void TestSeCanvasWidgets::canvasActionsAndFindBar()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QUndoStack stack;
    SystemCanvas canvas(model.get(), &stack);
    canvas.resize(900, 600);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));
    QAction *remove = canvas.action(QStringLiteral("actionDelete"));
    QVERIFY(remove);
    QVERIFY(!remove->isEnabled());
    canvas.scene()->selectComponents({QStringLiteral("Sink0")});
    QVERIFY(remove->isEnabled());
    QVERIFY(!canvas.action(QStringLiteral("actionAlign0"))->isEnabled());
    canvas.view()->setFocus();
    QTest::keyClick(canvas.view(), Qt::Key_Delete);
    QVERIFY(!model->hasComponent(QStringLiteral("Sink0")));
    stack.undo();
    QVERIFY(model->hasComponent(QStringLiteral("Sink0")));
    // Ctrl+F opens the find bar; Enter selects the match.
    QVERIFY(!canvas.findEdit()->isVisible());
    QTest::keyClick(canvas.view(), Qt::Key_F, Qt::ControlModifier);
    QVERIFY(canvas.findEdit()->isVisible());
    QTest::keyClicks(canvas.findEdit(), QStringLiteral("sens"));
    QTest::keyClick(canvas.findEdit(), Qt::Key_Return);
    QCOMPARE(canvas.scene()->selectedComponents(), QStringList {QStringLiteral("Sensor0")});
    // Select all, then turn the whole selection at once (one undo step).
    canvas.action(QStringLiteral("actionSelectAll"))->trigger();
    QCOMPARE(canvas.scene()->selectedComponents().size(), 3);
    canvas.action(QStringLiteral("actionDirectionup"))->trigger();
    QCOMPARE(model->layout(QStringLiteral("Sensor0")).direction, Direction::Up);
    QCOMPARE(model->layout(QStringLiteral("Filter0")).direction, Direction::Up);
    stack.undo();
    QCOMPARE(model->layout(QStringLiteral("Filter0")).direction, Direction::Left);
}

void TestSeCanvasWidgets::overviewShowsWhenDiagramIsLarge()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QUndoStack stack;
    SystemCanvas canvas(model.get(), &stack);
    canvas.resize(1200, 700);
    canvas.show();
    QVERIFY(QTest::qWaitForWindowExposed(&canvas));
    canvas.view()->fitToDiagram();
    QTRY_VERIFY(!canvas.overview()->isVisible());
    stack.push(new MoveComponentsCommand(model.get(),
                                         {{QStringLiteral("Sink0"), QPointF(4000, 3000)}}));
    canvas.view()->resetZoom();
    QTRY_VERIFY(canvas.overview()->isVisible());
    // Clicking in the map moves the view there.
    const QPoint target = (canvas.overview()->visibleFrame().center() + QPointF(60, 40)).toPoint();
    const QPointF wanted = canvas.overview()->sceneAt(target);
    QTest::mouseClick(canvas.overview(), Qt::LeftButton, {}, target);
    const QPointF centre
        = canvas.view()->mapToScene(canvas.view()->viewport()->rect().center());
    QVERIFY2(QLineF(centre, wanted).length() < 60,
             qPrintable(QStringLiteral("%1 away").arg(QLineF(centre, wanted).length())));
}

QTEST_MAIN(TestSeCanvasWidgets)
#include "tst_secanvaswidgets.moc"
