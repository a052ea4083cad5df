// SPDX-License-Identifier: MIT
#pragma once

#include <rtm/CorbaConsumer.h>
#include <rtm/CorbaPort.h>

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace RtPython {

class PyServant;

/// The reference slot of a Python OpenRTM_aist.CorbaConsumer, which the port fills on connect.
class PyConsumerSlot : public RTC::CorbaConsumerBase
{
public:
    /// The provider's reference as an `_rtstudio.ObjectRef`, or None while unconnected.
    pybind11::object reference();
};

/**
 * OpenRTM_aist.CorbaPort: the SDK's service port with Python providers (each behind a PyServant)
 * and Python consumers (PyConsumerSlot).
 */
class PyCorbaPort : public RTC::CorbaPort
{
public:
    explicit PyCorbaPort(const std::string &name);
    ~PyCorbaPort() override;

    /// Offers the Python servant @p servant as @p instanceName of interface type @p typeName.
    bool registerPythonProvider(const std::string &instanceName, const std::string &typeName,
                                pybind11::object servant);
    /// Declares the required interface @p instanceName that @p slot (kept as long as the port)
    /// receives.
    bool registerPythonConsumer(const std::string &instanceName, const std::string &typeName,
                                pybind11::object slot);

private:
    std::vector<PyServant *> m_servants; ///< one reference each
    std::vector<pybind11::object> m_slots;
};

} // namespace RtPython
