// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/InPortBase.h>

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * OpenRTM_aist.InPort: an SDK InPort whose samples are CDR of the IDL type of the value it was
 * made with (`InPort("in", RTC.TimedLong(RTC.Time(0, 0), 0))`), decoded into new Python values, or
 * by the Python serializer its connection's marshaling type names.
 */
class PyInPort : public RTC::InPortBase
{
public:
    PyInPort(const std::string &name, pybind11::object value);
    ~PyInPort() override;

    /// Takes the next sample into the port's value; false when none waits. Takes the GIL.
    bool read(std::string name = "") override;
    /// Samples arrive as CDR, also from ports of the same process.
    bool takesValues() const override { return false; }
    /// OpenRTM-aist-Python's read(): the next sample, or the last value when none waits.
    pybind11::object readValue();

    /// Adds a Python data listener (kept until the port goes).
    void addDataListener(RTC::ConnectorDataListenerType type, pybind11::object listener);
    /// Adds a Python connector listener (kept until the port goes).
    void addConnectorListener(RTC::ConnectorListenerType type, pybind11::object listener);

private:
    /// Takes the next sample into m_value; false when none waits. Needs the GIL.
    bool takeSample();
    /// The `inport.marshaling_type` (or `marshaling_type`) of connection @p connectorId, `cdr` by default.
    std::string marshalingType(const std::string &connectorId);

    pybind11::object m_value;
};

} // namespace RtPython
