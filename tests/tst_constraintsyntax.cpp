// SPDX-License-Identifier: MIT
// The constraint string syntax of RTC Builder's configuration editor: string → tree → string.
#include "constraintsyntax.h"

#include <QTest>

using namespace Profile;

namespace {

using Op = RtcConstraintOperator;

RtcConstraint cmp(Op op, const QString &literal)
{
    return RtcConstraint::comparison(op, literal);
}

RtcConstraint eq(const QString &literal)
{
    return cmp(Op::EqualTo, literal);
}

RtcConstraint keyed(const QString &key, RtcConstraint c)
{
    c.key = key;
    return c;
}

RtcConstraint like(const QString &pattern, const QString &wild, const QString &single,
                   const QString &escape)
{
    RtcConstraint c;
    c.op = Op::Like;
    c.literal = pattern;
    c.wildCard = wild;
    c.singleChar = single;
    c.escapeChar = escape;
    return c;
}

RtcConstraint isNull(const QString &text)
{
    RtcConstraint c;
    c.op = Op::IsNull;
    c.literal = text;
    return c;
}

} // namespace

Q_DECLARE_METATYPE(Profile::RtcConstraint)

class TestConstraintSyntax : public QObject
{
    Q_OBJECT

private slots:
    void parsesToTree_data();
    void parsesToTree();
    void blankIsNoConstraint();
    void reportsErrorsWithColumn_data();
    void reportsErrorsWithColumn();
    void writesTreesParsedBack_data();
    void writesTreesParsedBack();
    void recognisesEnumerations();
};

