// SPDX-License-Identifier: MIT
#pragma once

#include "rtcconstraint.h"

#include <QString>

#include <optional>

namespace Profile {

/// Where and why a constraint string could not be read.
struct ConstraintSyntaxError
{
    int column = 0; ///< 1-based position in the string
    QString message;

    /// `column N: message`.
    QString toString() const;
};

/// The result of parsing: a tree (nothing for a blank string) or an error.
struct ConstraintParseResult
{
    std::optional<RtcConstraint> constraint;
    std::optional<ConstraintSyntaxError> error;

    bool ok() const { return !error.has_value(); }
};

/**
 * Parses the constraint string of RTC Builder's configuration editor into a tree:
 *
 * | string                    | tree                                                    |
 * |---------------------------|---------------------------------------------------------|
 * | (blank)                   | none                                                    |
 * | `100`                     | propertyIsEqualTo 100                                   |
 * | `x>0` `x>=0` `x<5` `x<=5` `x!=3` | one comparison on the variable (any identifier)  |
 * | `0<=x<=100`, `0<x<100`    | And(lower bound, upper bound), in that order            |
 * | `100>=x>0`                | And(upper bound, lower bound), in that order            |
 * | `x<0&&x!=-5`              | And of any conditions                                   |
 * | `(a,b,c)`                 | enumeration: Or of propertyIsEqualTo (`(a)` too)        |
 * | `(x<0,x>10)`              | Or of any conditions                                    |
 * | `!(c)`                    | Not                                                     |
 * | `0..100`                  | propertyIsBetween (inclusive)                           |
 * | `like(p)` `like(p,w,s,e)` | propertyIsLike (by default `*`, `?` and `\` as w, s, e) |
 * | `null(text)`              | propertyIsNull                                          |
 * | `c1,c2,…` or `[c1,c2]`    | array: ConstraintListType of per-element constraints    |
 * | `{k0: c0, k1: c1}`        | hash: ConstraintHashType of keyed conditions            |
 *
 * Parts nest (`{a: (x,y), b: 0<=x<=1}`, `[0<x,(1,2)],{k: 3}`, `(c)` groups). Values may be
 * quoted with `"` (and `\"` inside) when they contain separators or spaces. Comparisons get
 * matchCase "false", as RTC Builder writes them. A hash member must be a single condition,
 * because the RTC Profile keys only ConstraintUnitType.
 */
ConstraintParseResult parseConstraintString(const QString &text);

/// Writes a tree in the string form parseConstraintString() reads: parsing the result gives the
/// same tree for every tree the parser can produce (matchCase other than "false", keys on
/// non-unit hash members and extras have no string form).
QString constraintToString(const RtcConstraint &constraint);

/// Writes an optional tree; nothing → empty string.
QString constraintToString(const std::optional<RtcConstraint> &constraint);

/// True when the tree is an enumeration (`(a,b,c)`: Or of equalities, or a single equality).
bool isEnumerationConstraint(const RtcConstraint &constraint);

} // namespace Profile
