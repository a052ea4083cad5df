// SPDX-License-Identifier: MIT
#pragma once

#include <omniORB4/CORBA.h>

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * An object reference held for Python (`_rtstudio.ObjectRef`, the `_obj` of omniORB.CORBA.Object):
 * the generated `_objref_<I>` methods call invoke(), which marshals by the operation's IDL
 * signature (see invokeOperation()).
 */
class PyObjectRef
{
public:
    explicit PyObjectRef(CORBA::Object_ptr object);

    CORBA::Object_ptr object() const { return m_object.in(); }
    pybind11::object invoke(const std::string &repositoryId, const std::string &operation,
                            const pybind11::tuple &arguments) const;
    bool isNil() const { return CORBA::is_nil(m_object); }
    /// True when the object no longer exists (or cannot be reached).
    bool nonExistent() const;
    bool isA(const std::string &repositoryId) const;
    std::string ior() const;

private:
    CORBA::Object_var m_object;
};

} // namespace RtPython