void TestConstraintSyntax::parsesToTree_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<RtcConstraint>("tree");
    QTest::addColumn<QString>("written"); // the canonical form constraintToString() gives

    QTest::newRow("equal") << "100" << eq("100") << "100";
    QTest::newRow("equal with ==") << "x==100" << eq("100") << "100";
    QTest::newRow("string value") << "fast" << eq("fast") << "fast";
    QTest::newRow("quoted value") << R"("a, b")" << eq("a, b") << R"("a, b")";
    QTest::newRow("escaped quote") << R"("say \"hi\"")" << eq(R"(say "hi")") << R"("say \"hi\"")";
    QTest::newRow("spaces inside") << "  hello world  " << eq("hello world") << "hello world";
    QTest::newRow("greater") << "x>0" << cmp(Op::GreaterThan, "0") << "x>0";
    QTest::newRow("greater or equal")
        << "x >= -1.5e3" << cmp(Op::GreaterThanOrEqualTo, "-1.5e3") << "x>=-1.5e3";
    QTest::newRow("less") << "x<3" << cmp(Op::LessThan, "3") << "x<3";
    QTest::newRow("less or equal") << "x<=5" << cmp(Op::LessThanOrEqualTo, "5") << "x<=5";
    QTest::newRow("not equal") << "val!=abc" << cmp(Op::NotEqualTo, "abc") << "x!=abc";
    QTest::newRow("variable on the right") << "5<x" << cmp(Op::GreaterThan, "5") << "x>5";
    QTest::newRow("range") << "0<=x<=100"
                           << RtcConstraint::logical(Op::And,
                                                     {cmp(Op::GreaterThanOrEqualTo, "0"),
                                                      cmp(Op::LessThanOrEqualTo, "100")})
                           << "0<=x<=100";
    QTest::newRow("half-open range")
        << "100 <= value < 150"
        << RtcConstraint::logical(Op::And,
                                  {cmp(Op::GreaterThanOrEqualTo, "100"), cmp(Op::LessThan, "150")})
        << "100<=x<150";
    QTest::newRow("descending range")
        << "10.0>x>0.0"
        << RtcConstraint::logical(Op::And, {cmp(Op::LessThan, "10.0"), cmp(Op::GreaterThan, "0.0")})
        << "10.0>x>0.0";
    QTest::newRow("and") << "x!=3&&x<10"
                         << RtcConstraint::logical(
                                Op::And, {cmp(Op::NotEqualTo, "3"), cmp(Op::LessThan, "10")})
                         << "x!=3&&x<10";
    QTest::newRow("nested and") << "(0<x<5)&&x!=3"
                                << RtcConstraint::logical(
                                       Op::And,
                                       {RtcConstraint::logical(
                                            Op::And,
                                            {cmp(Op::GreaterThan, "0"), cmp(Op::LessThan, "5")}),
                                        cmp(Op::NotEqualTo, "3")})
                                << "(0<x<5)&&x!=3";
    QTest::newRow("enumeration") << "(a,b,c)"
                                 << RtcConstraint::logical(Op::Or, {eq("a"), eq("b"), eq("c")})
                                 << "(a,b,c)";
    QTest::newRow("enumeration of one")
        << "(only)" << RtcConstraint::logical(Op::Or, {eq("only")}) << "(only)";
    QTest::newRow("or of conditions")
        << "(x<0, x>10)"
        << RtcConstraint::logical(Op::Or, {cmp(Op::LessThan, "0"), cmp(Op::GreaterThan, "10")})
        << "(x<0,x>10)";
    QTest::newRow("group") << "(x<0)" << cmp(Op::LessThan, "0") << "x<0";
    QTest::newRow("not") << "!(x<3)" << RtcConstraint::logical(Op::Not, {cmp(Op::LessThan, "3")})
                         << "!(x<3)";
    QTest::newRow("between") << "1..2" << RtcConstraint::between("1", "2") << "1..2";
    QTest::newRow("between negative")
        << "-1.5 .. 2" << RtcConstraint::between("-1.5", "2") << "-1.5..2";
    QTest::newRow("like") << "like(ab*)" << like("ab*", "*", "?", "\\") << "like(ab*)";
    QTest::newRow("like with characters")
        << "like(a%, %, _, !)" << like("a%", "%", "_", "!") << "like(a%,%,_,\"!\")";
    QTest::newRow("null") << "null(p)" << isNull("p") << "null(p)";
    QTest::newRow("null without text") << "null()" << isNull(QString()) << "null()";
    QTest::newRow("array") << "1,2,3" << RtcConstraint::list({eq("1"), eq("2"), eq("3")})
                           << "1,2,3";
    QTest::newRow("array of ranges and enums")
        << "0<x<1, (a,b)"
        << RtcConstraint::list({RtcConstraint::logical(
                                    Op::And, {cmp(Op::GreaterThan, "0"), cmp(Op::LessThan, "1")}),
                                RtcConstraint::logical(Op::Or, {eq("a"), eq("b")})})
        << "0<x<1,(a,b)";
    QTest::newRow("bracketed array")
        << "[1, 2]" << RtcConstraint::list({eq("1"), eq("2")}) << "1,2";
    QTest::newRow("array of one") << "[1]" << RtcConstraint::list({eq("1")}) << "[1]";
    QTest::newRow("empty array") << "[]" << RtcConstraint::list({}) << "[]";
    QTest::newRow("hash") << "{k0: 1, k1: (a,b)}"
                          << RtcConstraint::hash(
                                 {keyed("k0", eq("1")),
                                  keyed("k1", RtcConstraint::logical(Op::Or, {eq("a"), eq("b")}))})
                          << "{k0: 1, k1: (a,b)}";
    QTest::newRow("hash with range and quoted key")
        << R"({"a b": 0<=x<=1})"
        << RtcConstraint::hash({keyed("a b",
                                      RtcConstraint::logical(Op::And,
                                                             {cmp(Op::GreaterThanOrEqualTo, "0"),
                                                              cmp(Op::LessThanOrEqualTo, "1")}))})
        << "{a b: 0<=x<=1}";
    QTest::newRow("empty hash") << "{}" << RtcConstraint::hash({}) << "{}";
    QTest::newRow("array of array and hash")
        << "[0<x,(1,2)],{k: 3}"
        << RtcConstraint::list(
               {RtcConstraint::list({cmp(Op::GreaterThan, "0"),
                                     RtcConstraint::logical(Op::Or, {eq("1"), eq("2")})}),
                RtcConstraint::hash({keyed("k", eq("3"))})})
        << "[x>0,(1,2)],{k: 3}";
}

void TestConstraintSyntax::parsesToTree()
{
    QFETCH(QString, text);
    QFETCH(RtcConstraint, tree);
    QFETCH(QString, written);
    const ConstraintParseResult result = parseConstraintString(text);
    QVERIFY2(result.ok(), qPrintable(result.error ? result.error->toString() : QString()));
    QVERIFY(result.constraint);
    QVERIFY(*result.constraint == tree);
    QCOMPARE(constraintToString(*result.constraint), written);
    const ConstraintParseResult again = parseConstraintString(written);
    QVERIFY(again.ok());
    QVERIFY(again.constraint == result.constraint);
}

