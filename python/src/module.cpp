// SPDX-License-Identifier: MIT
// The extension module under OpenRTM_aist and RTC: OpenRTM-aist-Python's API over the C++ SDK.
#include "bindings.h"
#include "pyinterpreter.h"

PYBIND11_MODULE(_rtstudio, module)
{
    module.doc() = "RT Studio's component runtime for OpenRTM-aist-Python's API (used by OpenRTM_aist and RTC)";
    RtPython::bindProperties(module);
    RtPython::bindDataTypes(module);
    RtPython::bindTypeCodes(module);
    RtPython::bindListeners(module);
    RtPython::bindPorts(module);
    RtPython::bindObjectRef(module);
    RtPython::bindOrb(module);
    RtPython::bindServicePorts(module);
    RtPython::bindComponent(module);
    RtPython::bindConfiguration(module);
    RtPython::bindObjectReferences(module);
    RtPython::bindManager(module);
    RtPython::guardThreadEnds();
}
