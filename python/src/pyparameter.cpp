// SPDX-License-Identifier: MIT
#include "pyparameter.h"
#include "pyinterpreter.h"

#include <algorithm>
#include <cctype>

namespace py = pybind11;

namespace RtPython {

namespace {

std::string trimmed(const std::string &text)
{
    const auto isSpace = [](unsigned char c) { return std::isspace(c) != 0; };
    const auto begin = std::find_if_not(text.begin(), text.end(), isSpace);
    const auto end = std::find_if_not(text.rbegin(), text.rend(), isSpace).base();
    return begin < end ? std::string(begin, end) : std::string();
}

std::string lowered(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

py::object convertBool(const std::string &text)
{
    const std::string word = lowered(trimmed(text));
    if (word == "true" || word == "1" || word == "yes" || word == "on")
        return py::bool_(true);
    if (word == "false" || word == "0" || word == "no" || word == "off")
        return py::bool_(false);
    throw py::value_error("not a boolean: " + text);
}

/// Comma-separated elements, each converted like the first element of @p like (text when it is empty).
py::list convertList(py::handle like, const std::string &text)
{
    const py::object element = py::len(like) > 0 ? py::reinterpret_borrow<py::object>(like[py::int_(0)]) : py::str("");
    py::list values;
    if (trimmed(text).empty())
        return values;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        values.append(PyParameter::convert(element, text.substr(start, comma - start)));
        if (comma == std::string::npos)
            return values;
        start = comma + 1;
    }
}

} // namespace

PyParameter::PyParameter(py::object variable, py::object trans)
    : m_variable(std::move(variable))
    , m_trans(std::move(trans))
{
}

PyParameter::~PyParameter()
{
    releasePython(m_variable);
    releasePython(m_trans);
}

py::object PyParameter::convert(py::handle like, const std::string &text)
{
    if (py::isinstance<py::bool_>(like))
        return convertBool(text);
    if (py::isinstance<py::int_>(like))
        return py::int_(py::str(trimmed(text)));
    if (py::isinstance<py::float_>(like))
        return py::float_(py::str(trimmed(text)));
    if (py::isinstance<py::tuple>(like))
        return py::tuple(convertList(like, text));
    if (py::isinstance<py::list>(like))
        return convertList(like, text);
    return py::str(text);
}

bool PyParameter::set(const std::string &text)
{
    if (!interpreterAlive())
        return false;
    Gil gil;
    try {
        if (!m_trans.is_none())
            return py::bool_(m_trans(m_variable, text));
        m_variable[py::int_(0)] = convert(m_variable[py::int_(0)], text);
        return true;
    } catch (py::error_already_set &) {
        // A value that does not convert is refused, as in C++; the variable keeps its value.
        return false;
    }
}

} // namespace RtPython
