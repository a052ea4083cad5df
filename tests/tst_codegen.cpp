// SPDX-License-Identifier: MIT
#include "backups.h"
#include "codegenerator.h"
#include "contextbuilder.h"
#include "cxxtypemapping.h"
#include "idlparser.h"
#include "javatypemapping.h"
#include "profileio.h"
#include "projectwriter.h"
#include "regionmerge.h"
#include "rtcxml.h"
#include "templaterenderer.h"
#include "templateset.h"
#include "common/tmpfsmount.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace Codegen;
using namespace Profile;

// The steps of code generation one by one: IDL → C++/Java mappings, profile → render context,
// templates, region merge, backups and the all-or-nothing project writer.
class TestCodegen : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cxxParameterMapping_data();
    void cxxParameterMapping();
    void cxxReturnMapping_data();
    void cxxReturnMapping();
    void javaParameterMapping_data();
    void javaParameterMapping();
    void contextBasicsAndModuleSpec();
    void contextPortsAndConfiguration();
    void contextServices();
    void contextRefusesBadNames_data();
    void contextRefusesBadNames();
    void missingInterfaceTypeFails();
    void contextStateMachine();
    void contextRefusesBadEvents_data();
    void contextRefusesBadEvents();
    void rendererInsertsVerbatim();
    void rendererDropsStandaloneTagLines();
    void rendererReportsBrokenTemplate();
    void userTemplateFolderOverrides();
    void userManifestCannotEscape();
    void safeRelativePaths_data();
    void safeRelativePaths();
    void mergeKeepsUserCode();
    void mergeReportsBrokenMarkers();
    void backupNamingAndRotation();
    void restoreSwapsBackupSet();
    void writerCreatesKeepsMergesOverwrites();
    void writerLeavesNothingOnFailure();
    void writerReportsFullOrReadOnlyDisk_data();
    void writerReportsFullOrReadOnlyDisk();

private:
    IdlParameter parameter(const QString &operation, const QString &name) const;
    IdlOperation operation(const QString &name) const;
    RtcProfile m_profile;
    IdlModel m_idl;
};

static QString data(const QString &relative)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/codegen/")) + relative;
}

static QVariantMap find(const QVariantList &list, const QString &key, const QString &value)
{
    for (const QVariant &item : list) {
        if (item.toMap().value(key).toString() == value)
            return item.toMap();
    }
    return {};
}

static QByteArray readAll(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray("<missing>");
}

static void writeFile(const QString &path, const QByteArray &content)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(content);
}

void TestCodegen::initTestCase()
{
    Diagnostics diagnostics;
    const std::optional<LoadedProfile> loaded = loadProfileFile(data("SampleComp.xml"), &diagnostics);
    QVERIFY2(loaded && loaded->rtc, qPrintable(diagnostics.isEmpty() ? QString() : diagnostics.first().toString()));
    m_profile = *loaded->rtc;
    IdlParser parser;
    parser.addSearchDirectory(RTSTUDIO_IDL_DIR);
    QVERIFY(parser.parseFile(data("idl/SampleService.idl")));
    m_idl = parser.model();
    QVERIFY(m_idl.interfaces.contains(QStringLiteral("Sample::Echo")));
}

IdlOperation TestCodegen::operation(const QString &name) const
{
    for (const IdlOperation &op : m_idl.allOperations(QStringLiteral("Sample::Echo"))) {
        if (op.name == name)
            return op;
    }
    return {};
}

IdlParameter TestCodegen::parameter(const QString &op, const QString &name) const
{
    for (const IdlParameter &p : operation(op).parameters) {
        if (p.name == name)
            return p;
    }
    return {};
}

void TestCodegen::cxxParameterMapping_data()
{
    QTest::addColumn<QString>("operation");
    QTest::addColumn<QString>("parameter");
    QTest::addColumn<QString>("expected");
    const QList<QStringList> rows = {
        {"say", "message", "const char*"},
        {"numbers", "s", "CORBA::Short"},
        {"numbers", "l", "CORBA::Long_out"},
        {"numbers", "d", "CORBA::Double&"},
        {"numbers", "o", "CORBA::Octet"},
        {"numbers", "c", "CORBA::Char_out"},
        {"move", "from", "const Sample::Point&"},
        {"move", "to", "Sample::Point_out"},
        {"move", "via", "Sample::Point&"},
        {"tag", "item", "const Sample::Label&"},
        {"tag", "copy", "Sample::Label_out"},
        {"tag", "edited", "Sample::Label&"},
        {"names", "filter", "const Sample::NameList&"},
        {"names", "points", "Sample::PointList_out"},
        {"rotate", "m", "const Sample::Matrix"},
        {"rotate", "inverse", "Sample::Matrix_out"},
        {"rotate", "scratch", "Sample::Matrix"},
        {"switchMode", "next", "Sample::Mode"},
        {"switchMode", "previous", "Sample::Mode_out"},
        {"switchMode", "current", "Sample::Mode&"},
        {"convert", "value", "const CORBA::Any&"},
        {"convert", "result", "CORBA::Any_out"},
        {"convert", "both", "CORBA::Any&"},
        {"exchange", "other", "Sample::Clock_ptr"},
        {"exchange", "mine", "Sample::Clock_out"},
        {"exchange", "shared", "Sample::Clock_ptr&"},
        {"tally", "c", "Sample::Count"},
        {"tally", "total", "Sample::Count_out"},
        {"sample", "when", "const RTC::Time&"}};
    for (const QStringList &row : rows)
        QTest::newRow(qPrintable(row[0] + "/" + row[1])) << row[0] << row[1] << row[2];
}

