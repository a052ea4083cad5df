// SPDX-License-Identifier: MIT
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * A configuration parameter bound to a Python variable as OpenRTM-aist-Python binds them: the
 * variable is a list of one element (`self._gain = [1.0]`) whose element takes each new value,
 * converted to the type of its current value: int, float, bool, str, or a list (or tuple) of
 * those written comma-separated (`1.5,2,3`). A conversion function given to bindParameter is
 * called instead as `trans(variable, text)` and answers whether the text converted.
 */
class PyParameter
{
public:
    PyParameter(pybind11::object variable, pybind11::object trans);
    ~PyParameter();
    PyParameter(const PyParameter &) = delete;
    PyParameter &operator=(const PyParameter &) = delete;

    /// Converts @p text and stores it in the variable; false (nothing stored) when it does not convert. Takes the GIL.
    bool set(const std::string &text);

    /// @p text as a value of the type of @p like; throws pybind11::error_already_set when it does not convert.
    static pybind11::object convert(pybind11::handle like, const std::string &text);

private:
    pybind11::object m_variable;
    pybind11::object m_trans;
};

} // namespace RtPython
