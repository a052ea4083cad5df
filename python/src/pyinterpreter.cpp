// SPDX-License-Identifier: MIT
#include "pyinterpreter.h"

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

/// Holds one more use of the thread state Gil made for this thread, given up when the thread ends.
struct KeptThreadState
{
    bool kept = false;
    ~KeptThreadState()
    {
        if (!kept || !interpreterAlive())
            return;
        // Back to one use, which this acquisition's end gives up: the state is freed.
        py::gil_scoped_acquire gil;
        gil.dec_ref();
    }
};

thread_local KeptThreadState keptState;

} // namespace

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