void TestCodegen::cxxParameterMapping()
{
    QFETCH(QString, operation);
    QFETCH(QString, parameter);
    QFETCH(QString, expected);
    const IdlParameter p = this->parameter(operation, parameter);
    QCOMPARE(p.name, parameter);
    QCOMPARE(cxxParameterType(m_idl, p), expected);
}

void TestCodegen::cxxReturnMapping_data()
{
    QTest::addColumn<QString>("operation");
    QTest::addColumn<QString>("type");
    QTest::addColumn<QString>("statement");
    const QList<QStringList> rows = {
        {"say", "char*", "return CORBA::string_dup(\"\");"},
        {"numbers", "CORBA::Boolean", "return false;"},
        {"move", "Sample::Point", "return Sample::Point();"},
        {"tag", "Sample::Label*", "return new Sample::Label();"},
        {"names", "Sample::NameList*", "return new Sample::NameList();"},
        {"rotate", "Sample::Matrix_slice*", "return Sample::Matrix_alloc();"},
        {"switchMode", "Sample::Mode", "return Sample::IDLE;"},
        {"convert", "CORBA::Any*", "return new CORBA::Any();"},
        {"exchange", "Sample::Clock_ptr", "return Sample::Clock::_nil();"},
        {"tally", "Sample::Count", "return 0;"},
        {"notify", "void", ""},
        {"reset", "void", ""}};
    for (const QStringList &row : rows)
        QTest::newRow(qPrintable(row[0])) << row[0] << row[1] << row[2];
}

void TestCodegen::cxxReturnMapping()
{
    QFETCH(QString, operation);
    QFETCH(QString, type);
    QFETCH(QString, statement);
    const IdlOperation op = this->operation(operation);
    QCOMPARE(op.name, operation);
    QCOMPARE(cxxReturnType(m_idl, op.returnType), type);
    QCOMPARE(cxxReturnStatement(m_idl, op.returnType), statement);
}

void TestCodegen::javaParameterMapping_data()
{
    QTest::addColumn<QString>("operation");
    QTest::addColumn<QString>("parameter");
    QTest::addColumn<QString>("expected");
    const QList<QStringList> rows = {
        {"say", "message", "String"},
        {"numbers", "s", "short"},
        {"numbers", "l", "org.omg.CORBA.IntHolder"},
        {"numbers", "d", "org.omg.CORBA.DoubleHolder"},
        {"numbers", "o", "byte"},
        {"move", "to", "Sample.PointHolder"},
        {"names", "filter", "String[]"},
        {"names", "points", "Sample.PointListHolder"},
        {"rotate", "m", "double[][]"},
        {"switchMode", "previous", "Sample.ModeHolder"},
        {"tally", "c", "int"},
        {"tally", "total", "org.omg.CORBA.IntHolder"},
        {"exchange", "other", "Sample.Clock"}};
    for (const QStringList &row : rows)
        QTest::newRow(qPrintable(row[0] + "/" + row[1])) << row[0] << row[1] << row[2];
}

void TestCodegen::javaParameterMapping()
{
    QFETCH(QString, operation);
    QFETCH(QString, parameter);
    QFETCH(QString, expected);
    QCOMPARE(javaParameterType(m_idl, this->parameter(operation, parameter)), expected);
}

void TestCodegen::contextBasicsAndModuleSpec()
{
    Diagnostics diagnostics;
    const std::optional<QVariantMap> context =
        ContextBuilder(m_profile, m_idl).build(TargetLanguage::Cpp, &diagnostics);
    QVERIFY(context);
    QVERIFY(diagnostics.isEmpty());
    QCOMPARE(context->value("name").toString(), QStringLiteral("SampleComp"));
    QCOMPARE(context->value("nameLower").toString(), QStringLiteral("samplecomp"));
    QCOMPARE(context->value("cmakeVersion").toString(), QStringLiteral("1.2.0"));
    QStringList spec;
    for (const QVariant &line : context->value("moduleSpec").toList())
        spec << line.toMap().value("key").toString() + "=" + line.toMap().value("literalValue").toString();
    const QStringList expected = {
        "implementation_id=SampleComp", "type_name=SampleComp",
        "description=Sample component with \\\"all\\\" port kinds", "version=1.2.0",
        "vendor=Example", "category=Test", "activity_type=PERIODIC", "kind=DataFlowComponent",
        "max_instance=1", "language=C++", "lang_type=compile", "conf.default.gain_value=10",
        "conf.default.mode=fast", "conf.default.rate=0.5", "conf.__widget__.gain_value=slider.1",
        "conf.__widget__.mode=radio", "conf.__constraints__.gain_value=0<=x<=100",
        "conf.__constraints__.mode=(fast,slow)", "conf.__type__.gain_value=int",
        "conf.__type__.mode=string", "conf.__type__.rate=double"};
    QCOMPARE(spec, expected);
    const QVariantList actions = context->value("actions").toList();
    QCOMPARE(actions.size(), 12);
    QCOMPARE(find(actions, "name", "onExecute").value("implemented").toBool(), true);
    QCOMPARE(find(actions, "name", "onExecute").value("description").toString(), QStringLiteral("Copies in to out"));
    QCOMPARE(find(actions, "name", "onReset").value("implemented").toBool(), false);
    QCOMPARE(find(actions, "name", "onFinalize").value("cxxParameters").toString(), QString());
    QCOMPARE(find(actions, "name", "onActivated").value("cxxParameters").toString(), QStringLiteral("RTC::UniqueId ec_id"));
    const std::optional<QVariantMap> python =
        ContextBuilder(m_profile, m_idl).build(TargetLanguage::Python, &diagnostics);
    QVERIFY(python);
    QCOMPARE(find(python->value("moduleSpec").toList(), "key", "lang_type").value("value").toString(), QStringLiteral("SCRIPT"));
}

