// SPDX-License-Identifier: MIT
// Codegen::PythonStubWriter, the Python back end of rtctl idl: which files it writes for which IDL
// modules, omniORBpy's names and type ids, and that declarations of included files (OpenRTM's) are
// left to the modules that have them; IDL including IDL of its own folder (its stub imports theirs)
// and `#pragma prefix` in type ids, both ways between ids and scoped names. tst_pythonservice imports
// what it writes into python3.
#include "idlparser.h"
#include "pythonstubwriter.h"

#include <QFile>
#include <QTest>

using namespace Codegen;

namespace {

QString dataFile(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/pythonidl/")) + name;
}

QString readText(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

} // namespace

class TestPythonStubWriter : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void writesOmniOrbPyLayout();
    void usesOmniOrbPyNamesAndIds_data();
    void usesOmniOrbPyNamesAndIds();
    void leavesIncludedDeclarationsOut();
    void carriesItsIdlText();
    void importsStubsOfItsFolderIncludes();
    void prefixesTypeIds_data();
    void prefixesTypeIds();
    void findsScopedNamesOfPrefixedIds();

private:
    IdlParser m_parser;
    QMap<QString, QString> m_files;
    /// Canvas.idl (which includes Shapes.idl of its folder) and Shapes.idl, compiled together.
    IdlParser m_canvasParser;
    QMap<QString, QString> m_canvasFiles;
};

void TestPythonStubWriter::initTestCase()
{
    m_parser.addSearchDirectory(RTSTUDIO_IDL_DIR);
    const QStringList paths {dataFile(QStringLiteral("Calc.idl")),
                             dataFile(QStringLiteral("Scopes.idl"))};
    QVERIFY2(m_parser.parseFiles(paths), qPrintable(m_parser.diagnostics().value(0).toString()));
    m_files = PythonStubWriter(m_parser.model())
                  .write(paths, {readText(paths.at(0)), readText(paths.at(1))});

    m_canvasParser.addSearchDirectory(RTSTUDIO_IDL_DIR);
    const QStringList canvas{dataFile(QStringLiteral("Canvas.idl")), dataFile(QStringLiteral("Shapes.idl"))};
    QVERIFY2(m_canvasParser.parseFiles(canvas), qPrintable(m_canvasParser.diagnostics().value(0).toString()));
    m_canvasFiles = PythonStubWriter(m_canvasParser.model()).write(canvas, {readText(canvas.at(0)), readText(canvas.at(1))});
}

void TestPythonStubWriter::writesOmniOrbPyLayout()
{
    const QStringList expected {"Calc_idl.py",
                                "Outer/__init__.py",
                                "Outer__POA/__init__.py",
                                "PyCalc/__init__.py",
                                "PyCalc__POA/__init__.py",
                                "Scopes_idl.py",
                                "_GlobalIDL/__init__.py",
                                "_GlobalIDL__POA/__init__.py"};
    QCOMPARE(m_files.keys(), expected);
    QVERIFY(m_files.value("PyCalc/__init__.py")
                .contains(QLatin1String("omniORB.updateModule(\"PyCalc\")\n")));
    QVERIFY(m_files.value("PyCalc/__init__.py").contains(QLatin1String("import Calc_idl\n")));
    QVERIFY(m_files.value("_GlobalIDL/__init__.py").contains(QLatin1String("import Scopes_idl\n")));
    QVERIFY(!m_files.value("_GlobalIDL/__init__.py").contains(QLatin1String("import Calc_idl")));
}

void TestPythonStubWriter::usesOmniOrbPyNamesAndIds_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("text");
    QTest::newRow("struct")
        << "Calc_idl.py"
        << "class Term(omniORB.StructBase):\n    _NP_RepositoryId = \"IDL:PyCalc/Term:1.0\"";
    QTest::newRow("constructor") << "Calc_idl.py"
                                 << "    def __init__(self, value, label):\n";
    QTest::newRow("exception") << "Calc_idl.py"
                               << "class TooMany(CORBA.UserException):";
    QTest::newRow("enumerator")
        << "Calc_idl.py"
        << "_0_PyCalc.MULTIPLY = omniORB.EnumItem(\"MULTIPLY\", 1, \"IDL:PyCalc/Mode:1.0\")";
    QTest::newRow("constant") << "Calc_idl.py"
                              << "_0_PyCalc.STRICT = True\n";
    QTest::newRow("object reference") << "Calc_idl.py"
                                      << "class _objref_Calculator(CORBA.Object):";
    QTest::newRow("attribute")
        << "Calc_idl.py"
        << "    def _set_name(self, *args):\n        return self._invoke(\"_set_name\", args)";
    QTest::newRow("servant") << "Calc_idl.py"
                             << "_0_PyCalc__POA.Calculator = Calculator\n";
    QTest::newRow("derived servant") << "Calc_idl.py"
                                     << "class Scientific(_0_PyCalc__POA.Calculator):";
    QTest::newRow("nested POA module")
        << "Scopes_idl.py"
        << "omniORB.openModule(\"Outer__POA.Inner\", \"Scopes.idl\")";
    QTest::newRow("base in another module")
        << "Scopes_idl.py"
        << "class _objref_Holder(_0__GlobalIDL._objref_GlobalThing):";
    QTest::newRow("type in an interface") << "Scopes_idl.py"
                                          << "_0_Outer_Inner.Holder.Item = Item\n";
    QTest::newRow("enumerator value") << "Scopes_idl.py"
                                      << "_0_Outer.FAVOURITE = _0_Outer.GREEN\n";
}

