// SPDX-License-Identifier: MIT
#include "rtcconstraint.h"

#include <array>
#include <tuple>

namespace Profile {

namespace {

struct OperatorName
{
    RtcConstraintOperator op;
    const char *name;
};

// The schema's element names; note the odd `propertyIsNullType` wrapper.
constexpr std::array<OperatorName, 12> operatorNames {{
    {RtcConstraintOperator::Not, "Not"},
    {RtcConstraintOperator::And, "And"},
    {RtcConstraintOperator::Or, "Or"},
    {RtcConstraintOperator::IsNull, "propertyIsNullType"},
    {RtcConstraintOperator::EqualTo, "propertyIsEqualTo"},
    {RtcConstraintOperator::NotEqualTo, "propertyIsNotEqualTo"},
    {RtcConstraintOperator::LessThan, "propertyIsLessThan"},
    {RtcConstraintOperator::GreaterThan, "propertyIsGreaterThan"},
    {RtcConstraintOperator::LessThanOrEqualTo, "propertyIsLessThanOrEqualTo"},
    {RtcConstraintOperator::GreaterThanOrEqualTo, "propertyIsGreaterThanOrEqualTo"},
    {RtcConstraintOperator::Like, "propertyIsLike"},
    {RtcConstraintOperator::Between, "propertyIsBetween"},
}};

} // namespace

QString rtcConstraintOperatorElementName(RtcConstraintOperator op)
{
    for (const OperatorName &entry : operatorNames) {
        if (entry.op == op)
            return QLatin1String(entry.name);
    }
    return {};
}

std::optional<RtcConstraintOperator> rtcConstraintOperatorFromElementName(const QString &name)
{
    for (const OperatorName &entry : operatorNames) {
        if (name == QLatin1String(entry.name))
            return entry.op;
    }
    return std::nullopt;
}

bool isRtcComparison(RtcConstraintOperator op)
{
    switch (op) {
    case RtcConstraintOperator::EqualTo:
    case RtcConstraintOperator::NotEqualTo:
    case RtcConstraintOperator::LessThan:
    case RtcConstraintOperator::GreaterThan:
    case RtcConstraintOperator::LessThanOrEqualTo:
    case RtcConstraintOperator::GreaterThanOrEqualTo:
        return true;
    default:
        return false;
    }
}

bool isRtcLogical(RtcConstraintOperator op)
{
    return op == RtcConstraintOperator::Not || op == RtcConstraintOperator::And
        || op == RtcConstraintOperator::Or;
}

RtcConstraint RtcConstraint::comparison(RtcConstraintOperator op, const QString &literal)
{
    RtcConstraint c;
    c.kind = RtcConstraintKind::Unit;
    c.op = op;
    c.literal = literal;
    c.matchCase = QStringLiteral("false");
    return c;
}

RtcConstraint RtcConstraint::between(const QString &lower, const QString &upper)
{
    RtcConstraint c;
    c.kind = RtcConstraintKind::Unit;
    c.op = RtcConstraintOperator::Between;
    c.literal = lower;
    c.upperBoundary = upper;
    return c;
}

RtcConstraint RtcConstraint::logical(RtcConstraintOperator op, std::vector<RtcConstraint> operands)
{
    RtcConstraint c;
    c.kind = RtcConstraintKind::Unit;
    c.op = op;
    c.members = std::move(operands);
    return c;
}

RtcConstraint RtcConstraint::list(std::vector<RtcConstraint> elements)
{
    RtcConstraint c;
    c.kind = RtcConstraintKind::List;
    c.members = std::move(elements);
    return c;
}

RtcConstraint RtcConstraint::hash(std::vector<RtcConstraint> members)
{
    RtcConstraint c;
    c.kind = RtcConstraintKind::Hash;
    c.members = std::move(members);
    return c;
}

bool RtcConstraint::operator==(const RtcConstraint &other) const
{
    return std::tie(kind, members, key, op, literal, upperBoundary, matchCase, wildCard, singleChar,
                    escapeChar, missing, extras, typeExtras, operatorExtras)
        == std::tie(other.kind, other.members, other.key, other.op, other.literal,
                    other.upperBoundary, other.matchCase, other.wildCard, other.singleChar,
                    other.escapeChar, other.missing, other.extras, other.typeExtras,
                    other.operatorExtras);
}

} // namespace Profile