void TestCodegen::contextPortsAndConfiguration()
{
    Diagnostics diagnostics;
    const QVariantMap cpp = *ContextBuilder(m_profile, m_idl).build(TargetLanguage::Cpp, &diagnostics);
    const QVariantMap in = cpp.value("inPorts").toList().value(0).toMap();
    QCOMPARE(in.value("variable").toString(), QStringLiteral("in")); // empty variableName
    QCOMPARE(in.value("nativeType").toString(), QStringLiteral("RTC::TimedLong"));
    QCOMPARE(in.value("first").toBool(), true);
    QCOMPARE(in.value("last").toBool(), true);
    const QVariantMap out = cpp.value("outPorts").toList().value(0).toMap();
    QCOMPARE(out.value("variable").toString(), QStringLiteral("result"));
    const QVariantList configs = cpp.value("configurations").toList();
    QCOMPARE(configs.size(), 3);
    QCOMPARE(find(configs, "name", "gain_value").value("variable").toString(), QStringLiteral("gain"));
    QCOMPARE(find(configs, "name", "mode").value("nativeType").toString(), QStringLiteral("std::string"));
    QCOMPARE(find(configs, "name", "mode").value("variable").toString(), QStringLiteral("mode"));
    QCOMPARE(find(configs, "name", "rate").value("widget").toString(), QStringLiteral("text"));
    QCOMPARE(find(configs, "name", "rate").value("hasConstraint").toBool(), false);

    const QVariantMap java = *ContextBuilder(m_profile, m_idl).build(TargetLanguage::Java, &diagnostics);
    QCOMPARE(java.value("inPorts").toList().value(0).toMap().value("init").toString(),
             QStringLiteral("new RTC.TimedLong(new RTC.Time(0, 0), 0)"));
    QCOMPARE(find(java.value("configurations").toList(), "name", "gain_value").value("holder").toString(),
             QStringLiteral("IntegerHolder"));
    const QVariantMap python = *ContextBuilder(m_profile, m_idl).build(TargetLanguage::Python, &diagnostics);
    QCOMPARE(python.value("outPorts").toList().value(0).toMap().value("init").toString(),
             QStringLiteral("OpenRTM_aist.instantiateDataType(RTC.TimedDouble)"));
    QCOMPARE(python.value("pythonModules").toStringList(),
             (QStringList{"RTC", "Sample", "Sample__POA"}));
}

void TestCodegen::contextServices()
{
    Diagnostics diagnostics;
    const ContextBuilder builder(m_profile, m_idl);
    const QVariantMap cpp = *builder.build(TargetLanguage::Cpp, &diagnostics);
    const QVariantMap provided = cpp.value("providedInterfaces").toList().value(0).toMap();
    QCOMPARE(provided.value("className").toString(), QStringLiteral("EchoSVC_impl"));
    QCOMPARE(provided.value("poaClass").toString(), QStringLiteral("POA_Sample::Echo"));
    QCOMPARE(provided.value("variable").toString(), QStringLiteral("echo0"));
    QCOMPARE(provided.value("instanceName").toString(), QStringLiteral("echo"));
    QCOMPARE(provided.value("idlBaseName").toString(), QStringLiteral("SampleService"));
    const QVariantList operations = provided.value("operations").toList();
    // Inherited and attribute operations come first: version (get), gain (get, set), reset.
    QCOMPARE(operations.value(0).toMap().value("name").toString(), QStringLiteral("version"));
    const QVariantMap say = find(operations, "name", "say");
    QCOMPARE(say.value("parameters").toString(), QStringLiteral("const char* message"));
    QCOMPARE(say.value("idlSignature").toString(), QStringLiteral("string say(in string message)"));
    const QVariantMap required = cpp.value("requiredInterfaces").toList().value(0).toMap();
    QCOMPARE(required.value("nativeType").toString(), QStringLiteral("Sample::Clock"));
    QCOMPARE(required.value("variable").toString(), QStringLiteral("clock"));
    QCOMPARE(cpp.value("providedIdls").toList().size(), 1);
    QCOMPARE(cpp.value("cxxIncludes").toStringList(),
             (QStringList{"<rtm/idl/BasicDataTypeSkel.h>", "\"SampleService.hh\""}));
    QCOMPARE(builder.projectIdlFiles().size(), 1);
    QVERIFY(builder.projectIdlFiles().first().endsWith(QStringLiteral("SampleService.idl")));

    const QVariantMap python = *builder.build(TargetLanguage::Python, &diagnostics);
    const QVariantList pyOps = python.value("providedInterfaces").toList().value(0).toMap().value("operations").toList();
    QCOMPARE(find(pyOps, "pythonName", "_set_gain").value("pythonParameters").toString(), QStringLiteral("self, value"));
    QCOMPARE(find(pyOps, "name", "numbers").value("pythonParameters").toString(), QStringLiteral("self, s, d, o"));
    QCOMPARE(find(pyOps, "name", "numbers").value("pythonResults").toString(), QStringLiteral("result, l, d, c"));
    // Python keywords as parameter names get omniidl's leading underscore.
    QCOMPARE(find(pyOps, "name", "move").value("pythonParameters").toString(), QStringLiteral("self, _from, via"));
    QCOMPARE(python.value("providedInterfaces").toList().value(0).toMap().value("poaClass").toString(),
             QStringLiteral("Sample__POA.Echo"));
}

