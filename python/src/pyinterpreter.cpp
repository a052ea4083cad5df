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
    py::gil_scoped_acquire gil;
    object = py::object();
}

} // namespace RtPython
