// SPDX-License-Identifier: MIT
#pragma once

// The environment of the python3 processes the Python tests start.

#include "pythonsanitizer.h"

#include <QProcessEnvironment>

namespace LiveTest {

/**
 * python3 finds the packages in @p pythonPath (colon-separated); output is unbuffered, so the test
 * sees it as printed. In the sanitizer build the extension module is instrumented but python3 is
 * not: the runtimes in @p sanitizerPreload are preloaded, and leaks are not checked (the
 * interpreter keeps its objects until exit by design).
 */
inline QProcessEnvironment pythonEnvironment(const QString &pythonPath,
                                             const QString &sanitizerPreload)
{
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("PYTHONPATH"), pythonPath);
    environment.insert(QStringLiteral("PYTHONUNBUFFERED"), QStringLiteral("1"));
    if (!sanitizerPreload.isEmpty()) {
        environment.insert(QStringLiteral("LD_PRELOAD"), sanitizerPreload);
        environment.insert(QStringLiteral("ASAN_OPTIONS"),
                           withoutLeakChecks(environment.value(QStringLiteral("ASAN_OPTIONS"))));
    }
    return environment;
}

} // namespace LiveTest
