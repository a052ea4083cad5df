// SPDX-License-Identifier: MIT
#include "idlparser.h"

#include <QTest>

using namespace Codegen;
using Profile::Diagnostic;

namespace {

QString dataDir()
{
    return RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/idl");
}

QString firstError(const IdlParser &parser)
{
    for (const Diagnostic &diagnostic : parser.diagnostics()) {
        if (diagnostic.severity == Diagnostic::Severity::Error)
            return diagnostic.toString();
    }
    return {};
}

QString allDiagnostics(const IdlParser &parser)
{
    QStringList lines;
    for (const Diagnostic &diagnostic : parser.diagnostics())
        lines.append(diagnostic.toString());
    return lines.join(QLatin1Char('\n'));
}

} // namespace

class TestIdlParser : public QObject
{
    Q_OBJECT

private slots:
    void readsBasicDataTypes();
    void followsIncludesOnce();
    void survivesIncludeCycles();
    void readsServiceOperations();
    void inheritsOperations();
    void resolvesTypedefChains();
    void evaluatesConstants_data();
    void evaluatesConstants();
    void printsTypes_data();
    void printsTypes();
    void recordsPositions();
    void readsUnionsEnumsAndForwardDeclarations();
    void reopensModulesAndResolvesScopes();
    void honoursConditionals();
    void reportsErrors_data();
    void reportsErrors();
};

void TestIdlParser::readsBasicDataTypes()
{
    IdlParser parser;
    QVERIFY2(parser.parseFile(dataDir() + QStringLiteral("/include/BasicDataType.idl")),
             qPrintable(allDiagnostics(parser)));
    const IdlModel &model = parser.model();
    QStringList names;
    QStringList timed;
    for (const IdlDataType &type : model.dataTypes()) {
        names.append(type.scopedName);
        if (type.timed)
            timed.append(type.scopedName);
    }
    QCOMPARE(names, (QStringList{"RTC::Time", "RTC::TimedDouble", "RTC::TimedLong", "RTC::TimedLongSeq",
                                 "RTC::TimedString"}));
    QCOMPARE(timed, (QStringList{"RTC::TimedDouble", "RTC::TimedLong", "RTC::TimedLongSeq", "RTC::TimedString"}));
    const IdlStruct time = model.structs.value(QStringLiteral("RTC::Time"));
    QCOMPARE(time.members.size(), 2);
    QCOMPARE(time.members.at(1).name, QStringLiteral("nsec"));
    QCOMPARE(time.members.at(1).type, IdlType::basic(QStringLiteral("unsigned long")));
    QCOMPARE(model.structs.value(QStringLiteral("RTC::TimedLongSeq")).members.at(1).type,
             IdlType::named(QStringLiteral("RTC::LongSeq")));
}

void TestIdlParser::followsIncludesOnce()
{
    IdlParser parser;
    parser.addSearchDirectory(dataDir() + QStringLiteral("/include"));
    QVERIFY2(parser.parseFile(dataDir() + QStringLiteral("/ExtendedDataTypes.idl")),
             qPrintable(allDiagnostics(parser)));
    // Both spellings of the include name the same file; it is read once, so nothing is redefined.
    QCOMPARE(parser.model().files.size(), 2);
    QVERIFY(parser.model().files.at(1).endsWith(QLatin1String("include/BasicDataType.idl")));
    const IdlModel &model = parser.model();
    QVERIFY(model.structs.contains(QStringLiteral("RTC::TimedLong")));
    QVERIFY(model.structs.contains(QStringLiteral("RTC::TimedPoint2D")));
    // Timed through a typedef of RTC::Time.
    QVERIFY(model.isTimed(model.structs.value(QStringLiteral("RTC::TimedPoint2D"))));
    QVERIFY(!model.isTimed(model.structs.value(QStringLiteral("RTC::Point2D"))));
    // Reading a file again later does not redefine anything either.
    QVERIFY(parser.parseFile(dataDir() + QStringLiteral("/include/BasicDataType.idl")));
    QCOMPARE(parser.model().files.size(), 2);
}

