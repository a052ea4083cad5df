// SPDX-License-Identifier: MIT
// Offline System Editor dialogs and properties: the data connector's connect direction, the
// service connector's editable interface mapping, and configuration editing with the widgets and
// constraints of the RTC profile — each through undo, saved and read back.
#include "configurationseteditor.h"
#include "elementlisteditor.h"
#include "connectorcommands.h"
#include "connectordialog.h"
#include "parametereditor.h"
#include "propertiespanel.h"
#include "rtcprofile.h"
#include "serviceconnectordialog.h"
#include "systemfile.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSlider>
#include <QTableWidget>
#include <QToolButton>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace SystemEditor;

namespace {

std::unique_ptr<SystemModel> loadModel(const QString &path
                                       = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/seprops/system.xml"))
{
    Profile::Diagnostics diagnostics;
    std::optional<LoadedSystem> loaded = loadSystemFile(path, &diagnostics);
    if (!loaded)
        return nullptr;
    auto model = std::make_unique<SystemModel>();
    model->setProfile(loaded->profile, loaded->rtcProfiles);
    return model;
}

/// Saves the model into a temporary folder and loads it back.
std::unique_ptr<SystemModel> reopened(SystemModel &model, QTemporaryDir &dir)
{
    Profile::Diagnostics diagnostics;
    const QString path = dir.filePath(QStringLiteral("system.xml"));
    if (!saveSystemFile(model, path, &diagnostics))
        return nullptr;
    return loadModel(path);
}

ServicePortSide sideOf(const SystemModel &model, const QString &instance, const QString &port)
{
    const std::optional<PortInfo> info = model.port(instance, port);
    return {instance, info->profileName, info->interfaces};
}

/// The test system's model in a properties panel; edits go onto `stack`.
struct PanelFixture
{
    std::unique_ptr<SystemModel> model = loadModel();
    QUndoStack stack;
    std::unique_ptr<PropertiesPanel> panel;

    /// False when the system does not load; else the panel shows `instance`.
    bool show(const QString &instance)
    {
        if (!model)
            return false;
        panel = std::make_unique<PropertiesPanel>(model.get(), &stack);
        panel->showComponent(instance);
        return true;
    }
};

const QString SensorFilter = QStringLiteral("c-sensor-filter");
const QString Control = QStringLiteral("s-control");

} // namespace

class TestSeProps : public QObject
{
    Q_OBJECT

private slots:
    void connectDirectionEditedThroughUndo();
    void connectDirectionFixedWhenOnlyOneOffered();
    void serviceMappingEditedThroughUndoAndSaved();
    void serviceDirectionEditedThroughUndoAndSaved();
    void serviceDirectionOfNewConnector();
    void serviceDirectionFixed();
    void configurationWidgetsFollowTheProfile();
    void configurationRejectsBrokenConstraint();
    void configurationTextFallbackAndSets();
    void configurationArrayEditedPerElement();
    void elementRulesFromTheProfile();
};

void TestSeProps::connectDirectionEditedThroughUndo()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QVERIFY(model);
    const ConnectorSettings before
        = ConnectorSettings::fromConnector(*model->dataConnector(SensorFilter), model.get());
    QCOMPARE(before.connectDirection, ConnectDirection::OutToIn);
    ConnectorDialog dialog(before);
    auto *direction = dialog.findChild<QComboBox *>(QStringLiteral("connectDirection"));
    QVERIFY(direction->isEnabled());
    QCOMPARE(direction->count(), 2);
    QTest::keyClick(direction, Qt::Key_Down);
    const ConnectorSettings after = dialog.settings();
    QCOMPARE(after.connectDirection, ConnectDirection::InToOut);

