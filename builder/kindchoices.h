// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

namespace Builder::KindChoices {

/**
 * The two multiple choices of the Basic page, each stored in one text attribute.
 *
 * Component kind (`rtc:componentKind`): RTC Builder's check boxes DataFlow, FSM and MultiMode
 * make the text by concatenating the chosen parts and appending "Component", e.g.
 * `DataFlowFiniteStateMachineComponent`; reading looks for each part in the text.
 *
 * Languages (`rtc:Language @kind`): the chosen languages separated by ", " (Generate and
 * `rtctl gen` accept `,` or `;`); entries nobody knows are kept where they are.
 */

/// DataFlow, FiniteStateMachine, MultiMode: the parts in the order they are written.
const QStringList &componentKindParts();
/// True when `kind` contains `part`.
bool hasComponentKind(const QString &kind, const QString &part);
/// `kind` with `part` switched on or off, the parts in their written order.
QString withComponentKind(const QString &kind, const QString &part, bool on);
/// Empty when at least one known part is chosen, else the reason.
QString componentKindProblem(const QString &kind);

/// C++, Python, Java: the languages Generate knows.
const QStringList &languages();
/// The entries of a language kind text (trimmed, empty ones dropped).
QStringList languageEntries(const QString &kind);
/// True when `kind` lists `language` (case does not matter).
bool hasLanguage(const QString &kind, const QString &language);
/// `kind` with `language` added (at the end) or removed.
QString withLanguage(const QString &kind, const QString &language, bool on);
/// Empty when at least one language is chosen and all are known, else the reason.
QString languageProblem(const QString &kind);

} // namespace Builder::KindChoices
