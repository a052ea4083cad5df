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
/**
 * Registers the atexit function after which threads ending no longer give their Python thread
 * state back (the interpreter frees them as it ends). Called once, when the module is imported.
 */
void guardThreadEnds();
/// Drops @p object's reference with the GIL, or leaks it when the interpreter is gone.
void releasePython(pybind11::object &object);

/**
 * The GIL for the runtime's threads (ORB and execution context threads) calling into Python. As
 * pybind11::gil_scoped_acquire, but the Python thread state it makes for such a thread is kept
 * until the thread ends rather than made and freed on every call (with its frame stack, which
 * Python maps and unmaps), which took microseconds of each sample a Python port received.
 */
class Gil
{
public:
    Gil();
    Gil(const Gil &) = delete;
    Gil &operator=(const Gil &) = delete;

private:
    /// True when this thread has no Python thread state yet (read before acquiring).
    static bool threadHasNoState();

    bool m_first;
    pybind11::gil_scoped_acquire m_acquired;
};

} // namespace RtPython
