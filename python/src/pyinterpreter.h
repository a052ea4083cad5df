// SPDX-License-Identifier: MIT
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/// The Python traceback of @p error as the interpreter prints it.
std::string traceback(pybind11::error_already_set &error);
/// Writes @p context and the traceback of @p error to sys.stderr (callbacks run in the runtime's
/// threads, where nobody else would see the exception). Needs the GIL.
void printError(const std::string &context, pybind11::error_already_set &error);
/**
 * True while the interpreter can run code: the runtime's threads may outlive it at process exit,
 * and acquiring the GIL after finalization would hang them.
 */
bool interpreterAlive();
/// Drops @p object's reference with the GIL, or leaks it when the interpreter is gone.
void releasePython(pybind11::object &object);

} // namespace RtPython