void TestCodegen::contextRefusesBadNames_data()
{
    QTest::addColumn<QString>("field");
    QTest::addColumn<QString>("value");
    QTest::addColumn<int>("language");
    QTest::newRow("dash in name") << "name" << "My-Comp" << int(TargetLanguage::Cpp);
    QTest::newRow("path in name") << "name" << "../evil" << int(TargetLanguage::Cpp);
    QTest::newRow("digit first") << "name" << "1Comp" << int(TargetLanguage::Python);
    QTest::newRow("C++ keyword") << "name" << "class" << int(TargetLanguage::Cpp);
    QTest::newRow("Python keyword") << "name" << "lambda" << int(TargetLanguage::Python);
    QTest::newRow("Java keyword") << "name" << "package" << int(TargetLanguage::Java);
    QTest::newRow("dot in config variable") << "config" << "a.b" << int(TargetLanguage::Java);
    QTest::newRow("space in port") << "port" << "in port" << int(TargetLanguage::Cpp);
}

void TestCodegen::contextRefusesBadNames()
{
    QFETCH(QString, field);
    QFETCH(QString, value);
    QFETCH(int, language);
    RtcProfile profile = m_profile;
    if (field == "name")
        profile.basicInfo.name = value;
    else if (field == "port")
        profile.dataPorts[0].variableName = value;
    else
        profile.configurations[0].variableName = value;
    Diagnostics diagnostics;
    QVERIFY(!ContextBuilder(profile, m_idl).build(TargetLanguage(language), &diagnostics));
    QCOMPARE(diagnostics.size(), 1);
    QVERIFY2(diagnostics.first().message.contains(value), qPrintable(diagnostics.first().message));
    QVERIFY(!CodeGenerator(profile, m_idl).generate({TargetLanguage(language)}, &diagnostics));
}

void TestCodegen::missingInterfaceTypeFails()
{
    RtcProfile profile = m_profile;
    profile.servicePorts[0].interfaces[0].type = QStringLiteral("Sample::Nowhere");
    Diagnostics diagnostics;
    QVERIFY(!CodeGenerator(profile, m_idl).generate({TargetLanguage::Cpp}, &diagnostics));
    QVERIFY(hasErrors(diagnostics));
    QVERIFY(diagnostics.first().message.contains(QStringLiteral("Sample::Nowhere")));
}

namespace {

RtcEvent fsmEvent(const QString &name, const QString &source, const QString &target, const QString &type = {},
               const QString &condition = {})
{
    RtcEvent e;
    e.name = name;
    e.source = source;
    e.target = target;
    if (!type.isEmpty())
        e.type = type;
    if (!condition.isEmpty())
        e.condition = condition;
    return e;
}

RtcDataPort eventPort(const QString &name, const QList<RtcEvent> &events)
{
    RtcDataPort port;
    port.portType = QStringLiteral("EventPort");
    port.name = name;
    port.type = QStringLiteral("Any");
    port.events = events;
    return port;
}

} // namespace

