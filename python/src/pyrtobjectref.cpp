// SPDX-License-Identifier: MIT
#include "pyrtobjectref.h"
#include "pyexecutioncontextref.h"
#include "pyremotecall.h"

namespace RtPython {

namespace {

std::vector<PyExecutionContextRef> contexts(const RTC::ExecutionContextList &list)
{
    std::vector<PyExecutionContextRef> result;
    for (CORBA::ULong i = 0; i < list.length(); ++i)
        result.emplace_back(list[i].in());
    return result;
}

} // namespace

PyRTObjectRef::PyRTObjectRef(RTC::RTObject_ptr object)
    : m_object(RTC::RTObject::_duplicate(object))
{
}

std::vector<PyExecutionContextRef> PyRTObjectRef::get_owned_contexts()
{
    RTC::ExecutionContextList_var list = remoteCall("get_owned_contexts", [this] { return m_object->get_owned_contexts(); });
    return contexts(list.in());
}

std::vector<PyExecutionContextRef> PyRTObjectRef::get_participating_contexts()
{
    RTC::ExecutionContextList_var list =
        remoteCall("get_participating_contexts", [this] { return m_object->get_participating_contexts(); });
    return contexts(list.in());
}

bool PyRTObjectRef::is_alive(const PyExecutionContextRef *context)
{
    RTC::ExecutionContext_ptr ec = context ? context->object() : RTC::ExecutionContext::_nil();
    return remoteCall("is_alive", [this, ec] { return bool(m_object->is_alive(ec)); });
}

std::string PyRTObjectRef::instance_name()
{
    return remoteCall("get_component_profile", [this] {
        RTC::ComponentProfile_var profile = m_object->get_component_profile();
        return std::string(profile->instance_name.in());
    });
}

} // namespace RtPython