    QUndoStack stack;
    stack.push(EditConnectorCommand::fromSettings(model.get(), SensorFilter, after));
    const auto source = [&] { return model->dataConnector(SensorFilter)->source.portName; };
    QCOMPARE(source(), QStringLiteral("Filter0.in"));
    QCOMPARE(model->dataConnector(SensorFilter)->target.portName, QStringLiteral("Sensor0.out"));
    stack.undo();
    QCOMPARE(source(), QStringLiteral("Sensor0.out"));
    stack.redo();
    QCOMPARE(source(), QStringLiteral("Filter0.in"));

    // Saved as the source end, read back, shown again by the dialog.
    QTemporaryDir dir;
    std::unique_ptr<SystemModel> again = reopened(*model, dir);
    QVERIFY(again);
    const ConnectorSettings read
        = ConnectorSettings::fromConnector(*again->dataConnector(SensorFilter), again.get());
    QCOMPARE(read.connectDirection, ConnectDirection::InToOut);
    ConnectorDialog shown(read);
    QCOMPARE(shown.findChild<QComboBox *>(QStringLiteral("connectDirection"))->currentData(),
             QVariant(int(ConnectDirection::InToOut)));
    QCOMPARE(shown.settings(), read);
}

void TestSeProps::connectDirectionFixedWhenOnlyOneOffered()
{
    ConnectorDialog::Choices choices;
    choices.connectDirections = {ConnectDirection::OutToIn};
    ConnectorSettings settings = ConnectorSettings::defaults(QStringLiteral("a.out"),
                                                             QStringLiteral("b.in"),
                                                             QStringLiteral("RTC::TimedLong"));
    settings.connectDirection = ConnectDirection::InToOut;
    ConnectorDialog dialog(settings, choices);
    auto *direction = dialog.findChild<QComboBox *>(QStringLiteral("connectDirection"));
    QVERIFY(!direction->isEnabled());
    QCOMPARE(dialog.settings().connectDirection, ConnectDirection::InToOut);
}

void TestSeProps::serviceMappingEditedThroughUndoAndSaved()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QVERIFY(model);
    const ServiceConnectorSettings before
        = ServiceConnectorSettings::fromConnector(*model->serviceConnector(Control));
    QVERIFY(before.mapping.isEmpty());
    const ServicePortSide filter = sideOf(*model, "Filter0", "Filter0.control");
    const ServicePortSide sensor = sideOf(*model, "Sensor0", "Sensor0.control");
    ServiceConnectorDialog dialog(before, filter, sensor);
    QCOMPARE(dialog.mappingTable()->rowCount(), 1); // Filter0's one required interface
    QComboBox *provider = dialog.providerChoice(0);
    QCOMPARE(provider->count(), 3); // automatic, control, backup: only provided interfaces
    QCOMPARE(dialog.warnings().size(), 1); // Sensor0's "spare" is left over
    QTest::keyClick(provider, Qt::Key_Down);
    QTest::keyClick(provider, Qt::Key_Down);
    QVERIFY(provider->currentText().startsWith(QStringLiteral("backup")));
    const QString warnings = dialog.warnings().join(QLatin1Char('\n'));
    QVERIFY2(warnings.contains(QStringLiteral("another instance name")), qPrintable(warnings));
    const ServiceConnectorSettings after = dialog.settings();
    const QString key = QStringLiteral("Filter0.port.control.required.Demo::Control.control");
    const QString value = QStringLiteral("Sensor0.port.control.provided.Demo::Control.backup");
    QCOMPARE(after.mapping, (QList<QPair<QString, QString>> {{key, value}}));

    QUndoStack stack;
    stack.push(EditConnectorCommand::fromSettings(model.get(), Control, after));
    const auto mapped = [&] {
        return Profile::rtsPropertyValue(model->serviceConnector(Control)->properties, key);
    };
    QCOMPARE(mapped(), std::optional<QString>(value));
    stack.undo();
    QCOMPARE(mapped(), std::nullopt);
    stack.redo();
    QCOMPARE(mapped(), std::optional<QString>(value));

    QTemporaryDir dir;
    std::unique_ptr<SystemModel> again = reopened(*model, dir);
    QVERIFY(again);
    const ServiceConnectorSettings read
        = ServiceConnectorSettings::fromConnector(*again->serviceConnector(Control));
    QCOMPARE(read, after);
    // Other properties stay; reopening the dialog shows the saved choice.
    QVERIFY(Profile::rtsPropertyValue(again->serviceConnector(Control)->properties,
                                      QStringLiteral("port.port_type")));
    ServiceConnectorDialog shown(read, filter, sensor);
    QCOMPARE(shown.providerChoice(0)->currentIndex(), 2);
    QCOMPARE(shown.settings(), read);
}