void TestCodegen::contextStateMachine()
{
    RtcProfile profile = m_profile;
    profile.dataPorts << eventPort("control", {fsmEvent("coin", "Locked", "Unlocked", "TimedLong", "paidEnough"),
                                               fsmEvent("coin", "Unlocked", "Unlocked", "TimedLong"),
                                               fsmEvent("push", "Unlocked", "Locked", {}, "arm passed"),
                                               fsmEvent("push", "Locked", "Alarm")});
    profile.dataPorts << eventPort("service", {fsmEvent("reset", "Alarm", "Locked")});
    Diagnostics diagnostics;
    const QVariantMap cpp = *ContextBuilder(profile, m_idl).build(TargetLanguage::Cpp, &diagnostics);
    QVERIFY(cpp.value("hasFsm").toBool());
    QCOMPARE(cpp.value("fsmFiles").toList().size(), 1);
    QCOMPARE(cpp.value("fsmNamespace").toString(), QStringLiteral("SampleCompFsm"));
    QCOMPARE(cpp.value("fsmMachineType").toString(), QStringLiteral("RTC::Machine<SampleCompFsm::Top>"));
    QCOMPARE(cpp.value("fsmInitialState").toString(), QStringLiteral("Locked"));
    // One handler per event in Top; RTC Builder's unscoped data types get OpenRTM's scope.
    const QVariantList events = cpp.value("fsmEvents").toList();
    QCOMPARE(events.size(), 3);
    QCOMPARE(find(events, "name", "coin").value("declaration").toString(),
             QStringLiteral("virtual void coin(RTC::TimedLong /*data*/) {}"));
    QCOMPARE(find(events, "name", "reset").value("declaration").toString(), QStringLiteral("virtual void reset() {}"));
    // A condition that is a name names its guard; other text documents one named after the event.
    const QVariantList guards = cpp.value("fsmGuards").toList();
    QCOMPARE(guards.size(), 2);
    QCOMPARE(find(guards, "name", "paidEnough").value("declaration").toString(),
             QStringLiteral("bool paidEnough(const RTC::TimedLong& data)"));
    QCOMPARE(find(guards, "name", "paidEnough").value("hasConditions").toBool(), false);
    QCOMPARE(find(guards, "name", "pushGuard").value("conditions").toString(), QStringLiteral("arm passed"));
    // States in order of appearance; two transitions of one event from one state share a handler.
    const QVariantList states = cpp.value("fsmStates").toList();
    QCOMPARE(states.size(), 3);
    const QVariantMap locked = find(states, "name", "Locked");
    QCOMPARE(locked.value("declaredHandlers").toList().size(), 2);
    const QVariantList handlers = locked.value("handlers").toList();
    QCOMPARE(handlers.value(0).toMap().value("definition").toString(),
             QStringLiteral("void Locked::coin(RTC::TimedLong data)"));
    QCOMPARE(handlers.value(0).toMap().value("guardCall").toString(), QStringLiteral("paidEnough(data)"));
    QCOMPARE(handlers.value(1).toMap().value("hasGuard").toBool(), false);
    QCOMPARE(handlers.value(1).toMap().value("target").toString(), QStringLiteral("Alarm"));
    // Each EventPort binds each of its events once.
    const QVariantList ports = cpp.value("eventPorts").toList();
    QCOMPARE(ports.size(), 2);
    QCOMPARE(ports.value(0).toMap().value("events").toList().size(), 2);
    // onExecute runs the machine even when the profile leaves it off.
    const QVariantMap execute = find(cpp.value("actions").toList(), "name", "onExecute");
    QVERIFY(execute.value("implemented").toBool());
    QVERIFY(execute.value("runsFsm").toBool());

    // Python and Java keep their data-flow part.
    const QVariantMap python = *ContextBuilder(profile, m_idl).build(TargetLanguage::Python, &diagnostics);
    QVERIFY(!python.value("hasFsm").toBool());
    QVERIFY(python.value("fsmFiles").toList().isEmpty());
}

void TestCodegen::contextRefusesBadEvents_data()
{
    QTest::addColumn<QList<RtcEvent>>("events");
    QTest::addColumn<QString>("message");
    QTest::newRow("event name") << QList<RtcEvent>{fsmEvent("go on", "A", "B")} << "go on";
    QTest::newRow("state name") << QList<RtcEvent>{fsmEvent("go", "A", "B-1")} << "B-1";
    QTest::newRow("no source") << QList<RtcEvent>{fsmEvent("go", "", "B")} << "state ''";
    QTest::newRow("Top") << QList<RtcEvent>{fsmEvent("go", "Top", "B")} << "'Top'";
    QTest::newRow("one event, two types")
        << QList<RtcEvent>{fsmEvent("go", "A", "B", "TimedLong"), fsmEvent("go", "B", "A")} << "one event has one data type";
}

void TestCodegen::contextRefusesBadEvents()
{
    QFETCH(QList<RtcEvent>, events);
    QFETCH(QString, message);
    RtcProfile profile = m_profile;
    profile.dataPorts << eventPort("control", events);
    Diagnostics diagnostics;
    QVERIFY(!ContextBuilder(profile, m_idl).build(TargetLanguage::Cpp, &diagnostics));
    QCOMPARE(diagnostics.size(), 1);
    QVERIFY2(diagnostics.first().message.contains(message), qPrintable(diagnostics.first().message));
    QVERIFY2(diagnostics.first().message.contains("EventPort 'control'"), qPrintable(diagnostics.first().message));
}

void TestCodegen::rendererInsertsVerbatim()
{
    QString error;
    const QVariantMap context{{"a", "x<y && z>\"w\""},
                              {"list", QVariantList{QVariantMap{{"n", "1"}}, QVariantMap{{"n", "2"}}}},
                              {"flag", false}};
    QCOMPARE(*renderTemplate("{{a}}|{{#list}}{{n}},{{/list}}|{{^flag}}off{{/flag}}", context, &error),
             QStringLiteral("x<y && z>\"w\"|1,2,|off"));
}

