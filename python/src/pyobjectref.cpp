// SPDX-License-Identifier: MIT
#include "pyobjectref.h"
#include "bindings.h"
#include "pyservicecall.h"

#include <rtmruntime/corbautil.h>

namespace py = pybind11;

namespace RtPython {

PyObjectRef::PyObjectRef(CORBA::Object_ptr object)
    : m_object(CORBA::Object::_duplicate(object))
{ }

py::object PyObjectRef::invoke(const std::string &repositoryId, const std::string &operation,
                               const py::tuple &arguments) const
{
    return invokeOperation(m_object, repositoryId, operation, arguments);
}

bool PyObjectRef::nonExistent() const
{
    if (isNil())
        return true;
    try {
        py::gil_scoped_release release;
        return m_object->_non_existent();
    } catch (const CORBA::SystemException &) {
        return true;
    }
}

bool PyObjectRef::isA(const std::string &repositoryId) const
{
    if (isNil())
        return false;
    try {
        py::gil_scoped_release release;
        return m_object->_is_a(repositoryId.c_str());
    } catch (const CORBA::SystemException &error) {
        raiseSystemException(error);
    }
}

std::string PyObjectRef::ior() const
{
    CORBA::String_var text = Runtime::theOrb()->object_to_string(m_object);
    return std::string(text.in());
}

void bindObjectRef(py::module_ &module)
{
    py::class_<PyObjectRef>(module, "ObjectRef")
        .def("invoke", &PyObjectRef::invoke, py::arg("repository_id"), py::arg("operation"),
             py::arg("arguments"))
        .def("is_nil", &PyObjectRef::isNil)
        .def("non_existent", &PyObjectRef::nonExistent)
        .def("is_a", &PyObjectRef::isA, py::arg("repository_id"))
        .def("ior", &PyObjectRef::ior);
    module.def(
        "string_to_object",
        [](const std::string &ior) {
            CORBA::Object_var object = Runtime::theOrb()->string_to_object(ior.c_str());
            return PyObjectRef(object);
        },
        py::arg("ior"), "A reference from its IOR (or corbaloc/corbaname) text.");
}

} // namespace RtPython