void TestSeProps::serviceDirectionEditedThroughUndoAndSaved()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QVERIFY(model);
    const auto connector = [&] { return model->serviceConnector(Control); };
    const ServiceConnectorSettings before = ServiceConnectorSettings::fromConnector(*connector());
    const ServicePortSide filter = sideOf(*model, "Filter0", "Filter0.control");
    const ServicePortSide sensor = sideOf(*model, "Sensor0", "Sensor0.control");
    ServiceConnectorDialog dialog(before, filter, sensor);
    QComboBox *direction = dialog.directionChoice();
    QVERIFY(direction->isEnabled());
    QCOMPARE(direction->count(), 2);
    QCOMPARE(direction->currentIndex(), 0);
    QVERIFY2(direction->currentText().startsWith(QStringLiteral("Filter0.control")),
             qPrintable(direction->currentText()));
    QCOMPARE(dialog.settings(), before); // untouched: nothing to apply
    QTest::keyClick(direction, Qt::Key_Down);
    const ServiceConnectorSettings after = dialog.settings();
    QCOMPARE(after.connectingPort.instanceName, QStringLiteral("Sensor0"));
    QVERIFY(after != before);
    // The drawn route stays: the bend points reverse with the ends.
    Profile::RtsServicePortConnector routed = *connector();
    Profile::setRtsProperty(routed.properties, SystemModel::BendPointProperty,
                            bendPointsToText({{10, 20}, {30, 40}}));
    after.applyTo(routed);
    QCOMPARE(bendPointsFromText(*Profile::rtsPropertyValue(routed.properties,
                                                           SystemModel::BendPointProperty)),
             (QList<QPointF> {{30, 40}, {10, 20}}));

    const Profile::RtsServicePortConnector original = *connector();
    QUndoStack stack;
    stack.push(EditConnectorCommand::fromSettings(model.get(), Control, after));
    QCOMPARE(connector()->source.portName, QStringLiteral("Sensor0.control"));
    QCOMPARE(connector()->target.portName, QStringLiteral("Filter0.control"));
    stack.undo();
    QCOMPARE(*connector(), original);
    stack.redo();
    QCOMPARE(connector()->source.portName, QStringLiteral("Sensor0.control"));

    // Saved as the source end; the dialog shows the saved direction whichever side comes first.
    QTemporaryDir dir;
    std::unique_ptr<SystemModel> again = reopened(*model, dir);
    QVERIFY(again);
    const ServiceConnectorSettings read
        = ServiceConnectorSettings::fromConnector(*again->serviceConnector(Control));
    QCOMPARE(read.connectingPort, (ConnectorEnd {"Sensor0", "Sensor0.control"}));
    ServiceConnectorDialog shown(read, filter, sensor);
    QCOMPARE(shown.directionChoice()->currentIndex(), 1);
    QVERIFY(shown.directionChoice()->currentText().startsWith(QStringLiteral("Sensor0.control")));
    QCOMPARE(shown.settings(), read);
    ServiceConnectorDialog asDrawn(read, sensor, filter);
    QCOMPARE(asDrawn.directionChoice()->currentIndex(), 0);
    QCOMPARE(asDrawn.settings(), read);
}