void TestCodegen::rendererDropsStandaloneTagLines()
{
    QString error;
    const QVariantMap a{{"n", "a"}, {"p", true}, {"r", false}};
    const QVariantMap b{{"n", "b"}, {"p", false}, {"r", true}};
    const QVariantMap context{{"ports", QVariantList{QVariantMap{{"ifs", QVariantList{a}}},
                                                     QVariantMap{{"ifs", QVariantList{b}}}}}};
    const QString text = "S\n{{#ports}}\n  {{#ifs}}\n{{#p}}\n  P {{n}}\n{{/p}}\n{{^p}}\n  R {{n}}\n"
                         "{{/p}}\n{{/ifs}}\n  add\n{{/ports}}\nE\n";
    QCOMPARE(*renderTemplate(text, context, &error), QStringLiteral("S\n  P a\n  add\n  R b\n  add\nE\n"));
}

void TestCodegen::rendererReportsBrokenTemplate()
{
    QString error;
    QVERIFY(!renderTemplate("{{#open}} never closed", {}, &error));
    QVERIFY(error.contains(QStringLiteral("open")));
}

void TestCodegen::userTemplateFolderOverrides()
{
    QTemporaryDir user;
    writeFile(user.filePath("common/README.md.mustache"), "Custom {{name}}\n");
    Diagnostics diagnostics;
    CodeGenerator generator(m_profile, m_idl);
    generator.setUserTemplateFolder(user.path());
    const auto files = generator.generate({TargetLanguage::Python}, &diagnostics);
    QVERIFY(files);
    const auto readme = std::find_if(files->cbegin(), files->cend(),
                                     [](const GeneratedFile &f) { return f.path == "README.md"; });
    QVERIFY(readme != files->cend());
    QCOMPARE(readme->content, QByteArray("Custom SampleComp\n"));
    // Other templates still come from the built-ins.
    QString error;
    const auto set = TemplateSet::load("common", user.path(), &error);
    QVERIFY(set);
    QVERIFY(set->templateOrigin("rtc.conf.mustache").startsWith(QStringLiteral(":/")));
}

void TestCodegen::userManifestCannotEscape()
{
    QTemporaryDir user;
    writeFile(user.filePath("python/manifest.json"),
              R"({"files": [{"template": "x.mustache", "output": "../{{name}}.py"}]})");
    writeFile(user.filePath("python/x.mustache"), "print()\n");
    Diagnostics diagnostics;
    CodeGenerator generator(m_profile, m_idl);
    generator.setUserTemplateFolder(user.path());
    QVERIFY(!generator.generate({TargetLanguage::Python}, &diagnostics));
    QVERIFY(diagnostics.first().message.contains(QStringLiteral("would leave the project folder")));

    writeFile(user.filePath("python/manifest.json"),
              R"({"files": [{"template": "../../secret", "output": "a.py"}]})");
    diagnostics.clear();
    QVERIFY(!generator.generate({TargetLanguage::Python}, &diagnostics));
}

void TestCodegen::safeRelativePaths_data()
{
    QTest::addColumn<QString>("path");
    QTest::addColumn<bool>("safe");
    QTest::newRow("plain") << "src/A.cpp" << true;
    QTest::newRow("absolute") << "/etc/passwd" << false;
    QTest::newRow("parent") << "src/../../x" << false;
    QTest::newRow("dot") << "./x" << false;
    QTest::newRow("empty part") << "src//x" << false;
    QTest::newRow("drive") << "C:/x" << false;
    QTest::newRow("backslash") << "..\\x" << false;
    QTest::newRow("empty") << "" << false;
}

void TestCodegen::safeRelativePaths()
{
    QFETCH(QString, path);
    QFETCH(bool, safe);
    QCOMPARE(CodeGenerator::isSafeRelativePath(path), safe);
}

void TestCodegen::mergeKeepsUserCode()
{
    const QString existing = "#include \"A.h\"\n"
                             "// <rtc-template block=\"spec\">\n"
                             "old spec\n"
                             "// </rtc-template>\n"
                             "int userCode() { return 42; }\n"
                             "// <rtc-template block=\"gone\">\n"
                             "user kept this\n"
                             "// </rtc-template>\n";
    const QString fresh = "#include \"A.h\"\n"
                          "// <rtc-template block=\"spec\">\n"
                          "new spec 1\n"
                          "new spec 2\n"
                          "// </rtc-template>\n"
                          "// <rtc-template block=\"added\">\n"
                          "x\n"
                          "// </rtc-template>\n";
    const RegionMergeResult result = mergeTemplateRegions(existing, fresh);
    QVERIFY(result.text);
    QCOMPARE(*result.text, QStringLiteral("#include \"A.h\"\n"
                                          "// <rtc-template block=\"spec\">\n"
                                          "new spec 1\n"
                                          "new spec 2\n"
                                          "// </rtc-template>\n"
                                          "int userCode() { return 42; }\n"
                                          "// <rtc-template block=\"gone\">\n"
                                          "user kept this\n"
                                          "// </rtc-template>\n"));
    QCOMPARE(result.refreshed, QStringList{"spec"});
    QCOMPARE(result.notInExisting, QStringList{"added"});
    QCOMPARE(templateRegionNames(fresh), (QStringList{"spec", "added"}));
    // Merging the fresh file into itself changes nothing.
    QCOMPARE(*mergeTemplateRegions(fresh, fresh).text, fresh);
}