void TestConstraintSyntax::blankIsNoConstraint()
{
    for (const QString &blank : {QString(), QStringLiteral("   "), QStringLiteral("\t")}) {
        const ConstraintParseResult result = parseConstraintString(blank);
        QVERIFY(result.ok());
        QVERIFY(!result.constraint);
    }
    QCOMPARE(constraintToString(std::optional<RtcConstraint>()), QString());
}

void TestConstraintSyntax::reportsErrorsWithColumn_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("message");
    QTest::newRow("mixed range") << "0<=x>5" << 5 << "same way";
    QTest::newRow("range without variable") << "0<5<9" << 3 << "variable";
    QTest::newRow("list keyed in hash") << "{a: [1,2]}" << 5 << "single condition";
    QTest::newRow("unclosed enumeration") << "(1,2" << 5 << "')'";
    QTest::newRow("missing value") << "x<" << 3 << "value";
    QTest::newRow("doubled operator") << "x<<3" << 3 << "value";
    QTest::newRow("empty array element") << "1,,2" << 3 << "value";
    QTest::newRow("unclosed quote") << R"("abc)" << 1 << "not closed";
    QTest::newRow("hash without colon") << "{a 1}" << 5 << "':'";
    QTest::newRow("unclosed array") << "[1,2" << 5 << "']'";
    QTest::newRow("trailing text") << "1 2)" << 4 << "')'";
    QTest::newRow("not without parenthesis") << "!x" << 2 << "'('";
}

void TestConstraintSyntax::reportsErrorsWithColumn()
{
    QFETCH(QString, text);
    QFETCH(int, column);
    QFETCH(QString, message);
    const ConstraintParseResult result = parseConstraintString(text);
    QVERIFY(!result.ok());
    QVERIFY(!result.constraint);
    QCOMPARE(result.error->column, column);
    QVERIFY2(result.error->message.contains(message), qPrintable(result.error->message));
    QVERIFY(result.error->toString().contains(QString::number(column)));
}

void TestConstraintSyntax::writesTreesParsedBack_data()
{
    QTest::addColumn<RtcConstraint>("tree");
    QTest::newRow("value with separators") << eq("a,b(c)");
    QTest::newRow("value with operator text") << eq("x&&y");
    QTest::newRow("value like a call") << eq("like(x)");
    QTest::newRow("empty value") << eq(QString());
    QTest::newRow("leading space") << eq(QStringLiteral(" padded"));
    QTest::newRow("starts with !") << eq(QStringLiteral("!bang"));
    QTest::newRow("dots") << cmp(Op::LessThan, QStringLiteral("1..2"));
    QTest::newRow("colon in hash key") << RtcConstraint::hash({keyed("a:b", eq("1"))});
    QTest::newRow("not of and") << RtcConstraint::logical(
        Op::Not, {RtcConstraint::logical(Op::And, {cmp(Op::GreaterThan, "0"), eq("3")})});
}

void TestConstraintSyntax::writesTreesParsedBack()
{
    QFETCH(RtcConstraint, tree);
    const QString text = constraintToString(tree);
    const ConstraintParseResult result = parseConstraintString(text);
    QVERIFY2(result.ok(),
             qPrintable(text + QLatin1String(": ")
                        + (result.error ? result.error->toString() : QString())));
    QVERIFY2(result.constraint && *result.constraint == tree, qPrintable(text));
}

void TestConstraintSyntax::recognisesEnumerations()
{
    QVERIFY(isEnumerationConstraint(*parseConstraintString("(a,b)").constraint));
    QVERIFY(isEnumerationConstraint(*parseConstraintString("a").constraint));
    QVERIFY(!isEnumerationConstraint(*parseConstraintString("(x<0,x>1)").constraint));
    QVERIFY(!isEnumerationConstraint(*parseConstraintString("0<x<1").constraint));
    QVERIFY(!isEnumerationConstraint(*parseConstraintString("1,2").constraint));
}

QTEST_GUILESS_MAIN(TestConstraintSyntax)
#include "tst_constraintsyntax.moc"
