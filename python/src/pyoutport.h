// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/OutPortBase.h>

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * OpenRTM_aist.OutPort: an SDK OutPort sending Python values of one IDL data type as CDR. The
 * GIL is released while the sample travels, so listeners and components of this process that
 * receive it run meanwhile.
 */
class PyOutPort : public RTC::OutPortBase
{
public:
    PyOutPort(const std::string &name, pybind11::object value);
    ~PyOutPort() override;

    /// Sends the port's value. Takes the GIL.
    bool write() override;
    /// Samples leave as CDR, also to ports of the same process.
    bool givesValues() const override { return false; }
    /// Sends @p value (the port's value when None). Needs the GIL.
    bool writeValue(pybind11::object value);

    void addDataListener(RTC::ConnectorDataListenerType type, pybind11::object listener);
    void addConnectorListener(RTC::ConnectorListenerType type, pybind11::object listener);

private:
    pybind11::object m_value;
};

} // namespace RtPython