void TestCodegen::mergeReportsBrokenMarkers()
{
    const RegionMergeResult unclosed =
        mergeTemplateRegions("a\n# <rtc-template block=\"x\">\nb\n", "# <rtc-template block=\"x\">\n# </rtc-template>\n");
    QVERIFY(!unclosed.text);
    QCOMPARE(unclosed.error, QStringLiteral("line 2: block \"x\" is not closed"));
    const RegionMergeResult stray = mergeTemplateRegions("a\n</rtc-template>\n", "");
    QVERIFY(!stray.text);
    QVERIFY(stray.error.startsWith(QStringLiteral("line 2:")));
}

void TestCodegen::backupNamingAndRotation()
{
    QTemporaryDir dir;
    const QString file = dir.filePath("src/A.cpp");
    writeFile(file, "current");
    QCOMPARE(Backups::stamp(QDateTime(QDate(2024, 3, 5), QTime(7, 8, 9))), QStringLiteral("20240305070809"));
    QCOMPARE(Backups::backupPath(file, "20240305070809"), file + "20240305070809");
    for (const char *stamp : {"20240101000001", "20240101000003", "20240101000002", "20240101000004"})
        writeFile(Backups::backupPath(file, QString::fromLatin1(stamp)), stamp);
    writeFile(dir.filePath("src/A.cpp.orig"), "not a backup");
    QCOMPARE(Backups::backupsOf(file),
             (QStringList{file + "20240101000004", file + "20240101000003", file + "20240101000002",
                          file + "20240101000001"}));
    QCOMPARE(Backups::prune(file, 3), QStringList{file + "20240101000001"});
    QCOMPARE(Backups::backupsOf(file).size(), 3);
    QVERIFY(QFile::exists(dir.filePath("src/A.cpp.orig")));
    QCOMPARE(Backups::stamps(dir.path()),
             (QStringList{"20240101000004", "20240101000003", "20240101000002"}));
    QCOMPARE(Backups::stampOf(file, file + "2024"), QString());
    QCOMPARE(Backups::clear(dir.path()), 3);
    QVERIFY(Backups::backupsOf(file).isEmpty());
    QCOMPARE(readAll(file), QByteArray("current"));
}

void TestCodegen::restoreSwapsBackupSet()
{
    QTemporaryDir dir;
    writeFile(dir.filePath("a.txt"), "a new");
    writeFile(dir.filePath("src/b.txt"), "b new");
    writeFile(dir.filePath("a.txt20240101000000"), "a old");
    writeFile(dir.filePath("src/b.txt20240101000000"), "b old");
    Diagnostics diagnostics;
    QVERIFY(Backups::restore(dir.path(), "20240101000000", &diagnostics));
    QCOMPARE(readAll(dir.filePath("a.txt")), QByteArray("a old"));
    QCOMPARE(readAll(dir.filePath("src/b.txt")), QByteArray("b old"));
    QCOMPARE(readAll(dir.filePath("a.txt20240101000000")), QByteArray("a new"));
    QVERIFY(Backups::restore(dir.path(), "20240101000000", &diagnostics));
    QCOMPARE(readAll(dir.filePath("a.txt")), QByteArray("a new"));
    QVERIFY(!Backups::restore(dir.path(), "19990101000000", &diagnostics));
    QCOMPARE(diagnostics.size(), 1);
}