void TestPythonStubWriter::usesOmniOrbPyNamesAndIds()
{
    QFETCH(QString, file);
    QFETCH(QString, text);
    QVERIFY2(m_files.value(file).contains(text), qPrintable(m_files.value(file)));
}

void TestPythonStubWriter::leavesIncludedDeclarationsOut()
{
    const QString stub = m_files.value("Calc_idl.py");
    QVERIFY(stub.contains(QLatin1String("\nimport RTC\n")));
    QVERIFY(!stub.contains(QLatin1String("class Time(")));
    QVERIFY(!stub.contains(QLatin1String("class GPoint("))); // Scopes.idl's, in the same parse
    QVERIFY(stub.contains(QLatin1String("_exported_modules = (\"PyCalc\",)")));
}

void TestPythonStubWriter::carriesItsIdlText()
{
    // One line, escaped: the runtime parses it to marshal calls by their signatures.
    const QString stub = m_files.value("Scopes_idl.py");
    QVERIFY(stub.contains(
        QLatin1String("omniORB.loadIdl(\"Scopes.idl\", \"// SPDX-License-Identifier: MIT\\n")));
    QVERIFY(stub.contains(QLatin1String("struct GPoint { long x; };\\n")));
}

void TestPythonStubWriter::importsStubsOfItsFolderIncludes()
{
    const QString stub = m_canvasFiles.value("Canvas_idl.py");
    // Shapes_idl is imported before the runtime reads Canvas.idl, whose #include it answers.
    const qsizetype imported = stub.indexOf(QLatin1String("\nimport Shapes_idl\n"));
    QVERIFY2(imported > 0, qPrintable(stub));
    QVERIFY(imported < stub.indexOf(QLatin1String("omniORB.loadIdl(\"Canvas.idl\"")));
    QVERIFY(!stub.contains(QLatin1String("class Circle(")));
    // The included file's modules, as omniidl opens them, for the base interface in another module.
    QVERIFY2(stub.contains(QLatin1String("_0_PyShapes = omniORB.openModule(\"PyShapes\")\n")), qPrintable(stub));
    QVERIFY(stub.contains(QLatin1String("class _objref_Painter(_0_PyShapes._objref_Drawer):")));
    QVERIFY(m_canvasFiles.value("PyShapes/__init__.py").contains(QLatin1String("import Shapes_idl\n")));
    QVERIFY(!m_canvasFiles.value("PyShapes/__init__.py").contains(QLatin1String("import Canvas_idl")));
    // Includes from elsewhere (OpenRTM's IDL) stay with the modules that have them.
    QVERIFY(!m_files.value("Calc_idl.py").contains(QLatin1String("import BasicDataType_idl")));
    QVERIFY(!m_canvasFiles.value("Shapes_idl.py").contains(QLatin1String("import Canvas_idl")));
}

void TestPythonStubWriter::prefixesTypeIds_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("text");
    QTest::newRow("struct under a prefix") << "Shapes_idl.py" << "_NP_RepositoryId = \"IDL:example.org/PyShapes/Circle:1.0\"";
    QTest::newRow("exception under a prefix")
        << "Shapes_idl.py" << "_NP_RepositoryId = \"IDL:example.org/PyShapes/Degenerate:1.0\"";
    QTest::newRow("interface under a prefix") << "Shapes_idl.py" << "\"IDL:example.org/PyShapes/Drawer:1.0\"";
    // A prefix holds in its own file only.
    QTest::newRow("including file without one") << "Canvas_idl.py" << "_NP_RepositoryId = \"IDL:PyCanvas/Scene:1.0\"";
}

void TestPythonStubWriter::prefixesTypeIds()
{
    QFETCH(QString, file);
    QFETCH(QString, text);
    QVERIFY2(m_canvasFiles.value(file).contains(text), qPrintable(m_canvasFiles.value(file)));
}

void TestPythonStubWriter::findsScopedNamesOfPrefixedIds()
{
    const IdlModel &model = m_canvasParser.model();
    QCOMPARE(model.repositoryId("PyShapes::Drawer"), QStringLiteral("IDL:example.org/PyShapes/Drawer:1.0"));
    QCOMPARE(model.scopedNameOf("IDL:example.org/PyShapes/Drawer:1.0"), QStringLiteral("PyShapes::Drawer"));
    QCOMPARE(model.scopedNameOf("IDL:PyCanvas/Painter:1.0"), QStringLiteral("PyCanvas::Painter"));
    // The id without its prefix is no id of this model.
    QCOMPARE(model.scopedNameOf("IDL:PyShapes/Drawer:1.0"), QString());
    QCOMPARE(model.scopedNameOf("IDL:example.org/PyShapes/Nothing:1.0"), QString());
    QCOMPARE(model.repositoryId("RTC::Time"), QStringLiteral("IDL:RTC/Time:1.0"));
}

QTEST_GUILESS_MAIN(TestPythonStubWriter)
#include "tst_pythonstubwriter.moc"
