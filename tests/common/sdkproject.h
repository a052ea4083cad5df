// SPDX-License-Identifier: MIT
#pragma once

#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace SdkTest {

/// What running a tool gave: whether it finished in time, its exit code (-1 when it crashed) and
/// its merged output.
struct RunResult
{
    bool finished = false;
    int exitCode = -1;
    QString output;

    bool ok() const { return finished && exitCode == 0; }
};

/// Runs @p program in @p workingDirectory with @p environment; killed after @p timeoutMs.
RunResult run(const QString &program, const QStringList &arguments, const QProcessEnvironment &environment,
              const QString &workingDirectory, int timeoutMs);

/// "@p what failed (exit N):" and the end of the tool's output, for a test's failure message.
QString failure(const QString &what, const RunResult &result);

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

/// Copies the folder @p from with everything in it to @p to (created); false when a file cannot be copied.
bool copyTree(const QString &from, const QString &to);

/// Runs a tool in @p cwd; false with its output in @p log when it fails or runs past @p timeoutMs.
bool runTool(const QString &program, const QStringList &arguments, const QString &cwd, int timeoutMs, QString *log);

/**
 * Configures (`<dir>/build`, Ninja, Release, ccache when installed) and builds a generated
 * component project against the component SDK of the prefix @p sdkPrefix (this build tree in
 * the tests), with @p cmakeArguments added to the configure step. ccache sees paths under the
 * temporary folder relative to the build folder, so that the same project in another temporary
 * folder (the next run) is found in the cache. False with CMake's and the compiler's output in
 * @p log when either step fails.
 */
bool buildProject(const QString &dir, const QString &sdkPrefix, QString *log,
                  const QStringList &cmakeArguments = {});

} // namespace SdkTest
