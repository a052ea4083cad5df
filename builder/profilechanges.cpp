// SPDX-License-Identifier: MIT
#include "profilechanges.h"

#include "componentmodel.h"

#include <QCoreApplication>

namespace Builder {

namespace {

using namespace Profile;

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Builder::ProfileChanges)
};

QString shown(const std::optional<QString> &value)
{
    return value ? QStringLiteral("'%1'").arg(*value) : Text::tr("(none)");
}

void basicChanges(const RtcProfile &before, const RtcProfile &after, QStringList &lines)
{
    ComponentModel a(before);
    ComponentModel b(after);
    for (int f = int(BasicField::Name); f <= int(BasicField::ExecutionRate); ++f) {
        const auto field = BasicField(f);
        if (a.basicField(field) != b.basicField(field)) {
            lines << Text::tr("Basic: %1 %2 → %3")
                         .arg(ComponentModel::fieldLabel(field), shown(a.basicField(field)),
                              shown(b.basicField(field)));
        }
    }
    if (before.basicInfo.doc != after.basicInfo.doc)
        lines << Text::tr("Documentation changed");
}

void actionChanges(const RtcProfile &before, const RtcProfile &after, QStringList &lines)
{
    for (RtcAction action : rtcAllActions()) {
        const auto &a = before.actions[action];
        const auto &b = after.actions[action];
        if (a == b)
            continue;
        const bool onA = a && a->isImplemented();
        const bool onB = b && b->isImplemented();
        if (onA != onB)
            lines << Text::tr("%1: %2 → %3")
                         .arg(rtcActionKey(action), onA ? Text::tr("on") : Text::tr("off"),
                              onB ? Text::tr("on") : Text::tr("off"));
        else
            lines << Text::tr("%1 changed").arg(rtcActionKey(action));
    }
}

/// Added, removed and changed elements of a list, matched by name.
template<typename T>
void listChanges(const QList<T> &before, const QList<T> &after, const QString &what,
                 QStringList &lines)
{
    const auto find = [](const QList<T> &list, const QString &name) -> const T * {
        for (const T &item : list) {
            if (item.name == name)
                return &item;
        }
        return nullptr;
    };
    for (const T &item : before) {
        if (!find(after, item.name))
            lines << Text::tr("%1 '%2' removed").arg(what, item.name);
    }
    for (const T &item : after) {
        const T *old = find(before, item.name);
        if (!old)
            lines << Text::tr("%1 '%2' added").arg(what, item.name);
        else if (*old != item)
            lines << Text::tr("%1 '%2' changed").arg(what, item.name);
    }
    QStringList namesBefore;
    QStringList namesAfter;
    for (const T &item : before)
        namesBefore << item.name;
    for (const T &item : after)
        namesAfter << item.name;
    if (namesBefore != namesAfter && namesBefore.size() == namesAfter.size()
        && std::is_permutation(namesBefore.cbegin(), namesBefore.cend(), namesAfter.cbegin()))
        lines << Text::tr("Order of %1s changed").arg(what.toLower());
}

} // namespace

QStringList describeChanges(const RtcProfile &before, const RtcProfile &after)
{
    if (before == after)
        return {};
    QStringList lines;
    if (before.id != after.id)
        lines << Text::tr("Component id '%1' → '%2'").arg(before.id, after.id);
    basicChanges(before, after, lines);
    actionChanges(before, after, lines);
    listChanges(before.dataPorts, after.dataPorts, Text::tr("Data port"), lines);
    listChanges(before.servicePorts, after.servicePorts, Text::tr("Service port"), lines);
    listChanges(before.configurations, after.configurations, Text::tr("Configuration parameter"), lines);
    if (before.language != after.language)
        lines << Text::tr("Language and environment changed");
    if (lines.isEmpty())
        lines << Text::tr("Other content changed (dates, properties, unknown elements)");
    return lines;
}

} // namespace Builder
