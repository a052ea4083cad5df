// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace Codegen::Installation {

/// True when the running program is one of the build tree's (not an installed copy).
bool runsFromBuildTree();

/**
 * The prefix the running program is installed in, found from the program's own folder
 * (`<prefix>/bin`), so that a moved or unpacked installation finds its files; the build tree for
 * programs run from it.
 */
QString prefix();

/// The bundled OpenRTM IDL: `<prefix>/share/rtstudio/idl`, or the source folder from the build tree.
QString bundledIdlDirectory();

/// The rtmanager program: `<prefix>/bin/rtmanager`, or the build tree's.
QString managerProgram();

/// The rtctl program: `<prefix>/bin/rtctl`, or the build tree's (a Python project's idlcompile.sh runs `rtctl idl`).
QString rtctlProgram();

} // namespace Codegen::Installation
