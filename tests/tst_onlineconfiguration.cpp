// SPDX-License-Identifier: MIT
#include "componentproxy.h"
#include "configurationview.h"
#include "livesystem.h"
#include "namingbrowser.h"
#include "onlinesession.h"
#include "orb.h"
#include "parametereditor.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTest>

using namespace SystemEditor;
using Widget = ParameterRule::Widget;

// The Configuration view: widget and constraint rules, and editing ConfigSample0 in a real
// rtmanager.
class TestOnlineConfiguration : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void rulesFromWidgetAndConstraint_data();
    void rulesFromWidgetAndConstraint();
    void checksValues_data();
    void checksValues();
    void editorsRoundTripValues();
    void showsSetsAndWidgets();
    void refusesInvalidValues();
    void appliesToTheLiveComponent();
    void addsCopiesActivatesAndDeletesSets();

private:
    Corba::ComponentProxy sample() const;
    void load(ConfigurationView &view);

    LiveTest::LiveSystem m_live;
};

void TestOnlineConfiguration::initTestCase()
{
    Corba::Orb::setCallTimeout(3000);
    QString error;
    QVERIFY2(m_live.startNameServer(&error), qPrintable(error));
    const quint16 port = LiveTest::freePort();
    const QStringList arguments {"-d",
                                 "-o",
                                 QStringLiteral("corba.endpoints=127.0.0.1:%1").arg(port),
                                 "-o",
                                 "corba.nameservers=" + m_live.namingServer(),
                                 "-o",
                                 "naming.formats=cfghost.host_cxt/%n.rtc",
                                 "-o",
                                 "manager.naming_formats=cfghost.host_cxt/%n.mgr",
                                 "-o",
                                 "manager.components.precreate=ConfigSample"};
    QVERIFY2(
        m_live.startProcess(RTMANAGER_PATH, arguments, "rtmanager ready", &error),
        qPrintable(error));
}

Corba::ComponentProxy TestOnlineConfiguration::sample() const
{
    const auto path = Corba::RtPath::parse(
        QStringLiteral("/%1/cfghost.host_cxt/ConfigSample0.rtc").arg(m_live.namingServer()));
    return Corba::ComponentProxy(Corba::NamingBrowser::resolve(*path), path->toString());
}

void TestOnlineConfiguration::load(ConfigurationView &view)
{
    QSignalSpy loaded(&view, &ConfigurationView::loaded);
    const Corba::ComponentProxy proxy = sample();
    view.setComponent(proxy.path(), proxy.ior());
    QVERIFY(loaded.wait(10000));
}

void TestOnlineConfiguration::rulesFromWidgetAndConstraint_data()
{
    QTest::addColumn<QString>("widget");
    QTest::addColumn<QString>("constraint");
    QTest::addColumn<int>("kind");
    QTest::addColumn<double>("step");
    QTest::addColumn<QStringList>("choices");
    QTest::newRow("text") << "text"
                          << "" << int(Widget::Text) << 1.0 << QStringList();
    QTest::newRow("slider with step") << "slider.0.1"
                                      << "0<=x<=100" << int(Widget::Slider) << 0.1 << QStringList();
    QTest::newRow("slider without bounds falls back")
        << "slider.1"
        << "" << int(Widget::Text) << 1.0 << QStringList();
    QTest::newRow("spin") << "spin"
                          << "0..10" << int(Widget::Spin) << 1.0 << QStringList();
    QTest::newRow("radio") << "radio"
                           << "(a,b,c)" << int(Widget::Radio) << 1.0 << QStringList {"a", "b", "c"};
    QTest::newRow("checkbox") << "checkbox"
                              << "(x,y)" << int(Widget::CheckBox) << 1.0 << QStringList {"x", "y"};
    QTest::newRow("ordered list") << "ordered_list"
                                  << "(p,q,r)" << int(Widget::OrderedList) << 1.0
                                  << QStringList {"p", "q", "r"};
    QTest::newRow("unknown widget") << "dial"
                                    << "0<=x<=5" << int(Widget::Text) << 1.0 << QStringList();
}

void TestOnlineConfiguration::rulesFromWidgetAndConstraint()
{
    QFETCH(QString, widget);
    QFETCH(QString, constraint);
    QFETCH(int, kind);
    QFETCH(double, step);
    QFETCH(QStringList, choices);
    const ParameterRule rule = ParameterRule::from(widget, constraint);
    QCOMPARE(int(rule.widget), kind);
    QCOMPARE(rule.step, step);
    QCOMPARE(rule.choices, choices);
}

