// SPDX-License-Identifier: MIT
#pragma once

#include "xmlextras.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

namespace Profile {

/// Which of the three `rtc:constraint_type` choices an `rtc:Constraint` element holds.
enum class RtcConstraintKind {
    Empty, ///< `<rtc:Constraint/>` without a choice (kept as it was)
    Hash, ///< `rtc:ConstraintHashType`: members with keys, `{k0: c0, k1: c1}`
    List, ///< `rtc:ConstraintListType`: per-element constraints of an array, `c0,c1`
    Unit ///< `rtc:ConstraintUnitType`: one condition, possibly combined with Not/And/Or
};

/// The condition inside an `rtc:ConstraintUnitType`.
enum class RtcConstraintOperator {
    None, ///< an empty ConstraintUnitType
    Not, ///< `rtc:Not` → exactly one operand
    And, ///< `rtc:And` → two or more operands
    Or, ///< `rtc:Or` → two or more operands (an enumeration `(a,b,c)`)
    IsNull, ///< `rtc:propertyIsNullType/rtc:propertyIsNull`
    EqualTo, ///< `rtc:propertyIsEqualTo`
    NotEqualTo, ///< `rtc:propertyIsNotEqualTo`
    LessThan, ///< `rtc:propertyIsLessThan`
    GreaterThan, ///< `rtc:propertyIsGreaterThan`
    LessThanOrEqualTo, ///< `rtc:propertyIsLessThanOrEqualTo`
    GreaterThanOrEqualTo, ///< `rtc:propertyIsGreaterThanOrEqualTo`
    Like, ///< `rtc:propertyIsLike`
    Between ///< `rtc:propertyIsBetween`
};

/// The element name of an operator inside ConstraintUnitType (`propertyIsEqualTo`, `And` …);
/// empty for None.
QString rtcConstraintOperatorElementName(RtcConstraintOperator op);
/// The operator for an element name; nothing for an unknown name.
std::optional<RtcConstraintOperator> rtcConstraintOperatorFromElementName(const QString &name);
/// True for the six comparisons that carry a Literal and matchCase.
bool isRtcComparison(RtcConstraintOperator op);
/// True for Not, And and Or (whose operands are nested constraints).
bool isRtcLogical(RtcConstraintOperator op);

/**
 * One `rtc:Constraint` element (schema type `rtc:constraint_type`) with everything below it.
 *
 * The tree is flattened into one struct per Constraint element: the choice (`kind`), the members
 * of a hash or list, and for a unit its key and operator with the operator's data. Operands of
 * Not/And/Or are nested Constraint elements and live in `members` as well.
 *
 * Literal values and matchCase are the file's text. Every level that is an XML element keeps
 * what the reader did not know (`extras` for rtc:Constraint, `typeExtras` for the
 * ConstraintXxxType element, `operatorExtras` for the operator element).
 */
struct RtcConstraint
{
    RtcConstraintKind kind = RtcConstraintKind::Unit;
    /// Hash/List members, or the operands of Not/And/Or.
    std::vector<RtcConstraint> members;

    // --- ConstraintUnitType
    std::optional<QString> key; ///< `rtc:key` of a unit (a member of a hash)
    RtcConstraintOperator op = RtcConstraintOperator::None;
    /// `rtc:Literal` of a comparison or Like; LowerBoundary of Between; the text of propertyIsNull.
    QString literal;
    QString upperBoundary; ///< `rtc:UpperBoundary` of Between
    /// xs:boolean ("true"/"false"; other text as read); required on comparisons.
    std::optional<QString> matchCase;
    std::optional<QString> wildCard; ///< propertyIsLike
    std::optional<QString> singleChar; ///< propertyIsLike
    std::optional<QString> escapeChar; ///< propertyIsLike

    /// Schema-required parts the source lacked (e.g. "matchCase", "Literal"); see
    /// RtcProfile::missing.
    QStringList missing;
    XmlExtras extras;
    XmlExtras typeExtras;
    XmlExtras operatorExtras;
    SourceLocation location;

    /// A unit with a comparison (matchCase "false", as RTC Builder writes it).
    static RtcConstraint comparison(RtcConstraintOperator op, const QString &literal);
    /// A unit `lower <= x <= upper` as propertyIsBetween.
    static RtcConstraint between(const QString &lower, const QString &upper);
    /// A unit combining operands with Not/And/Or.
    static RtcConstraint logical(RtcConstraintOperator op, std::vector<RtcConstraint> operands);
    /// A ConstraintListType (array) of per-element constraints.
    static RtcConstraint list(std::vector<RtcConstraint> elements);
    /// A ConstraintHashType; each member should carry its key.
    static RtcConstraint hash(std::vector<RtcConstraint> members);

    bool operator==(const RtcConstraint &other) const;
    bool operator!=(const RtcConstraint &other) const { return !(*this == other); }
};

} // namespace Profile