void TestIdlParser::survivesIncludeCycles()
{
    IdlParser parser;
    QVERIFY2(parser.parseFile(dataDir() + QStringLiteral("/cyclea.idl")), qPrintable(allDiagnostics(parser)));
    QVERIFY(parser.model().structs.contains(QStringLiteral("A::FromA")));
    QVERIFY(parser.model().structs.contains(QStringLiteral("B::FromB")));
    QCOMPARE(parser.model().files.size(), 2);
}

void TestIdlParser::readsServiceOperations()
{
    IdlParser parser;
    parser.addSearchDirectory(dataDir() + QStringLiteral("/include"));
    QVERIFY2(parser.parseFile(dataDir() + QStringLiteral("/MyService.idl")), qPrintable(allDiagnostics(parser)));
    const IdlInterface service = parser.model().interfaces.value(QStringLiteral("SimpleService::MyService"));
    QVERIFY(service.defined);
    QCOMPARE(service.bases, QStringList{QStringLiteral("SimpleService::Echo")});
    QCOMPARE(service.operations.size(), 5);

    const IdlOperation values = service.operations.at(2);
    QCOMPARE(values.name, QStringLiteral("get_values"));
    QCOMPARE(values.returnType.toString(), QStringLiteral("SimpleService::ValueList"));
    QCOMPARE(values.parameters.size(), 2);
    QCOMPARE(values.parameters.at(0).mode, IdlParameter::Mode::Out);
    QCOMPARE(values.parameters.at(0).name, QStringLiteral("values"));
    QCOMPARE(values.parameters.at(1).mode, IdlParameter::Mode::InOut);
    QCOMPARE(values.parameters.at(1).type.toString(), QStringLiteral("long"));
    QCOMPARE(values.raises, QStringList{QStringLiteral("SimpleService::NotFound")});

    const IdlOperation notify = service.operations.at(3);
    QVERIFY(notify.oneway);
    QVERIFY(notify.returnType.isVoid());
    QCOMPARE(notify.parameters.at(0).mode, IdlParameter::Mode::In);
    QCOMPARE(notify.parameters.at(0).type.toString(), QStringLiteral("RTC::TimedLong"));
    QCOMPARE(notify.contexts, QStringList{QStringLiteral("user")});
    QCOMPARE(IdlParameter::modeName(IdlParameter::Mode::InOut), QStringLiteral("inout"));

    QCOMPARE(service.attributes.size(), 1);
    QVERIFY(!service.attributes.at(0).readonly);
    const IdlInterface echo = parser.model().interfaces.value(QStringLiteral("SimpleService::Echo"));
    QVERIFY(echo.attributes.at(0).readonly);
    // A forward declaration followed by the definition is one defined interface.
    QVERIFY(parser.model().interfaces.value(QStringLiteral("SimpleService::Base_")).defined);
    const auto exception = parser.model().exceptions.value(QStringLiteral("SimpleService::NotFound"));
    QCOMPARE(exception.members.at(0).name, QStringLiteral("name"));
}

void TestIdlParser::inheritsOperations()
{
    IdlParser parser;
    QVERIFY(parser.parseText(QStringLiteral(R"(
module M {
  interface A { void a(); };
  interface B : A { void b(); };
  interface C : A { void c(); };
  abstract interface D { };
  local interface L { };
  interface E : B, ::M::C { void e(); readonly attribute long n; };
};)"),
                             QStringLiteral("diamond.idl")));
    const IdlModel &model = parser.model();
    QCOMPARE(model.allBases(QStringLiteral("M::E")), (QStringList{"M::B", "M::C", "M::A"}));
    QStringList names;
    for (const IdlOperation &operation : model.allOperations(QStringLiteral("M::E")))
        names.append(operation.interfaceName + QLatin1String("::") + operation.name);
    QCOMPARE(names, (QStringList{"M::A::a", "M::C::c", "M::B::b", "M::E::e"}));
    QVERIFY(model.interfaces.value(QStringLiteral("M::D")).isAbstract);
    QVERIFY(model.interfaces.value(QStringLiteral("M::L")).isLocal);
    QCOMPARE(model.allAttributes(QStringLiteral("M::E")).size(), 1);
}

