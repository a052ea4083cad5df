// SPDX-License-Identifier: MIT
// The IDL parser on input it was not written for: truncated files, random garbage, absurd nesting,
// and the real-world IDL that Debian's omniORB packages install.
#include "idlparser.h"

#include <QDir>
#include <QFile>
#include <QRandomGenerator>
#include <QTest>

using namespace Codegen;
using Profile::Diagnostic;

namespace {

QString dataDir()
{
    return RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/idl");
}

QString readText(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll());
}

/// Every diagnostic names the in-memory file and a line inside it.
bool diagnosticsArePlaced(const IdlParser &parser, const QString &fileName, int lines, QString *problem)
{
    for (const Diagnostic &diagnostic : parser.diagnostics()) {
        if (diagnostic.file != fileName || diagnostic.line < 1 || diagnostic.line > lines
            || diagnostic.column < 1) {
            *problem = diagnostic.toString();
            return false;
        }
    }
    return true;
}

const char *const OmniOrbIdl = "/usr/share/idl/omniORB";

} // namespace

class TestIdlRobustness : public QObject
{
    Q_OBJECT

private slots:
    void survivesEveryTruncation_data();
    void survivesEveryTruncation();
    void survivesRandomGarbage();
    void limitsNesting_data();
    void limitsNesting();
    void parsesOmniOrbIdl_data();
    void parsesOmniOrbIdl();
    void rejectsOmniOrbValuetypesClearly();
};

void TestIdlRobustness::survivesEveryTruncation_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("basic data types") << "include/BasicDataType.idl";
    QTest::newRow("service") << "MyService.idl";
}

void TestIdlRobustness::survivesEveryTruncation()
{
    QFETCH(QString, file);
    const QString text = readText(dataDir() + QLatin1Char('/') + file);
    QVERIFY(!text.isEmpty());
    int failures = 0;
    for (int length = 0; length < text.size(); ++length) {
        IdlParser parser;
        parser.addSearchDirectory(dataDir() + QStringLiteral("/include"));
        const QString prefix = text.left(length);
        const bool ok = parser.parseText(prefix, QStringLiteral("cut.idl"));
        if (!ok)
            ++failures;
        QString problem;
        QVERIFY2(diagnosticsArePlaced(parser, QStringLiteral("cut.idl"), int(prefix.count(QLatin1Char('\n'))) + 1,
                                      &problem)
                     || problem.contains(QLatin1String("BasicDataType.idl")),
                 qPrintable(QStringLiteral("length %1: %2").arg(length).arg(problem)));
    }
    // Most cuts land inside a declaration; each of those must be an error, not a silent success.
    QVERIFY2(failures > text.size() / 2, qPrintable(QString::number(failures)));
}

void TestIdlRobustness::survivesRandomGarbage()
{
    static const QStringList pieces{
        "module", "interface", "struct", "union", "switch", "case", "default", "enum", "typedef", "const",
        "sequence", "<", ">", ">>", "<<", "{", "}", "(", ")", "[", "]", ";", ":", "::", ",", "=", "long",
        "unsigned", "string", "in", "out", "inout", "oneway", "void", "raises", "exception", "attribute",
        "readonly", "A", "B", "x", "0", "42", "0x1F", "1.5", "'c'", "\"s\"", "/*", "*/", "//", "\n#ifdef X\n",
        "\n#endif\n", "\n#include \"nothing.idl\"\n", "\n#define X\n", "-", "~", "/", "%", "\"", "'", "@", "\\"};
    QRandomGenerator random(20240611); // fixed seed: a failure can be reproduced
    for (int round = 0; round < 2000; ++round) {
        QString text;
        const int count = int(random.bounded(1, 60));
        for (int i = 0; i < count; ++i)
            text += pieces.at(int(random.bounded(int(pieces.size())))) + QLatin1Char(' ');
        IdlParser parser;
        parser.parseText(text, QStringLiteral("garbage.idl"));
        QString problem;
        QVERIFY2(diagnosticsArePlaced(parser, QStringLiteral("garbage.idl"), int(text.count(QLatin1Char('\n'))) + 1,
                                      &problem),
                 qPrintable(QStringLiteral("%1\n%2").arg(problem, text)));
    }
}

void TestIdlRobustness::limitsNesting_data()
{
    QTest::addColumn<QString>("open");
    QTest::addColumn<QString>("close");
    QTest::addColumn<QString>("message");
    QTest::newRow("modules") << "module m { " << "}; " << "nested too deeply";
    QTest::newRow("parentheses") << "(" << ")" << "nested too deeply";
    QTest::newRow("unary minus") << "-" << "" << "nested too deeply";
    QTest::newRow("sequences") << "sequence<" << ">" << "nested too deeply";
    QTest::newRow("structs") << "struct S { " << " s; }" << "nested too deeply";
}

