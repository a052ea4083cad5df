// SPDX-License-Identifier: MIT
#include "constraintsyntax.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace Profile {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("Profile::ConstraintSyntax", text);
}

using Op = RtcConstraintOperator;

/// Thrown inside the parser only; parseConstraintString() turns it into a result.
struct SyntaxError
{
    int index;
    QString message;
};

/// A value as written: quoted values are never taken for the variable name.
struct Token
{
    QString text;
    bool quoted = false;
    int index = 0;

    bool isIdentifier() const
    {
        static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][A-Za-z0-9_]*$"));
        return !quoted && identifier.match(text).hasMatch();
    }
};

bool isLowerBound(Op op)
{
    return op == Op::GreaterThan || op == Op::GreaterThanOrEqualTo;
}

bool isUpperBound(Op op)
{
    return op == Op::LessThan || op == Op::LessThanOrEqualTo;
}

/// `x OP value` with OP seen from the variable; `value OP x` is the mirror image.
Op mirrored(Op op)
{
    switch (op) {
    case Op::LessThan:
        return Op::GreaterThan;
    case Op::LessThanOrEqualTo:
        return Op::GreaterThanOrEqualTo;
    case Op::GreaterThan:
        return Op::LessThan;
    case Op::GreaterThanOrEqualTo:
        return Op::LessThanOrEqualTo;
    default:
        return op;
    }
}

/**
 * Recursive descent over the editor syntax; see parseConstraintString() for the grammar.
 * Positions are indices into the text; errors carry the index of the offending character.
 */
class Parser
{
public:
    explicit Parser(const QString &text)
        : m_text(text)
    { }

    RtcConstraint parseTop()
    {
        RtcConstraint result = parseItemList(QChar());
        skipSpace();
        if (!atEnd())
            fail(tr("unexpected '%1' after the constraint").arg(m_text.at(m_pos)));
        return result;
    }

private:
    [[noreturn]] void fail(const QString &message, int index = -1) const
    {
        throw SyntaxError {index < 0 ? int(m_pos) : index, message};
    }

    bool atEnd() const { return m_pos >= m_text.size(); }
    QChar peek() const { return atEnd() ? QChar() : m_text.at(m_pos); }

    void skipSpace()
    {
        while (!atEnd() && m_text.at(m_pos).isSpace())
            ++m_pos;
    }

    bool lookingAt(const char *literal)
    {
        skipSpace();
        return QStringView(m_text).mid(m_pos).startsWith(QLatin1String(literal));
    }

    bool accept(const char *literal)
    {
        if (!lookingAt(literal))
            return false;
        m_pos += qsizetype(qstrlen(literal));
        return true;
    }

    void expect(const char *literal)
    {
        if (!accept(literal))
            fail(atEnd() ? tr("expected '%1' but the text ends").arg(QLatin1String(literal))
                         : tr("expected '%1'").arg(QLatin1String(literal)));
    }

    /// Items separated by commas; a list when there are several (or when `close` is given).
    RtcConstraint parseItemList(QChar close)
    {
        std::vector<RtcConstraint> items;
        skipSpace();
        if (!close.isNull() && peek() == close)
            return RtcConstraint::list({});
        items.push_back(parseItem());
        while (accept(","))
            items.push_back(parseItem());
        if (items.size() == 1 && close.isNull())
            return items.front();
        return RtcConstraint::list(std::move(items));
    }

    /// Every nesting passes parseItem() or parseCondition(); a string nested deeper than any real
    /// constraint (from a file, say) is an error rather than a stack overflow.
    class Nesting
    {
    public:
        explicit Nesting(Parser *parser)
            : m_parser(parser)
        {
            if (++m_parser->m_depth > 200)
                m_parser->fail(tr("the constraint is nested too deeply"));
        }
        ~Nesting() { --m_parser->m_depth; }

    private:
        Parser *m_parser;
    };

    RtcConstraint parseItem()
    {
        const Nesting nesting(this);
        if (accept("[")) {
            RtcConstraint list = parseItemList(QLatin1Char(']'));
            expect("]");
            return list;
        }
        if (accept("{"))
            return parseHash();
        return parseCondition();
    }

    RtcConstraint parseHash()
    {
        std::vector<RtcConstraint> members;
        skipSpace();
        if (!accept("}")) {
            do {
                members.push_back(parseHashMember());
            } while (accept(","));
            expect("}");
        }
        return RtcConstraint::hash(std::move(members));
    }

    RtcConstraint parseHashMember()
    {
        skipSpace();
        const Token key = parseValue(true);
        expect(":");
        skipSpace();
        const int valueIndex = int(m_pos);
        RtcConstraint member = parseItem();
        if (member.kind != RtcConstraintKind::Unit)
            fail(tr("a hash member must be a single condition (the RTC Profile can only key "
                    "those)"),
                 valueIndex);
        if (!key.text.isEmpty())
            member.key = key.text;
        return member;
    }