void TestIdlParser::resolvesTypedefChains()
{
    IdlParser parser;
    parser.addSearchDirectory(dataDir() + QStringLiteral("/include"));
    QVERIFY(parser.parseFile(dataDir() + QStringLiteral("/MyService.idl")));
    const IdlModel &model = parser.model();
    QCOMPARE(model.typedefChain(QStringLiteral("SimpleService::History")),
             (QStringList{"SimpleService::History", "SimpleService::EchoHistory", "SimpleService::EchoList"}));
    const IdlType resolved = model.resolve(IdlType::named(QStringLiteral("SimpleService::History")));
    QCOMPARE(resolved.kind, IdlType::Kind::Sequence);
    QCOMPARE(resolved.toString(), QStringLiteral("sequence<string>"));
    QCOMPARE(model.resolve(IdlType::named(QStringLiteral("SimpleService::ValueList"))).toString(),
             QStringLiteral("sequence<float, 16>"));
    // A type that is no typedef resolves to itself.
    QCOMPARE(model.resolve(IdlType::named(QStringLiteral("RTC::Time"))).name, QStringLiteral("RTC::Time"));
}

void TestIdlParser::evaluatesConstants_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("value");
    QTest::newRow("literal") << "SimpleService::Base" << "4";
    QTest::newRow("shift of a constant") << "SimpleService::Shifted" << "16";
    QTest::newRow("arithmetic") << "SimpleService::Mixed" << "52";
    QTest::newRow("hex, and, not") << "SimpleService::Mask" << "240";
    QTest::newRow("string") << "SimpleService::Greeting" << "\"hello\"";
    QTest::newRow("float") << "SimpleService::Half" << "0.5";
}

void TestIdlParser::evaluatesConstants()
{
    QFETCH(QString, name);
    QFETCH(QString, value);
    IdlParser parser;
    parser.addSearchDirectory(dataDir() + QStringLiteral("/include"));
    QVERIFY(parser.parseFile(dataDir() + QStringLiteral("/MyService.idl")));
    QVERIFY2(parser.model().consts.contains(name), qPrintable(name));
    QCOMPARE(parser.model().consts.value(name).value, value);
}

void TestIdlParser::printsTypes_data()
{
    QTest::addColumn<QString>("declaration");
    QTest::addColumn<QString>("printed");
    QTest::newRow("bounded sequence of sequences") << "typedef sequence<sequence<long>, 3> T;"
                                                   << "sequence<sequence<long>, 3>";
    QTest::newRow("bounded strings") << "typedef wstring<8> T;" << "wstring<8>";
    QTest::newRow("arrays") << "typedef unsigned long long T[2][1+2];" << "unsigned long long[2][3]";
    QTest::newRow("fixed") << "typedef fixed<10, 2> T;" << "fixed<10, 2>";
    QTest::newRow("any") << "typedef any T;" << "any";
    QTest::newRow("object") << "typedef Object T;" << "Object";
    QTest::newRow("scoped") << "struct S { long x; }; typedef sequence<S> T;" << "sequence<M::S>";
    QTest::newRow("long double") << "typedef long double T;" << "long double";
}

void TestIdlParser::printsTypes()
{
    QFETCH(QString, declaration);
    QFETCH(QString, printed);
    IdlParser parser;
    QVERIFY2(parser.parseText(QStringLiteral("module M { %1 };").arg(declaration), QStringLiteral("t.idl")),
             qPrintable(allDiagnostics(parser)));
    QCOMPARE(parser.model().typedefs.value(QStringLiteral("M::T")).type.toString(), printed);
}

