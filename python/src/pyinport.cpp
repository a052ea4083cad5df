// SPDX-License-Identifier: MIT
#include "pyinport.h"
#include "pyconnectorlistener.h"
#include "pydatalistener.h"
#include "pydatatypes.h"
#include "pyinterpreter.h"
#include "pyserializers.h"

namespace py = pybind11;

namespace RtPython {

PyInPort::PyInPort(const std::string &name, py::object value)
    : InPortBase(name.c_str(), PyDataTypes::repositoryId(value).c_str())
    , m_value(std::move(value))
{
    setUserSerializers(true);
}

PyInPort::~PyInPort()
{
    releasePython(m_value);
}

bool PyInPort::read(std::string name)
{
    (void)name; // samples are not told apart by connection (as in the SDK's InPort with several)
    // Also called by the runtime (readAll) from threads that do not hold the GIL.
    Gil gil;
    return takeSample();
}

std::string PyInPort::marshalingType(const std::string &connectorId)
{
    RTC::InPortConnector *connection = getConnectorById(connectorId.c_str());
    return connection ? PySerializers::marshalingType(connection->profile().properties, "inport") : std::string("cdr");
}

bool PyInPort::takeSample()
{
    Runtime::SharedCdr bytes;
    bool little = true;
    std::string marshaling;
    {
        // A pull connection asks the other side here: other threads run Python meanwhile.
        py::gil_scoped_release released;
        std::string connectorId;
        if (!readBytes(&bytes, &little, &connectorId))
            return false;
        marshaling = marshalingType(connectorId);
    }
    m_value = PySerializers::read(marshaling, m_value, dataType(), bytes->data(), bytes->size(), little);
    py::gil_scoped_release released;
    m_listeners.notifyData(RTC::ConnectorDataListenerType::ON_BUFFER_READ, std::string(), bytes->data(),
                           static_cast<unsigned long>(bytes->size()), little);
    return true;
}

py::object PyInPort::readValue()
{
    takeSample();
    return m_value;
}

void PyInPort::addDataListener(RTC::ConnectorDataListenerType type, py::object listener)
{
    auto *made = new PyDataListener(std::move(listener), dataType(), "inport");
    // The port's lock is also taken by the ORB's threads while they call listeners, which wait for
    // the GIL: it is not held while waiting for that lock (as in portbindings.cpp).
    py::gil_scoped_release released;
    addConnectorDataListener(type, made);
}

void PyInPort::addConnectorListener(RTC::ConnectorListenerType type, py::object listener)
{
    auto *made = new PyConnectorListener(std::move(listener));
    py::gil_scoped_release released; // see addDataListener()
    RTC::InPortBase::addConnectorListener(type, made);
}

} // namespace RtPython
