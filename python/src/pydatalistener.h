// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/ConnectorListener.h>

#include <pybind11/pybind11.h>

#include <string>

namespace RtPython {

/**
 * A Python connector data listener (an OpenRTM_aist.ConnectorDataListenerT: `listener(info, data)`)
 * on a port whose samples are of the IDL type @p repositoryId: the runtime's CDR sample is decoded
 * for it, on an InPort (@p side `inport`) as the connection's inport marshaling type says, on an
 * OutPort (`outport`) as the component wrote it. Listeners observe; what they return is not sent on.
 * Their exceptions are printed and do not reach the port.
 */
class PyDataListener : public RTC::ConnectorDataListener
{
public:
    PyDataListener(pybind11::object listener, std::string repositoryId, const char *side);
    ~PyDataListener() override;
    ReturnCode operator()(RTC::ConnectorInfo &info, RTC::ByteData &data, const std::string &marshalingtype) override;

private:
    pybind11::object m_listener;
    std::string m_repositoryId;
    const char *m_side;
};

} // namespace RtPython