void TestOnlineConfiguration::checksValues_data()
{
    QTest::addColumn<QString>("widget");
    QTest::addColumn<QString>("constraint");
    QTest::addColumn<QString>("value");
    QTest::addColumn<bool>("valid");
    QTest::newRow("in range") << "text"
                              << "0<=x<=150"
                              << "150" << true;
    QTest::newRow("above range") << "text"
                                 << "0<=x<=150"
                                 << "151" << false;
    QTest::newRow("not a number") << "text"
                                  << "0<=x<=150"
                                  << "abc" << false;
    QTest::newRow("open bound") << "text"
                                << "x>0"
                                << "0" << false;
    QTest::newRow("between") << "text"
                             << "1..3"
                             << "2.5" << true;
    QTest::newRow("enumeration") << "text"
                                 << "(default,mode0)"
                                 << "mode0" << true;
    QTest::newRow("not in enumeration") << "text"
                                        << "(default,mode0)"
                                        << "mode9" << false;
    QTest::newRow("not") << "text"
                         << "!(5)"
                         << "5" << false;
    QTest::newRow("list") << "text"
                          << "[0<x,(1,2)]"
                          << "3,2" << true;
    QTest::newRow("list element wrong") << "text"
                                        << "[0<x,(1,2)]"
                                        << "3,7" << false;
    QTest::newRow("checkbox values") << "checkbox"
                                     << "(a,b,c)"
                                     << "a,c" << true;
    QTest::newRow("checkbox stranger") << "checkbox"
                                       << "(a,b,c)"
                                       << "a,z" << false;
    QTest::newRow("no constraint") << "text"
                                   << ""
                                   << "anything" << true;
}

void TestOnlineConfiguration::checksValues()
{
    QFETCH(QString, widget);
    QFETCH(QString, constraint);
    QFETCH(QString, value);
    QFETCH(bool, valid);
    const ParameterRule rule = ParameterRule::from(widget, constraint);
    QVERIFY(rule.constraintError.isEmpty());
    QCOMPARE(rule.check(value).isEmpty(), valid);
}

void TestOnlineConfiguration::editorsRoundTripValues()
{
    const struct
    {
        const char *widget;
        const char *constraint;
        const char *value;
    } cases[] = {{"text", "", "hello"},
                 {"slider.0.5", "0<=x<=10", "2.5"},
                 {"slider.2", "0<=x<=100", "40"},
                 {"spin", "0<=x<=1000", "999"},
                 {"radio", "(a,b,c)", "b"},
                 {"checkbox", "(a,b,c)", "a,c"},
                 {"ordered_list", "(a,b,c)", "c,a"}};
    for (const auto &c : cases) {
        ParameterEditor editor("p", ParameterRule::from(c.widget, c.constraint));
        QSignalSpy changed(&editor, &ParameterEditor::valueChanged);
        editor.setValue(c.value);
        QCOMPARE(editor.value(), QString(c.value));
        QVERIFY(editor.error().isEmpty());
        QVERIFY(!changed.isEmpty());
    }
    ParameterEditor slider("s", ParameterRule::from("slider.0.5", "0<=x<=10"));
    auto *input = qobject_cast<QSlider *>(slider.input());
    QVERIFY(input);
    QCOMPARE(input->maximum(), 20); // ten units in steps of 0.5
    input->setValue(3);
    QCOMPARE(slider.value(), QStringLiteral("1.5"));
}

void TestOnlineConfiguration::showsSetsAndWidgets()
{
    OnlineSession session;
    ConfigurationView view(&session);
    load(view);
    QCOMPARE(view.activeSet(), QStringLiteral("default"));
    QCOMPARE(view.currentSet(), QStringLiteral("default"));
    QCOMPARE(view.shownSets(), (QStringList {"default", "mode0", "mode1"}));
    auto *list = view.findChild<QListWidget *>("setList");
    QCOMPARE(list->item(0)->text(), QStringLiteral("default (active)"));
    QVERIFY(list->item(0)->font().bold());
    QVERIFY(!list->item(1)->font().bold());

    QVERIFY(qobject_cast<QSlider *>(view.editor("int_param0")->input()));
    QVERIFY(qobject_cast<QSpinBox *>(view.editor("int_param1")->input()));
    QVERIFY(qobject_cast<QSlider *>(view.editor("double_param0")->input()));
    QVERIFY(qobject_cast<QLineEdit *>(view.editor("double_param1")->input()));
    QVERIFY(view.editor("str_param0")->input()->findChild<QRadioButton *>("choice_mode1"));
    QVERIFY(!view.findChild<QPushButton *>("applyButton")->isEnabled());

    view.setDetailMode(true);
    QVERIFY(view.shownSets().contains("__widget__"));
    QVERIFY(view.shownSets().contains("__constraints__"));
    view.selectSet("__widget__");
    QCOMPARE(view.editor("int_param0")->value(), QStringLiteral("slider.10"));
    QVERIFY(qobject_cast<QLineEdit *>(view.editor("int_param0")->input()));
    view.setDetailMode(false);
    QVERIFY(!view.shownSets().contains("__widget__"));
    QCOMPARE(view.currentSet(), QStringLiteral("default"));
}