    /// Conditions joined by `&&`.
    RtcConstraint parseCondition()
    {
        const Nesting nesting(this);
        std::vector<RtcConstraint> operands;
        operands.push_back(parseUnary());
        while (accept("&&"))
            operands.push_back(parseUnary());
        if (operands.size() == 1)
            return operands.front();
        return RtcConstraint::logical(Op::And, std::move(operands));
    }

    RtcConstraint parseUnary()
    {
        if (accept("!")) {
            expect("(");
            RtcConstraint operand = parseCondition();
            expect(")");
            return RtcConstraint::logical(Op::Not, {operand});
        }
        if (accept("("))
            return parseParenthesised();
        if (lookingAtCall("like"))
            return parseLike();
        if (lookingAtCall("null"))
            return parseNull();
        return parseComparison();
    }

    /// `(a,b,c)` is an enumeration (Or); a single non-equality in parentheses is a group.
    RtcConstraint parseParenthesised()
    {
        std::vector<RtcConstraint> operands;
        operands.push_back(parseCondition());
        while (accept(","))
            operands.push_back(parseCondition());
        expect(")");
        if (operands.size() == 1 && operands.front().op != Op::EqualTo)
            return operands.front();
        return RtcConstraint::logical(Op::Or, std::move(operands));
    }

    /// `name(`, with white space allowed before the parenthesis. Read in place: a copy (or a
    /// regular expression's check) of the rest of the text for every operand made long `&&` chains
    /// take quadratic time.
    bool lookingAtCall(const char *name)
    {
        skipSpace();
        qsizetype end = m_pos;
        while (end < m_text.size() && m_text.at(end) >= QLatin1Char('a') && m_text.at(end) <= QLatin1Char('z'))
            ++end;
        const QStringView word = QStringView(m_text).mid(m_pos, end - m_pos);
        while (end < m_text.size() && m_text.at(end).isSpace())
            ++end;
        return end < m_text.size() && m_text.at(end) == QLatin1Char('(') && word == QLatin1String(name);
    }

    RtcConstraint parseLike()
    {
        accept("like");
        expect("(");
        RtcConstraint c = RtcConstraint::comparison(Op::Like, parseValue(false).text);
        c.matchCase.reset();
        c.wildCard = QStringLiteral("*");
        c.singleChar = QStringLiteral("?");
        c.escapeChar = QStringLiteral("\\");
        if (accept(",")) {
            c.wildCard = parseValue(false).text;
            expect(",");
            c.singleChar = parseValue(false).text;
            expect(",");
            c.escapeChar = parseValue(false).text;
        }
        expect(")");
        return c;
    }

    RtcConstraint parseNull()
    {
        accept("null");
        expect("(");
        RtcConstraint c;
        c.op = Op::IsNull;
        skipSpace();
        if (peek() != QLatin1Char(')'))
            c.literal = parseValue(false).text;
        expect(")");
        return c;
    }

    std::optional<Op> parseOperator()
    {
        static const std::pair<const char *, Op> operators[] = {{"<=", Op::LessThanOrEqualTo},
                                                                {">=", Op::GreaterThanOrEqualTo},
                                                                {"==", Op::EqualTo},
                                                                {"!=", Op::NotEqualTo},
                                                                {"<", Op::LessThan},
                                                                {">", Op::GreaterThan},
                                                                {"=", Op::EqualTo}};
        for (const auto &entry : operators) {
            if (accept(entry.first))
                return entry.second;
        }
        return std::nullopt;
    }

    /// `v`, `v..w`, `x OP v`, `v OP x`, `lo < x < hi`, `hi > x > lo`.
    RtcConstraint parseComparison()
    {
        const Token first = parseValue(false);
        if (accept(".."))
            return RtcConstraint::between(first.text, parseValue(false).text);
        const int opIndex = int(m_pos);
        const auto op = parseOperator();
        if (!op)
            return RtcConstraint::comparison(Op::EqualTo, first.text);
        const Token second = parseValue(false);
        skipSpace();
        const int secondOpIndex = int(m_pos);
        if (const auto op2 = parseOperator())
            return parseRange(first, *op, second, *op2, opIndex, secondOpIndex);
        // The identifier is the variable; with two or none, the left side is.
        if (!first.isIdentifier() && second.isIdentifier())
            return RtcConstraint::comparison(mirrored(*op), first.text);
        return RtcConstraint::comparison(*op, second.text);
    }