void TestIdlParser::recordsPositions()
{
    IdlParser parser;
    parser.addSearchDirectory(dataDir() + QStringLiteral("/include"));
    QVERIFY(parser.parseFile(dataDir() + QStringLiteral("/MyService.idl")));
    const IdlModel &model = parser.model();
    const auto timedLong = model.find(QStringLiteral("RTC::TimedLong"));
    QVERIFY(timedLong);
    QVERIFY(timedLong->source.file.endsWith(QLatin1String("include/BasicDataType.idl")));
    QCOMPARE(timedLong->source.line, 14);
    QCOMPARE(timedLong->source.column, 10);
    const IdlInterface service = model.interfaces.value(QStringLiteral("SimpleService::MyService"));
    QVERIFY(service.source.file.endsWith(QLatin1String("MyService.idl")));
    QCOMPARE(service.source.line, 30);
    QCOMPARE(service.source.column, 3);
    QCOMPARE(service.operations.at(1).source.line, 33);
    QCOMPARE(service.operations.at(1).source.column, 5);
    QCOMPARE(model.structs.value(QStringLiteral("RTC::Time")).members.at(1).source.line, 11);
    QCOMPARE(model.children(QStringLiteral("SimpleService")).first().name(), QStringLiteral("EchoList"));
}

void TestIdlParser::readsUnionsEnumsAndForwardDeclarations()
{
    IdlParser parser;
    QVERIFY2(parser.parseText(QStringLiteral(R"(
module M {
  enum Kind { ONE, TWO, THREE };
  const Kind Default = TWO;
  union Value switch (Kind) {
    case ONE: long number;
    case TWO:
    case THREE: string text;
    default: boolean flag;
  };
  struct Outer { struct Inner { char c; } inner; sequence<Outer> children; };
};)"),
                              QStringLiteral("u.idl")),
             qPrintable(allDiagnostics(parser)));
    const IdlModel &model = parser.model();
    QCOMPARE(model.enums.value(QStringLiteral("M::Kind")).enumerators, (QStringList{"ONE", "TWO", "THREE"}));
    QCOMPARE(model.consts.value(QStringLiteral("M::Default")).value, QStringLiteral("M::TWO"));
    const IdlUnion value = model.unions.value(QStringLiteral("M::Value"));
    QCOMPARE(value.discriminator.toString(), QStringLiteral("M::Kind"));
    QCOMPARE(value.cases.size(), 3);
    QCOMPARE(value.cases.at(1).labels, (QStringList{"M::TWO", "M::THREE"}));
    QCOMPARE(value.cases.at(1).member.name, QStringLiteral("text"));
    QVERIFY(value.cases.at(2).isDefault);
    QVERIFY(model.structs.contains(QStringLiteral("M::Outer::Inner")));
    QCOMPARE(model.structs.value(QStringLiteral("M::Outer")).members.at(0).type.toString(),
             QStringLiteral("M::Outer::Inner"));
    QCOMPARE(model.find(QStringLiteral("M::ONE"))->kind, IdlDeclaration::Kind::Enumerator);
}

