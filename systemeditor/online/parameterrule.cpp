// SPDX-License-Identifier: MIT
#include "parameterrule.h"

#include "constraintsyntax.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>

namespace SystemEditor {

using Profile::RtcConstraint;
using Profile::RtcConstraintKind;
using Op = Profile::RtcConstraintOperator;

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SystemEditor::ParameterRule)
};

std::optional<double> number(const QString &text)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

// Numbers compare as numbers, anything else as text (OpenRTP compares the same way).
int compare(const QString &value, const QString &literal)
{
    const auto a = number(value);
    const auto b = number(literal);
    if (a && b)
        return *a < *b ? -1 : (*a > *b ? 1 : 0);
    return value.compare(literal);
}

bool likeMatches(const RtcConstraint &c, const QString &value)
{
    const QString wild = c.wildCard.value_or(QStringLiteral("*"));
    const QString single = c.singleChar.value_or(QStringLiteral("?"));
    QString pattern;
    for (const QChar ch : c.literal) {
        if (QString(ch) == wild)
            pattern += QStringLiteral(".*");
        else if (QString(ch) == single)
            pattern += QLatin1Char('.');
        else
            pattern += QRegularExpression::escape(QString(ch));
    }
    return QRegularExpression(QRegularExpression::anchoredPattern(pattern)).match(value).hasMatch();
}

bool satisfies(const RtcConstraint &c, const QString &value);

bool unitSatisfies(const RtcConstraint &c, const QString &value)
{
    switch (c.op) {
    case Op::None:
        return true;
    case Op::Not:
        return c.members.empty() || !satisfies(c.members.front(), value);
    case Op::And:
        return std::all_of(c.members.begin(), c.members.end(),
                           [&](const RtcConstraint &m) { return satisfies(m, value); });
    case Op::Or:
        return std::any_of(c.members.begin(), c.members.end(),
                           [&](const RtcConstraint &m) { return satisfies(m, value); });
    case Op::IsNull:
        return value.isEmpty();
    case Op::EqualTo:
        return compare(value, c.literal) == 0;
    case Op::NotEqualTo:
        return compare(value, c.literal) != 0;
    case Op::LessThan:
        return compare(value, c.literal) < 0;
    case Op::GreaterThan:
        return compare(value, c.literal) > 0;
    case Op::LessThanOrEqualTo:
        return compare(value, c.literal) <= 0;
    case Op::GreaterThanOrEqualTo:
        return compare(value, c.literal) >= 0;
    case Op::Like:
        return likeMatches(c, value);
    case Op::Between:
        return compare(value, c.literal) >= 0 && compare(value, c.upperBoundary) <= 0;
    }
    return true;
}

bool satisfies(const RtcConstraint &c, const QString &value)
{
    switch (c.kind) {
    case RtcConstraintKind::Empty:
    case RtcConstraintKind::Hash: // keyed values have no string form to split reliably
        return true;
    case RtcConstraintKind::List: {
        const QStringList parts = value.split(QLatin1Char(','));
        for (size_t i = 0; i < c.members.size() && i < size_t(parts.size()); ++i) {
            if (!satisfies(c.members[i], parts.at(int(i)).trimmed()))
                return false;
        }
        return true;
    }
    case RtcConstraintKind::Unit:
        return unitSatisfies(c, value);
    }
    return true;
}

// Bounds of `lo<=x<=hi`, `x>=lo`, `lo..hi` and And of those.
void collectBounds(const RtcConstraint &c, ParameterRule &rule)
{
    if (c.kind != RtcConstraintKind::Unit)
        return;
    const auto literal = number(c.literal);
    switch (c.op) {
    case Op::And:
        for (const RtcConstraint &m : c.members)
            collectBounds(m, rule);
        break;
    case Op::GreaterThan:
    case Op::GreaterThanOrEqualTo:
        rule.minimum = literal;
        break;
    case Op::LessThan:
    case Op::LessThanOrEqualTo:
        rule.maximum = literal;
        break;
    case Op::Between:
        rule.minimum = literal;
        rule.maximum = number(c.upperBoundary);
        break;
    default:
        break;
    }
}

QStringList enumeration(const RtcConstraint &c)
{
    if (c.kind != RtcConstraintKind::Unit || !Profile::isEnumerationConstraint(c))
        return {};
    if (c.op == Op::EqualTo)
        return {c.literal};
    QStringList values;
    for (const RtcConstraint &m : c.members)
        values.append(m.literal);
    return values;
}

ParameterRule::Widget widgetOf(const QString &name, const ParameterRule &rule)
{
    using W = ParameterRule::Widget;
    const bool bounded = rule.minimum && rule.maximum;
    if (name == QLatin1String("slider") && bounded)
        return W::Slider;
    if (name == QLatin1String("spin") && bounded)
        return W::Spin;
    const bool hasChoices = !rule.choices.isEmpty();
    if (name == QLatin1String("radio") && hasChoices)
        return W::Radio;
    if (name == QLatin1String("checkbox") && hasChoices)
        return W::CheckBox;
    if (name == QLatin1String("ordered_list") && hasChoices)
        return W::OrderedList;
    return W::Text;
}

} // namespace

ParameterRule ParameterRule::from(const QString &widgetSpec, const QString &constraintText)
{
    ParameterRule rule;
    rule.constraintText = constraintText.trimmed();
    if (!rule.constraintText.isEmpty()) {
        const auto parsed = Profile::parseConstraintString(rule.constraintText);
        if (parsed.ok()) {
            rule.constraint = parsed.constraint;
        } else {
            rule.constraintError = parsed.error->toString();
        }
    }
    if (rule.constraint) {
        collectBounds(*rule.constraint, rule);
        rule.choices = enumeration(*rule.constraint);
    }
    // `slider.0.1`: the step follows the first dot.
    const QString spec = widgetSpec.trimmed();
    const int dot = spec.indexOf(QLatin1Char('.'));
    const QString name = dot < 0 ? spec : spec.left(dot);
    if (dot >= 0) {
        const auto step = number(spec.mid(dot + 1));
        if (step && *step > 0)
            rule.step = *step;
    }
    rule.widget = widgetOf(name, rule);
    return rule;
}

QString ParameterRule::check(const QString &value) const
{
    if (!constraint)
        return {};
    if (widget == Widget::CheckBox || widget == Widget::OrderedList) {
        // Several choices, comma-separated, each one of the enumeration.
        for (const QString &part : value.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            if (!choices.contains(part.trimmed()))
                return Text::tr("'%1' is not one of %2")
                    .arg(part.trimmed(), choices.join(QStringLiteral(", ")));
        }
        return {};
    }
    const bool numeric = (minimum || maximum) && constraint->kind == RtcConstraintKind::Unit;
    if (numeric && !number(value))
        return Text::tr("'%1' is not a number").arg(value);
    if (!satisfies(*constraint, value))
        return Text::tr("'%1' does not satisfy %2").arg(value, constraintText);
    return {};
}

bool ParameterRule::isIntegral() const
{
    auto whole = [](double v) { return std::floor(v) == v; };
    return whole(step) && (!minimum || whole(*minimum)) && (!maximum || whole(*maximum));
}

} // namespace SystemEditor