void TestIdlRobustness::limitsNesting()
{
    QFETCH(QString, open);
    QFETCH(QString, close);
    QFETCH(QString, message);
    const int depth = 100000;
    QString text;
    if (open.startsWith(QLatin1String("module")))
        text = open.repeated(depth) + close.repeated(depth);
    else if (open.startsWith(QLatin1String("struct")))
        text = QStringLiteral("typedef ") + open.repeated(depth) + QStringLiteral("long x;") + close.repeated(depth)
            + QStringLiteral(" T;");
    else if (open.startsWith(QLatin1String("sequence")))
        text = QStringLiteral("typedef ") + open.repeated(depth) + QStringLiteral("long") + close.repeated(depth)
            + QStringLiteral(" T;");
    else
        text = QStringLiteral("const long c = ") + open.repeated(depth) + QStringLiteral("1") + close.repeated(depth)
            + QStringLiteral(";");
    IdlParser parser;
    QVERIFY(!parser.parseText(text, QStringLiteral("deep.idl")));
    QVERIFY(!parser.diagnostics().isEmpty());
    QVERIFY2(parser.diagnostics().first().message.contains(message),
             qPrintable(parser.diagnostics().first().toString()));
}

void TestIdlRobustness::parsesOmniOrbIdl_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("declaration");
    QTest::addColumn<int>("minimumOperations"); ///< of the declaration with its bases; 0 for no interface
    QTest::newRow("orb.idl (value boxes)") << "orb.idl" << "CORBA::StringValue" << 0;
    QTest::newRow("Naming.idl") << "Naming.idl" << "CosNaming::NamingContextExt" << 14;
    QTest::newRow("poa.idl") << "poa.idl" << "PortableServer::ServantActivator" << 2;
    QTest::newRow("ir.idl") << "ir.idl" << "CORBA::Repository" << 5;
    QTest::newRow("bootstrap.idl") << "bootstrap.idl" << "CORBA_InitialReferences" << 2;
    QTest::newRow("CosEventChannelAdmin") << "COS/CosEventChannelAdmin.idl" << "CosEventChannelAdmin::EventChannel"
                                          << 3;
    QTest::newRow("CosNotifyChannelAdmin") << "COS/CosNotifyChannelAdmin.idl"
                                           << "CosNotifyChannelAdmin::EventChannel" << 5;
    QTest::newRow("CosTrading") << "COS/CosTrading.idl" << "CosTrading::Lookup" << 1;
    QTest::newRow("CosTime") << "COS/CosTime.idl" << "CosTime::TimeService" << 3;
    QTest::newRow("CosPropertyService") << "COS/CosPropertyService.idl" << "CosPropertyService::PropertySet" << 5;
}

void TestIdlRobustness::parsesOmniOrbIdl()
{
    QFETCH(QString, file);
    QFETCH(QString, declaration);
    QFETCH(int, minimumOperations);
    const QString root = QString::fromLatin1(OmniOrbIdl);
    if (!QFileInfo::exists(root + QLatin1Char('/') + file))
        QSKIP("omniORB's IDL files are not installed (Debian package omniorb-idl)");
    IdlParser parser;
    parser.addSearchDirectory(root);
    parser.addSearchDirectory(root + QStringLiteral("/COS"));
    QStringList lines;
    const bool ok = parser.parseFile(root + QLatin1Char('/') + file);
    for (const Diagnostic &diagnostic : parser.diagnostics())
        lines.append(diagnostic.toString());
    QVERIFY2(ok, qPrintable(lines.join(QLatin1Char('\n'))));
    QVERIFY2(parser.model().find(declaration), qPrintable(declaration));
    QVERIFY2(parser.model().allOperations(declaration).size() >= minimumOperations,
             qPrintable(QString::number(parser.model().allOperations(declaration).size())));
}

void TestIdlRobustness::rejectsOmniOrbValuetypesClearly()
{
    const QString path = QString::fromLatin1(OmniOrbIdl) + QStringLiteral("/pollable.idl");
    if (!QFileInfo::exists(path))
        QSKIP("omniORB's IDL files are not installed (Debian package omniorb-idl)");
    IdlParser parser;
    QVERIFY(!parser.parseFile(path));
    QVERIFY2(parser.diagnostics().first().message.contains(QLatin1String("valuetypes are not supported")),
             qPrintable(parser.diagnostics().first().toString()));
    QVERIFY(parser.diagnostics().first().line > 0);
}

QTEST_GUILESS_MAIN(TestIdlRobustness)
#include "tst_idlrobustness.moc"
