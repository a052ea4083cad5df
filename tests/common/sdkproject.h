// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QStringList>

namespace SdkTest {

/// What a user writes into a generated file: the generated text @p before becomes @p after.
struct UserEdit
{
    const char *file; ///< relative to the project
    const char *before;
    const char *after;
};

/// Applies @p edit to the project at @p root; false with the reason in @p error when the file
/// cannot be read or written or has no such generated text.
bool applyEdit(const QString &root, const UserEdit &edit, QString *error);

/// Runs a tool in @p cwd; false with its output in @p log when it fails or runs past @p timeoutMs.
bool runTool(const QString &program, const QStringList &arguments, const QString &cwd, int timeoutMs, QString *log);

/**
 * Configures (`<dir>/build`, Ninja, Release, ccache when installed) and builds a generated
 * component project against the component SDK of the prefix @p sdkPrefix (this build tree in
 * the tests). False with CMake's and the compiler's output in @p log when either step fails.
 */
bool buildProject(const QString &dir, const QString &sdkPrefix, QString *log);

} // namespace SdkTest