    RtcConstraint parseRange(const Token &low, Op op1, const Token &variable, Op op2, int opIndex,
                             int secondOpIndex)
    {
        const Token high = parseValue(false);
        if (!variable.isIdentifier())
            fail(tr("expected the variable name between the two comparisons"), variable.index);
        // `lo < x` reads as x > lo: seen from the variable, the first operator is mirrored.
        const Op first = mirrored(op1);
        const bool ascending = isLowerBound(first) && isUpperBound(op2);
        const bool descending = isUpperBound(first) && isLowerBound(op2);
        if (!ascending && !descending) {
            fail(tr("a range needs two comparisons pointing the same way (lo<=x<hi or hi>x>=lo)"),
                 isLowerBound(first) || isUpperBound(first) ? secondOpIndex : opIndex);
        }
        return RtcConstraint::logical(Op::And,
                                      {RtcConstraint::comparison(first, low.text),
                                       RtcConstraint::comparison(op2, high.text)});
    }

    /// A quoted or bare value; `key` allows what a hash key may contain (not ':').
    Token parseValue(bool key)
    {
        skipSpace();
        Token token;
        token.index = int(m_pos);
        if (peek() == QLatin1Char('"')) {
            token.quoted = true;
            token.text = parseQuoted();
            return token;
        }
        while (!atEnd() && !endsBareValue(key))
            token.text.append(m_text.at(m_pos++));
        token.text = token.text.trimmed();
        if (token.text.isEmpty())
            fail(atEnd() ? tr("expected a value but the text ends")
                         : tr("expected a value before '%1'").arg(peek()));
        return token;
    }

    bool endsBareValue(bool key) const
    {
        static const QString special = QStringLiteral(",()[]{}<>=\"");
        const QChar c = m_text.at(m_pos);
        if (special.contains(c) || (key && c == QLatin1Char(':')))
            return true;
        const QStringView rest = QStringView(m_text).mid(m_pos);
        return rest.startsWith(QLatin1String("&&")) || rest.startsWith(QLatin1String("!="))
            || rest.startsWith(QLatin1String(".."));
    }

    QString parseQuoted()
    {
        const int start = int(m_pos);
        ++m_pos;
        QString text;
        while (!atEnd()) {
            const QChar c = m_text.at(m_pos++);
            if (c == QLatin1Char('"'))
                return text;
            if (c == QLatin1Char('\\') && !atEnd())
                text.append(m_text.at(m_pos++));
            else
                text.append(c);
        }
        fail(tr("the quoted value is not closed"), start);
    }

    const QString &m_text;
    qsizetype m_pos = 0;
    int m_depth = 0;
};

// ---- writing

QString quoted(const QString &value, bool key)
{
    static const QRegularExpression plain(
        QStringLiteral(R"(^[^,()\[\]{}<>="!\s][^,()\[\]{}<>="]*$)"));
    const bool needsQuotes = value.isEmpty() || value.trimmed() != value
        || !plain.match(value).hasMatch() || value.contains(QLatin1String("&&"))
        || value.contains(QLatin1String("!=")) || value.contains(QLatin1String(".."))
        // `a&` before `&&`, `1.` before `..` would make a longer operator of the two.
        || value.endsWith(QLatin1Char('&')) || value.endsWith(QLatin1Char('.'))
        || (key && value.contains(QLatin1Char(':')));
    if (!needsQuotes)
        return value;
    QString escaped = value;
    escaped.replace(QLatin1Char('\\'), QLatin1String("\\\\"));
    escaped.replace(QLatin1Char('"'), QLatin1String("\\\""));
    return QLatin1Char('"') + escaped + QLatin1Char('"');
}

QString operatorText(Op op)
{
    switch (op) {
    case Op::EqualTo:
        return QStringLiteral("==");
    case Op::NotEqualTo:
        return QStringLiteral("!=");
    case Op::LessThan:
        return QStringLiteral("<");
    case Op::LessThanOrEqualTo:
        return QStringLiteral("<=");
    case Op::GreaterThan:
        return QStringLiteral(">");
    case Op::GreaterThanOrEqualTo:
        return QStringLiteral(">=");
    default:
        return {};
    }
}

QString itemText(const RtcConstraint &c);
QString conditionText(const RtcConstraint &c);

bool isPlainComparison(const RtcConstraint &c)
{
    return c.kind == RtcConstraintKind::Unit && isRtcComparison(c.op) && c.members.empty();
}

/// `lo<x<hi` or `hi>x>lo` for an And of two bounds; empty when it is not one.
QString rangeText(const RtcConstraint &c)
{
    if (c.members.size() != 2 || !isPlainComparison(c.members[0])
        || !isPlainComparison(c.members[1]))
        return {};
    const RtcConstraint &a = c.members[0];
    const RtcConstraint &b = c.members[1];
    const bool ascending = isLowerBound(a.op) && isUpperBound(b.op);
    const bool descending = isUpperBound(a.op) && isLowerBound(b.op);
    if (!ascending && !descending)
        return {};
    return quoted(a.literal, false) + operatorText(mirrored(a.op)) + QStringLiteral("x")
        + operatorText(b.op) + quoted(b.literal, false);
}