void TestSeProps::serviceDirectionOfNewConnector()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QVERIFY(model);
    const ConnectorEnd filter {"Filter0", "Filter0.control"};
    const ConnectorEnd sensor {"Sensor0", "Sensor0.control"};
    ServiceConnectorDialog dialog(ServiceConnectorSettings {"link", {}, {}},
                                  sideOf(*model, "Filter0", "Filter0.control"),
                                  sideOf(*model, "Sensor0", "Sensor0.control"));
    // A new connector starts with the port the drag began at.
    QCOMPARE(dialog.directionChoice()->currentIndex(), 0);
    QCOMPARE(makeServiceConnector(*model, filter, sensor, dialog.settings()).source.instanceName,
             QStringLiteral("Filter0"));
    dialog.directionChoice()->setCurrentIndex(1);
    const Profile::RtsServicePortConnector made
        = makeServiceConnector(*model, filter, sensor, dialog.settings());
    QCOMPARE(made.source.portName, QStringLiteral("Sensor0.control"));
    QCOMPARE(made.target.portName, QStringLiteral("Filter0.control"));
    QCOMPARE(made.name, QStringLiteral("link"));
}

void TestSeProps::serviceDirectionFixed()
{
    std::unique_ptr<SystemModel> model = loadModel();
    QVERIFY(model);
    const ServiceConnectorSettings settings
        = ServiceConnectorSettings::fromConnector(*model->serviceConnector(Control));
    ServiceConnectorDialog dialog(settings, sideOf(*model, "Sensor0", "Sensor0.control"),
                                  sideOf(*model, "Filter0", "Filter0.control"));
    QVERIFY(dialog.directionChoice()->isEnabled());
    QCOMPARE(dialog.directionChoice()->currentIndex(), 1);
    dialog.setDirectionChangeable(false);
    QVERIFY(!dialog.directionChoice()->isEnabled());
    QCOMPARE(dialog.settings().connectingPort, settings.connectingPort);

    // Ports known only by their interfaces: nothing names a direction.
    ServiceConnectorDialog unnamed(QStringLiteral("a_b"), {}, {});
    QVERIFY(!unnamed.directionChoice()->isEnabled());
    QVERIFY(unnamed.settings().connectingPort.instanceName.isEmpty());
    Profile::RtsServicePortConnector connector = *model->serviceConnector(Control);
    unnamed.settings().applyTo(connector);
    QCOMPARE(connector.source.instanceName, QStringLiteral("Filter0"));
}

void TestSeProps::configurationWidgetsFollowTheProfile()
{
    PanelFixture f;
    QVERIFY(f.show(QStringLiteral("Filter0")));
    ConfigurationSetEditor *editor = f.panel->configurationEditor();
    auto *slider = qobject_cast<QSlider *>(editor->parameterEditor("gain")->input());
    QVERIFY(slider);
    QCOMPARE(slider->maximum(), 20); // 0..10 by 0.5
    auto *label = editor->findChild<QLabel *>(QStringLiteral("label_gain"));
    QCOMPARE(label->text(), QStringLiteral("gain (dB):"));
    QCOMPARE(label->toolTip(), QStringLiteral("Type: double"));
    QCOMPARE(editor->findChild<QLabel *>(QStringLiteral("label_mode"))->text(),
             QStringLiteral("mode:"));
    QCOMPARE(slider->value(), 2);
    const auto value = [&](int set, int index) {
        return f.model->component(QStringLiteral("Filter0"))
            ->configurationSets.at(set)
            .data.at(index)
            .data.value_or(QString());
    };
    QTest::keyClick(slider, Qt::Key_Right);
    QCOMPARE(value(0, 0), QStringLiteral("1.5"));
    auto *slow = editor->parameterEditor("mode")->findChild<QRadioButton *>("choice_slow");
    QVERIFY(slow);
    QTest::mouseClick(slow, Qt::LeftButton);
    QCOMPARE(value(0, 1), QStringLiteral("slow"));
    QCOMPARE(f.stack.count(), 2);
    f.stack.undo();
    QCOMPARE(value(0, 1), QStringLiteral("fast"));
    QVERIFY(editor->parameterEditor("mode")->findChild<QRadioButton *>("choice_fast")->isChecked());
    f.stack.undo();
    QCOMPARE(value(0, 0), QStringLiteral("1.0"));
    QCOMPARE(slider->value(), 2);
    f.stack.redo();
    f.stack.redo();
    QCOMPARE(value(0, 0), QStringLiteral("1.5"));
    QCOMPARE(value(0, 1), QStringLiteral("slow"));
}

