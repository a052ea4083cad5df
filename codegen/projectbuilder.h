// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "pythonproject.h"

#include <QObject>
#include <QPointer>
#include <QProcess>
#include <QString>
#include <QStringList>

#include <optional>

class QTimer;

namespace Codegen {

/// What ProjectBuilder::start() builds and how.
struct BuildOptions
{
    QString projectDir; ///< the folder with the top CMakeLists.txt
    QString buildDir; ///< empty: `<projectDir>/build`
    QString prefixPath; ///< CMAKE_PREFIX_PATH (the SDK); empty: not passed
    QString configuration = QStringLiteral("Release"); ///< CMAKE_BUILD_TYPE, `--config`
    bool clean = false; ///< rebuild everything (`--clean-first`)
    int jobs = 0; ///< parallel jobs; 0: one per processor core

    /// The build folder actually used.
    QString effectiveBuildDir() const;
};

/// `[n/m]` (Ninja) or `[ xx%]` (Make) at the start of a build line, as done/total.
struct BuildProgress
{
    int done = 0;
    int total = 0;
};

/**
 * Configures and builds a generated CMake project in the background, as the Builder's Build
 * and `rtctl build` do: `cmake -S DIR -B DIR/build -DCMAKE_BUILD_TYPE=… [-DCMAKE_PREFIX_PATH=…]`,
 * then `cmake --build DIR/build -j N --config …`.
 *
 * The processes run under QProcess and report through signals from the event loop, so the
 * caller's thread is never blocked. Every line the tools print is passed on through output();
 * progress lines of Ninja and Make become progress(); compiler and CMake messages
 * (`FILE:LINE[:COL]: error|warning: text`, `CMake Error at FILE:LINE`) become problem(), with
 * relative file names resolved against the folder the tool ran in. cancel() ends the whole
 * process tree (make or ninja and the compilers under it), not only the cmake process.
 *
 * A generated Python project (PythonProject) has nothing to build: its own IDL, if any, is
 * compiled with its idlcompile.sh, then the module is loaded into a manager process of its own
 * (`rtmanager --module-profile`), which imports it with RT Studio's Python packages and runs its
 * `<Name>Init`; a module that does not load becomes a problem at the file and line it names, one
 * that does not register its component type too.
 *
 * Qt Core only: used by the Builder's GUI and by rtctl alike.
 */
class ProjectBuilder : public QObject
{
    Q_OBJECT

public:
    explicit ProjectBuilder(QObject *parent = nullptr);
    ~ProjectBuilder() override;

    /// The cmake program to run (default: `cmake` found on PATH).
    void setCMakeProgram(const QString &program) { m_cmake = program; }
    QString cmakeProgram() const;

    /// Starts configuring and building; false (with finished() emitted) when it cannot start.
    bool start(const BuildOptions &options);
    /// Stops a running build: the process group is terminated, then killed when it lingers.
    void cancel();
    bool isRunning() const;
    /// True when the running or last build was cancelled.
    bool wasCancelled() const { return m_cancelled; }

    /// Problems seen by the running or last build, in the order they were printed.
    const Profile::Diagnostics &problems() const { return m_problems; }
    const BuildOptions &options() const { return m_options; }

    /// A compiler or linker message line as a diagnostic; relative paths are resolved against
    /// `baseDir`. Nothing for other lines (notes and context lines included).
    static std::optional<Profile::Diagnostic> parseProblemLine(const QString &line,
                                                               const QString &baseDir);
    /// The progress a Ninja (`[3/10] …`) or Make (`[ 30%] …`) line announces.
    static std::optional<BuildProgress> parseProgressLine(const QString &line);

    /// The SDK prefix offered when the user chose none: RT Studio's build tree when the running
    /// program is inside it, else the prefix RT Studio was installed into.
    static QString defaultSdkPrefix();

signals:
    /// One line of tool output (without the line break).
    void output(const QString &line);
    /// `done` of `total` steps; total 0: busy without a count (configuring).
    void progress(int done, int total);
    void problem(const Profile::Diagnostic &diagnostic);
    /// The build ended: built, failed, could not start, or was cancelled; `message` names the
    /// project folder.
    void finished(bool ok, const QString &message);

private:
    enum class Step { Idle, Configure, Build, CompileIdl, CheckModule };

    /// The program (in @p program) and arguments of @p step.
    QStringList stepCommand(Step step, QString *program) const;
    void runStep(Step step);
    void readOutput();
    void handleLine(const QString &line);
    /// A line of the manager that checks a Python module: the types it registers, its refusal.
    void handleModuleLine(const QString &line);
    void finishPythonCheck();
    bool handleCMakeMessage(const QString &line);
    void flushCMakeMessage();
    void stepFinished(int exitCode, QProcess::ExitStatus status);
    QString failureMessage(int exitCode) const;
    void finish(bool ok, const QString &message);
    void signalProcessGroup(int signal);
    QString stepDir() const;

    BuildOptions m_options;
    QString m_cmake;
    QPointer<QProcess> m_process;
    qint64 m_processGroup = 0; ///< the running step's process group (its cmake's process id)
    QTimer *m_killTimer;
    Step m_step = Step::Idle;
    QList<Step> m_plan; ///< the steps after the running one
    std::optional<PythonProject> m_python; ///< the Python project being checked, if it is one
    QStringList m_registered; ///< the component types the checked Python module registered
    bool m_cancelled = false;
    QByteArray m_pending;
    Profile::Diagnostics m_problems;
    std::optional<Profile::Diagnostic> m_cmakeMessage;
};

} // namespace Codegen