QString andOperandText(const RtcConstraint &operand)
{
    const QString text = conditionText(operand);
    return operand.op == Op::And ? QLatin1Char('(') + text + QLatin1Char(')') : text;
}

QString logicalText(const RtcConstraint &c)
{
    QStringList parts;
    switch (c.op) {
    case Op::Not:
        return QStringLiteral("!(")
            + (c.members.empty() ? QString() : conditionText(c.members.front())) + QLatin1Char(')');
    case Op::And: {
        const QString range = rangeText(c);
        if (!range.isEmpty())
            return range;
        for (const RtcConstraint &operand : c.members)
            parts.append(andOperandText(operand));
        return parts.join(QLatin1String("&&"));
    }
    default:
        for (const RtcConstraint &operand : c.members)
            parts.append(conditionText(operand));
        return QLatin1Char('(') + parts.join(QLatin1Char(',')) + QLatin1Char(')');
    }
}

QString likeText(const RtcConstraint &c)
{
    QString text = QStringLiteral("like(") + quoted(c.literal, false);
    const bool defaults = c.wildCard == QLatin1String("*") && c.singleChar == QLatin1String("?")
        && c.escapeChar == QLatin1String("\\");
    if (!defaults) {
        text += QLatin1Char(',') + quoted(c.wildCard.value_or(QString()), false) + QLatin1Char(',')
            + quoted(c.singleChar.value_or(QString()), false) + QLatin1Char(',')
            + quoted(c.escapeChar.value_or(QString()), false);
    }
    return text + QLatin1Char(')');
}

QString conditionText(const RtcConstraint &c)
{
    if (c.kind != RtcConstraintKind::Unit)
        return itemText(c);
    switch (c.op) {
    case Op::None:
        return {};
    case Op::Not:
    case Op::And:
    case Op::Or:
        return logicalText(c);
    case Op::IsNull:
        return QStringLiteral("null(")
            + (c.literal.isEmpty() ? QString() : quoted(c.literal, false)) + QLatin1Char(')');
    case Op::Like:
        return likeText(c);
    case Op::Between:
        return quoted(c.literal, false) + QLatin1String("..") + quoted(c.upperBoundary, false);
    case Op::EqualTo:
        return quoted(c.literal, false);
    default:
        return QStringLiteral("x") + operatorText(c.op) + quoted(c.literal, false);
    }
}

QString membersText(const std::vector<RtcConstraint> &members, bool withKeys)
{
    QStringList parts;
    for (const RtcConstraint &member : members) {
        const QString text = itemText(member);
        parts.append(withKeys
                         ? quoted(member.key.value_or(QString()), true) + QLatin1String(": ") + text
                         : text);
    }
    return parts.join(withKeys ? QLatin1String(", ") : QLatin1String(","));
}

QString itemText(const RtcConstraint &c)
{
    switch (c.kind) {
    case RtcConstraintKind::Empty:
        return {};
    case RtcConstraintKind::Hash:
        return QLatin1Char('{') + membersText(c.members, true) + QLatin1Char('}');
    case RtcConstraintKind::List:
        return QLatin1Char('[') + membersText(c.members, false) + QLatin1Char(']');
    case RtcConstraintKind::Unit:
        return conditionText(c);
    }
    return {};
}

} // namespace

QString ConstraintSyntaxError::toString() const
{
    return tr("column %1: %2").arg(column).arg(message);
}

ConstraintParseResult parseConstraintString(const QString &text)
{
    ConstraintParseResult result;
    if (text.trimmed().isEmpty())
        return result;
    try {
        result.constraint = Parser(text).parseTop();
    } catch (const SyntaxError &error) {
        result.error = ConstraintSyntaxError {error.index + 1, error.message};
    }
    return result;
}

QString constraintToString(const RtcConstraint &constraint)
{
    // A top-level array is written without brackets, as the editor shows it.
    if (constraint.kind == RtcConstraintKind::List && constraint.members.size() > 1)
        return membersText(constraint.members, false);
    return itemText(constraint);
}

QString constraintToString(const std::optional<RtcConstraint> &constraint)
{
    return constraint ? constraintToString(*constraint) : QString();
}

bool isEnumerationConstraint(const RtcConstraint &constraint)
{
    if (constraint.kind != RtcConstraintKind::Unit)
        return false;
    if (constraint.op == Op::EqualTo)
        return true;
    if (constraint.op != Op::Or || constraint.members.empty())
        return false;
    for (const RtcConstraint &member : constraint.members) {
        if (member.kind != RtcConstraintKind::Unit || member.op != Op::EqualTo)
            return false;
    }
    return true;
}

} // namespace Profile