void TestSeProps::configurationRejectsBrokenConstraint()
{
    PanelFixture f;
    QVERIFY(f.show(QStringLiteral("Filter0")));
    QVERIFY(!f.panel->setValue(QStringLiteral("gain"), QStringLiteral("42")));
    QVERIFY(!f.panel->setValue(QStringLiteral("mode"), QStringLiteral("turbo")));
    QCOMPARE(f.stack.count(), 0);
    ParameterEditor *gain = f.panel->configurationEditor()->parameterEditor("gain");
    gain->setValue(QStringLiteral("42")); // as a pasted value: shown, refused, explained
    QVERIFY(!gain->error().isEmpty());
    QCOMPARE(f.stack.count(), 0);
    QVERIFY(f.panel->setValue(QStringLiteral("gain"), QStringLiteral("9.5")));
    QCOMPARE(f.stack.count(), 1);
}

void TestSeProps::configurationTextFallbackAndSets()
{
    PanelFixture f;
    QVERIFY(f.show(QStringLiteral("Sink0"))); // its profile lists no parameters
    ConfigurationSetEditor *editor = f.panel->configurationEditor();
    auto *text = qobject_cast<QLineEdit *>(editor->parameterEditor("label")->input());
    QVERIFY(text);
    text->selectAll();
    QTest::keyClicks(text, QStringLiteral("end"));
    const auto sink = [&] { return f.model->component(QStringLiteral("Sink0")); };
    QCOMPARE(sink()->configurationSets.at(0).data.at(0).data, QStringLiteral("end"));
    QCOMPARE(f.stack.count(), 1); // typing merges into one step
    f.stack.undo();
    QCOMPARE(sink()->configurationSets.at(0).data.at(0).data, QStringLiteral("sink"));
    f.stack.redo();

    f.panel->showComponent(QStringLiteral("Filter0"));
    editor->addSet();
    QCOMPARE(f.model->component("Filter0")->configurationSets.size(), 3);
    QCOMPARE(f.model->component("Filter0")->configurationSets.last().id, QStringLiteral("new_set"));
    QCOMPARE(f.model->component("Filter0")->configurationSets.last().data.at(1).data,
             QStringLiteral("fast")); // the profile's default
    QCOMPARE(editor->shownSet(), QStringLiteral("new_set"));
    editor->activateShownSet();
    QCOMPARE(f.model->component("Filter0")->activeConfigurationSet, QStringLiteral("new_set"));

    QTemporaryDir dir;
    std::unique_ptr<SystemModel> again = reopened(*f.model, dir);
    QVERIFY(again);
    QCOMPARE(again->component("Filter0")->configurationSets.size(), 3);
    QCOMPARE(again->component("Filter0")->activeConfigurationSet, QStringLiteral("new_set"));
    QCOMPARE(again->component("Sink0")->configurationSets.at(0).data.at(0).data,
             QStringLiteral("end"));
    f.stack.undo();
    f.stack.undo();
    QCOMPARE(f.model->component("Filter0")->configurationSets.size(), 2);
}

