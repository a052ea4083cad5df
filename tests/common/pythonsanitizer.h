// SPDX-License-Identifier: MIT
#pragma once

// Sanitizer options for processes that run Python: the interpreter (python3, or the one rtmanager
// embeds for Python modules) keeps its objects until the process exits by design, which
// LeakSanitizer would report by the thousand. Harmless in builds without sanitizers.

#include <QByteArray>
#include <QString>

namespace LiveTest {

/// @p asanOptions (an ASAN_OPTIONS value) with leak detection off.
inline QString withoutLeakChecks(const QString &asanOptions)
{
    return asanOptions + (asanOptions.isEmpty() ? QString() : QStringLiteral(":")) + QStringLiteral("detect_leaks=0");
}

/// Turns leak detection off for the processes this one starts from now on (not for itself).
inline void startChildrenWithoutLeakChecks()
{
    qputenv("ASAN_OPTIONS", withoutLeakChecks(QString::fromLocal8Bit(qgetenv("ASAN_OPTIONS"))).toLocal8Bit());
}

} // namespace LiveTest
