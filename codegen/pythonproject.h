// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"

#include <QString>
#include <QStringList>

#include <optional>

namespace Codegen {

/**
 * A generated Python component project: `<Name>.py` (with `<Name>Init(manager)`) beside the
 * project's RTC.xml, no CMakeLists.txt, the project's own IDL files in `idl/` compiled by its
 * `idlcompile.sh`. What the Builder's Build checks and Run in Manager loads (rtmanager runs Python
 * modules in its own process).
 */
class PythonProject
{
public:
    /// The project of component @p componentName in @p folder (whether or not it exists).
    PythonProject(QString folder, QString componentName);
    /// The Python project in @p folder, its component named by the folder's RTC.xml; nothing
    /// when the folder holds no generated Python project.
    static std::optional<PythonProject> inFolder(const QString &folder);

    /// Whether the folder holds this component's Python module and no C++ (CMake) project.
    bool exists() const;
    QString folder() const { return m_folder; }
    QString componentName() const { return m_name; }
    /// `<folder>/<Name>.py`.
    QString modulePath() const;
    /// `<Name>Init`, which registers the component type with a manager.
    QString initFunction() const { return m_name + QStringLiteral("Init"); }
    /// The project's own IDL files (`idl/*.idl`): compiled by idlCompileScript() before the module runs.
    QStringList ownIdlFiles() const;
    QString idlCompileScript() const;

    /**
     * A manager's refusal of a Python module (`… load_module: '<module>' does not load:
     * FILE:LINE: Type: message`, or `… has no init function …`) as a diagnostic at the file and
     * line it names; nothing for other lines.
     */
    static std::optional<Profile::Diagnostic> parseLoadProblem(const QString &line);

private:
    QString m_folder;
    QString m_name;
};

} // namespace Codegen