void TestOnlineConfiguration::refusesInvalidValues()
{
    OnlineSession session;
    ConfigurationView view(&session);
    load(view);
    view.selectSet("mode0");
    ParameterEditor *editor = view.editor("int_param1"); // spin, 0<=x<=1000, mode0 holds 98765
    QVERIFY(!editor->error().isEmpty()); // the live value is shown with its reason
    auto *errorLabel = editor->findChild<QLabel *>("error_int_param1");
    QVERIFY(!errorLabel->text().isEmpty());
    QCOMPARE(editor->value(), QStringLiteral("98765")); // not clamped by the spin box
    QVERIFY(!view.canApply()); // nothing edited yet

    ParameterEditor *text = view.editor("double_param1"); // text, no constraint
    text->setValue("1.5");
    QVERIFY(view.canApply()); // the untouched bad value does not block other edits
    editor->setValue("2000");
    QVERIFY(!view.canApply());
    QVERIFY(!view.apply());
    QVERIFY(!view.findChild<QPushButton *>("applyButton")->isEnabled());
    editor->setValue("12");
    QVERIFY(editor->error().isEmpty());
    QVERIFY(errorLabel->text().isEmpty());
    QVERIFY(view.canApply());
}

void TestOnlineConfiguration::appliesToTheLiveComponent()
{
    OnlineSession session;
    ConfigurationView view(&session);
    load(view);
    auto *text = qobject_cast<QLineEdit *>(view.editor("str_param1")->input());
    QVERIFY(text);
    text->setText("applied-value");
    auto *slider = qobject_cast<QSlider *>(view.editor("int_param0")->input());
    slider->setValue(4); // slider.10: the fourth step is 40
    auto *apply = view.findChild<QPushButton *>("applyButton");
    QStringList errors;
    for (const char *name : {"int_param0", "int_param1", "double_param0", "double_param1",
                             "str_param0", "str_param1", "vector_param0"})
        errors.append(view.editor(name)->error());
    QVERIFY2(apply->isEnabled(), qPrintable(errors.join('|')));
    QSignalSpy finished(&view, &ConfigurationView::editFinished);
    QSignalSpy loaded(&view, &ConfigurationView::loaded);
    QTest::mouseClick(apply, Qt::LeftButton);
    QVERIFY(finished.wait(10000));
    QCOMPARE(finished.at(0).at(0).toString(), QString());
    QVERIFY(loaded.wait(10000));
    QCOMPARE(sample().parameter("default", "str_param1"), QStringLiteral("applied-value"));
    QCOMPARE(sample().parameter("default", "int_param0"), QStringLiteral("40"));
    QCOMPARE(view.editor("int_param0")->value(), QStringLiteral("40"));
    QVERIFY(!apply->isEnabled());
}

void TestOnlineConfiguration::addsCopiesActivatesAndDeletesSets()
{
    OnlineSession session;
    ConfigurationView view(&session);
    load(view);
    QSignalSpy loaded(&view, &ConfigurationView::loaded);
    view.selectSet("mode1");
    view.addSet("copied", true);
    QVERIFY(loaded.wait(10000));
    QCOMPARE(sample().parameter("copied", "str_param0"), QStringLiteral("mode1"));
    QCOMPARE(view.currentSet(), QStringLiteral("copied"));
    view.addSet("added", false);
    QVERIFY(loaded.wait(10000));
    QCOMPARE(sample().parameter("added", "str_param1"),
             sample().parameter("default", "str_param1"));

    view.activateSet("copied");
    QVERIFY(loaded.wait(10000));
    QCOMPARE(sample().activeConfigurationSet(), QStringLiteral("copied"));
    QCOMPARE(view.activeSet(), QStringLiteral("copied"));
    QVERIFY(view.shownSets().contains("copied"));

    view.deleteSet("copied"); // the active set is not deleted
    view.deleteSet("added");
    QVERIFY(loaded.wait(10000));
    QVERIFY(!view.shownSets().contains("added"));
    QVERIFY(view.shownSets().contains("copied"));
    view.activateSet("default");
    QVERIFY(loaded.wait(10000));
    QCOMPARE(sample().activeConfigurationSet(), QStringLiteral("default"));
}

QTEST_MAIN(TestOnlineConfiguration)
#include "tst_onlineconfiguration.moc"
