// SPDX-License-Identifier: MIT
#pragma once

#include <pybind11/pybind11.h>

/// The parts of the extension module _rtstudio, each adding its classes and functions to it.
namespace RtPython {

/// Properties (coil::Properties with OpenRTM-aist-Python's constructor).
void bindProperties(pybind11::module_ &module);
/// IDL data types: loading OpenRTM's IDL, the classes of its structs and enums.
void bindDataTypes(pybind11::module_ &module);
/// What CORBA.TypeCode tells of a type (after bindDataTypes).
void bindTypeCodes(pybind11::module_ &module);
/// ConnectorInfo and the listener types.
void bindListeners(pybind11::module_ &module);
/// InPort and OutPort.
void bindPorts(pybind11::module_ &module);
/// ObjectRef, the references Python consumers call through.
void bindObjectRef(pybind11::module_ &module);
/// CorbaPort and the consumers' reference slots.
void bindServicePorts(pybind11::module_ &module);
/// The component bridge that DataFlowComponentBase delegates to.
void bindComponent(pybind11::module_ &module);
/// Configuration sets and configuration listeners of the component.
void bindConfiguration(pybind11::module_ &module);
/// Object references of components and execution contexts (after bindComponent).
void bindObjectReferences(pybind11::module_ &module);
/// The ORB's own calls and servants' activation (after bindObjectRef).
void bindOrb(pybind11::module_ &module);
/// Manager.
void bindManager(pybind11::module_ &module);

} // namespace RtPython