void TestSeProps::configurationArrayEditedPerElement()
{
    PanelFixture f;
    QVERIFY(f.show(QStringLiteral("Filter0")));
    ConfigurationSetEditor *editor = f.panel->configurationEditor();
    QVERIFY(!editor->parameterEditor(QStringLiteral("weights")));
    ElementListEditor *weights = editor->elementEditor(QStringLiteral("weights"));
    QVERIFY(weights);
    QVERIFY(!editor->elementEditor(QStringLiteral("gain"))); // a scalar stays one widget
    QCOMPARE(weights->count(), 2);
    const auto stored = [&] {
        return f.model->component(QStringLiteral("Filter0"))
            ->configurationSets.at(0)
            .data.at(2)
            .data.value_or(QString());
    };
    const auto typeInto = [](ParameterEditor *element, const QString &text) {
        auto *edit = qobject_cast<QLineEdit *>(element->input());
        edit->selectAll();
        QTest::keyClicks(edit, text);
    };

    // Each element is checked on its own: 2 breaks 0<=x<=1 and is refused with the reason.
    typeInto(weights->element(1), QStringLiteral("2"));
    QVERIFY(!weights->element(1)->error().isEmpty());
    QVERIFY(weights->element(0)->error().isEmpty());
    QCOMPARE(stored(), QStringLiteral("0.25,0.75"));
    QCOMPARE(f.stack.count(), 0);
    QVERIFY(!f.panel->setValue(QStringLiteral("weights"), QStringLiteral("0.1,2")));
    typeInto(weights->element(1), QStringLiteral("0.5"));
    QCOMPARE(stored(), QStringLiteral("0.25,0.5"));
    QCOMPARE(f.stack.count(), 1);

    // Add and remove are steps of their own.
    QTest::mouseClick(weights->findChild<QPushButton *>(QStringLiteral("addElement_weights")),
                      Qt::LeftButton);
    QCOMPARE(weights->count(), 3);
    QCOMPARE(stored(), QStringLiteral("0.25,0.5,0.5"));
    QCOMPARE(f.stack.count(), 2);
    typeInto(weights->element(2), QStringLiteral("1"));
    QCOMPARE(stored(), QStringLiteral("0.25,0.5,1"));
    QCOMPARE(f.stack.count(), 3);
    QTest::mouseClick(weights->findChild<QToolButton *>(QStringLiteral("removeElement_0")),
                      Qt::LeftButton);
    QCOMPARE(stored(), QStringLiteral("0.5,1"));
    QCOMPARE(f.stack.count(), 4);
    QCOMPARE(weights->count(), 2);

    f.stack.undo();
    QCOMPARE(stored(), QStringLiteral("0.25,0.5,1"));
    QCOMPARE(weights->count(), 3);
    QCOMPARE(weights->element(0)->value(), QStringLiteral("0.25"));
    f.stack.undo();
    f.stack.undo();
    QCOMPARE(stored(), QStringLiteral("0.25,0.5"));
    QCOMPARE(weights->value(), QStringLiteral("0.25,0.5"));
    f.stack.redo();
    QCOMPARE(stored(), QStringLiteral("0.25,0.5,0.5"));
}

void TestSeProps::elementRulesFromTheProfile()
{
    Profile::RtcConfiguration vector;
    vector.type = QStringLiteral("vector<int>");
    QVERIFY(ElementRules::appliesTo(vector));
    Profile::RtcConfiguration scalar;
    scalar.type = QStringLiteral("int");
    QVERIFY(!ElementRules::appliesTo(scalar));
    // A list constraint checks element i against member i; later elements are free.
    ElementRules rules;
    rules.memberTexts = {QStringLiteral("0<=x<=1"), QStringLiteral("x<10")};
    QVERIFY(rules.check(QStringLiteral("0.5,9,100")).isEmpty());
    QVERIFY(rules.check(QStringLiteral("0.5,11")).startsWith(QStringLiteral("Element 2")));
    QVERIFY(!rules.check(QStringLiteral("2")).isEmpty());
}

QTEST_MAIN(TestSeProps)
#include "tst_seprops.moc"
