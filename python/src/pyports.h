// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/InPortBase.h>
#include <rtm/OutPortBase.h>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace RtPython {

/**
 * OpenRTM_aist.InPort: an SDK InPort whose samples are CDR of the IDL type of the value it was
 * made with (`InPort("in", RTC.TimedLong(RTC.Time(0, 0), 0))`), decoded into new Python values.
 */
class PyInPort : public RTC::InPortBase
{
public:
    PyInPort(const std::string &name, pybind11::object value);
    ~PyInPort() override;

    /// Takes the next sample into the port's value; false when none waits. Takes the GIL.
    bool read(std::string name = "") override;
    /// OpenRTM-aist-Python's read(): the next sample, or the last value when none waits.
    pybind11::object readValue();

    /// Adds a Python data listener (kept until the port goes).
    void addDataListener(RTC::ConnectorDataListenerType type, pybind11::object listener);
    /// Adds a Python connector listener (kept until the port goes).
    void addConnectorListener(RTC::ConnectorListenerType type, pybind11::object listener);

private:
    pybind11::object m_value;
};

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
    /// Sends @p value (the port's value when None). Needs the GIL.
    bool writeValue(pybind11::object value);

    void addDataListener(RTC::ConnectorDataListenerType type, pybind11::object listener);
    void addConnectorListener(RTC::ConnectorListenerType type, pybind11::object listener);

private:
    pybind11::object m_value;
};

} // namespace RtPython
