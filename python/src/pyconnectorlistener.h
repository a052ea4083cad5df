// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/ConnectorListener.h>

#include <pybind11/pybind11.h>

namespace RtPython {

/// A Python connector listener (an OpenRTM_aist.ConnectorListener: `listener(info)`).
class PyConnectorListener : public RTC::ConnectorListener
{
public:
    explicit PyConnectorListener(pybind11::object listener);
    ~PyConnectorListener() override;
    ReturnCode operator()(RTC::ConnectorInfo &info) override;

private:
    pybind11::object m_listener;
};

} // namespace RtPython