void TestIdlParser::reopensModulesAndResolvesScopes()
{
    IdlParser parser;
    QVERIFY2(parser.parseText(QStringLiteral(R"(
struct Global { long g; };
module Outer {
  const long Size = 2;
  module Inner { typedef long Vector[Size * 2]; };
};
module Outer {
  module Inner { struct Use { Vector v; Global g; ::Global h; Outer::Inner::Vector w; }; };
  module Inner { const long Size2 = 5; };
  const long Twice = Inner::Size2 + Size;
};)"),
                              QStringLiteral("scopes.idl")),
             qPrintable(allDiagnostics(parser)));
    const IdlModel &model = parser.model();
    QCOMPARE(model.consts.value(QStringLiteral("Outer::Twice")).integerValue(), std::optional<qint64>(7));
    QCOMPARE(model.typedefs.value(QStringLiteral("Outer::Inner::Vector")).type.toString(),
             QStringLiteral("long[4]"));
    const IdlStruct use = model.structs.value(QStringLiteral("Outer::Inner::Use"));
    QCOMPARE(use.members.size(), 4);
    QCOMPARE(use.members.at(0).type.name, QStringLiteral("Outer::Inner::Vector"));
    QCOMPARE(use.members.at(1).type.name, QStringLiteral("Global"));
    QCOMPARE(use.members.at(2).type.name, QStringLiteral("Global"));
    QCOMPARE(use.members.at(3).type.name, QStringLiteral("Outer::Inner::Vector"));
    // The module is one node of the tree however often it is reopened.
    QCOMPARE(model.children(QStringLiteral("Outer")).size(), 3);
}

void TestIdlParser::honoursConditionals()
{
    IdlParser parser;
    parser.define(QStringLiteral("FROM_OUTSIDE"));
    QVERIFY2(parser.parseText(QStringLiteral(R"(#define FEATURE
#ifdef FEATURE
struct Yes1 { long a; };
#else
struct No1 { long a; };
#endif
#ifndef FEATURE
struct No2 { long a; };
#elif defined(FROM_OUTSIDE) && !defined(OTHER)
struct Yes2 { long a; };
#endif
#if 0
this is not IDL at all
#endif
#undef FEATURE
#if defined FEATURE || 1
struct Yes3 { long a; };
#endif
#pragma ID Yes3 "IDL:Yes3:1.0"
)"),
                              QStringLiteral("cond.idl")),
             qPrintable(allDiagnostics(parser)));
    QCOMPARE(parser.model().structs.keys(), (QStringList{"Yes1", "Yes2", "Yes3"}));
}

void TestIdlParser::reportsErrors_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("where");
    QTest::addColumn<QString>("message");
    QTest::newRow("syntax") << "syntax.idl" << ":4:5:" << "expected ';', found 'long'";
    QTest::newRow("truncated") << "truncated.idl" << ":3:24:"
                               << "expected '}' to close interface 'M::I', found end of file";
    QTest::newRow("missing include") << "missinginclude.idl" << ":2:1:"
                                     << "cannot find include file 'NoSuchFile.idl'";
    QTest::newRow("unknown type") << "unknowntype.idl" << ":4:5:" << "unknown type 'Unknown'";
    QTest::newRow("redefinition") << "redefinition.idl" << ":4:10:" << "redefinition of 'M::S' (first declared at";
    QTest::newRow("valuetype") << "valuetype.idl" << ":2:15:" << "valuetypes are not supported";
    QTest::newRow("unterminated string") << "unterminatedstring.idl" << ":2:20:" << "unterminated string literal";
    QTest::newRow("unterminated comment") << "unterminatedcomment.idl" << ":2:3:" << "unterminated comment";
    QTest::newRow("parameter mode") << "parametermode.idl" << ":3:13:" << "expected 'in', 'out' or 'inout'";
    QTest::newRow("division by zero") << "divisionbyzero.idl" << ":2:20:" << "division by zero";
    QTest::newRow("unterminated #if") << "unterminatedif.idl" << ":1:1:" << "without #endif";
}

void TestIdlParser::reportsErrors()
{
    QFETCH(QString, file);
    QFETCH(QString, where);
    QFETCH(QString, message);
    IdlParser parser;
    const QString path = dataDir() + QStringLiteral("/broken/") + file;
    QVERIFY(!parser.parseFile(path));
    const QString error = firstError(parser);
    QVERIFY2(error.startsWith(path + where + QStringLiteral(" error: ")), qPrintable(error));
    QVERIFY2(error.contains(message), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestIdlParser)
#include "tst_idlparser.moc"