void TestCodegen::writerCreatesKeepsMergesOverwrites()
{
    QTemporaryDir dir;
    const QList<GeneratedFile> first = {
        {"keep.txt", "k1\n"}, {"merge.cpp", "// <rtc-template block=\"b\">\nv1\n// </rtc-template>\n"},
        {"over.txt", "o1\n"}, {"same.txt", "s\n"}, {"run.sh", "#!/bin/sh\n"}};
    Diagnostics diagnostics;
    ProjectWriter writer(dir.path());
    int clock = 0;
    writer.setClock([&clock] { return QDateTime(QDate(2024, 1, 1), QTime(0, 0, clock)); });
    const auto created = writer.write(first, &diagnostics);
    QVERIFY(created);
    QCOMPARE(created->created.size(), 5);
    QVERIFY(QFileInfo(dir.filePath("run.sh")).isExecutable());

    writeFile(dir.filePath("merge.cpp"), "user\n// <rtc-template block=\"b\">\nv1\n// </rtc-template>\nmore user\n");
    writeFile(dir.filePath("keep.txt"), "k user\n");
    const QList<GeneratedFile> second = {
        {"keep.txt", "k2\n"}, {"merge.cpp", "// <rtc-template block=\"b\">\nv2\n// </rtc-template>\n"},
        {"over.txt", "o2\n"}, {"same.txt", "s\n"}};
    QStringList asked;
    writer.setDecisionCallback([&asked](const QString &path) {
        asked << path;
        return path == "keep.txt" ? FileDecision::Keep
            : path == "merge.cpp" ? FileDecision::Merge
                                  : FileDecision::Overwrite;
    });
    for (clock = 1; clock <= 4; ++clock) {
        const auto report = writer.write(second, &diagnostics);
        QVERIFY(report);
        if (clock == 1) {
            QCOMPARE(asked, (QStringList{"keep.txt", "merge.cpp", "over.txt"}));
            QCOMPARE(report->kept, QStringList{"keep.txt"});
            QCOMPARE(report->merged, QStringList{"merge.cpp"});
            QCOMPARE(report->overwritten, QStringList{"over.txt"});
            QCOMPARE(report->unchanged, QStringList{"same.txt"});
            QCOMPARE(report->backups, (QStringList{"merge.cpp20240101000001", "over.txt20240101000001"}));
        }
        // Make the files differ again so the next run backs them up once more.
        writeFile(dir.filePath("over.txt"), QByteArray("o user ") + QByteArray::number(clock));
    }
    QCOMPARE(readAll(dir.filePath("keep.txt")), QByteArray("k user\n"));
    QCOMPARE(readAll(dir.filePath("merge.cpp")), QByteArray("user\n// <rtc-template block=\"b\">\nv2\n// </rtc-template>\nmore user\n"));
    QCOMPARE(readAll(dir.filePath("over.txt20240101000004")), QByteArray("o user 3"));
    // Only the newest three backups of over.txt survive four overwrites.
    QCOMPARE(Backups::backupsOf(dir.filePath("over.txt")).size(), 3);
    QVERIFY(!QFile::exists(dir.filePath("over.txt20240101000001")));
    QVERIFY(diagnostics.isEmpty());
    QCOMPARE(QDir(dir.path()).entryList({".rtstudio-gen-*"}, QDir::AllEntries | QDir::Hidden).size(), 0);
}

void TestCodegen::writerLeavesNothingOnFailure()
{
    QTemporaryDir dir;
    writeFile(dir.filePath("a.txt"), "user\n");
    writeFile(dir.filePath("b.cpp"), "// <rtc-template block=\"b\">\nbroken, never closed\n");
    ProjectWriter writer(dir.path());
    writer.setDecisionCallback([](const QString &) { return FileDecision::Merge; });
    Diagnostics diagnostics;
    QVERIFY(!writer.write({{"a.txt", "fresh\n"}, {"new.txt", "n\n"},
                           {"b.cpp", "// <rtc-template block=\"b\">\n// </rtc-template>\n"}},
                          &diagnostics));
    QVERIFY(diagnostics.first().message.contains(QStringLiteral("not closed")));
    QCOMPARE(readAll(dir.filePath("a.txt")), QByteArray("user\n"));
    QVERIFY(!QFile::exists(dir.filePath("new.txt")));
    QVERIFY(Backups::stamps(dir.path()).isEmpty());

    diagnostics.clear();
    QVERIFY(!writer.write({{"ok.txt", "x"}, {"../outside.txt", "x"}}, &diagnostics));
    QVERIFY(!QFile::exists(dir.filePath("ok.txt")));
    QVERIFY(!QFileInfo::exists(QDir(dir.path()).filePath("../outside.txt")));
}

void TestCodegen::writerReportsFullOrReadOnlyDisk_data()
{
    TestDisk::addSpoiledDiskRows();
}

void TestCodegen::writerReportsFullOrReadOnlyDisk()
{
    // Regenerating into a tree that cannot take the files: an error naming the file, the user's
    // file as it was, no new file.
    QFETCH(bool, readOnly);
    QTemporaryDir dir;
    TestDisk::TmpfsMount disk;
    TESTDISK_MOUNT_OR_SKIP(disk, dir.path());
    writeFile(dir.filePath("src/comp.cpp"), "// <rtc-template block=\"b\">\n// </rtc-template>\nuser code\n");
    QString why;
    QVERIFY2(disk.spoil(readOnly, &why), qPrintable(why));
    ProjectWriter writer(dir.path());
    writer.setDecisionCallback([](const QString &) { return FileDecision::Merge; });
    Diagnostics diagnostics;
    const QByteArray large(64 * 1024, 'x');
    QVERIFY(!writer.write({{"src/comp.cpp", "// <rtc-template block=\"b\">\nfresh\n// </rtc-template>\n"},
                           {"src/new.cpp", large}},
                          &diagnostics));
    QVERIFY(hasErrors(diagnostics));
    QVERIFY2(diagnostics.first().toString().contains(dir.path()), qPrintable(diagnostics.first().toString()));
    QCOMPARE(readAll(dir.filePath("src/comp.cpp")),
             QByteArray("// <rtc-template block=\"b\">\n// </rtc-template>\nuser code\n"));
    QVERIFY(!QFile::exists(dir.filePath("src/new.cpp")));
}

QTEST_GUILESS_MAIN(TestCodegen)
#include "tst_codegen.moc"
