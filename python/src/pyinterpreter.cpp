// SPDX-License-Identifier: MIT
#include "pyinterpreter.h"

#include <mutex>

namespace py = pybind11;

namespace RtPython {

std::string traceback(py::error_already_set &error)
{
    try {
        const py::object format = py::module_::import("traceback").attr("format_exception");
        return py::str("").attr("join")(format(error.type(), error.value(), error.trace())).cast<std::string>();
    } catch (const py::error_already_set &) {
        return std::string(error.what()) + '\n';
    }
}

void printError(const std::string &context, py::error_already_set &error)
{
    const py::object stderrStream = py::module_::import("sys").attr("stderr");
    stderrStream.attr("write")(context + '\n' + traceback(error));
    stderrStream.attr("flush")();
}

bool interpreterAlive()
{
#if PY_VERSION_HEX >= 0x030D0000
    return Py_IsInitialized() && !Py_IsFinalizing();
#else
    return Py_IsInitialized() && !_Py_IsFinalizing();
#endif
}

void releasePython(py::object &object)
{
    if (!interpreterAlive()) {
        object.release();
        return;
    }
    Gil gil;
    object = py::object();
}

namespace {

/// Guards interpreterEnding; a thread giving its state up holds it while it waits for the GIL.
std::mutex threadEndMutex;
/// Set by an atexit function, before the interpreter begins to finalize.
bool interpreterEnding = false;

/// Holds one more use of the thread state Gil made for this thread, given up when the thread ends.
struct KeptThreadState
{
    bool kept = false;
    ~KeptThreadState()
    {
        if (!kept)
            return;
        // Python ends a thread that wants the GIL once finalization has begun, which in this
        // destructor (noexcept) would abort the process. The atexit function waits for this lock,
        // with the GIL released, so finalization cannot begin before the GIL is ours. A state
        // left behind is freed with the interpreter.
        std::lock_guard lock(threadEndMutex);
        if (interpreterEnding || !interpreterAlive())
            return;
        // Back to one use, which this acquisition's end gives up: the state is freed.
        py::gil_scoped_acquire gil;
        gil.dec_ref();
    }
};

thread_local KeptThreadState keptState;

} // namespace

void guardThreadEnds()
{
    py::module_::import("atexit").attr("register")(py::cpp_function([] {
        py::gil_scoped_release released;
        std::lock_guard lock(threadEndMutex);
        interpreterEnding = true;
    }));
}

bool Gil::threadHasNoState()
{
    return !keptState.kept && PyGILState_GetThisThreadState() == nullptr;
}

Gil::Gil()
    : m_first(threadHasNoState())
{
    if (m_first) {
        m_acquired.inc_ref();
        keptState.kept = true;
    }
}

} // namespace RtPython
