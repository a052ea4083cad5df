// SPDX-License-Identifier: MIT
// Sensor → Controller → Motor: OpenRTM-aist's three-component loop example. Each passes the
// TimedLong it receives on "in" to "out"; Motor adds its motor_id so the loop is observable.
#include "builtins.h"
#include "factorytemplate.h"

#include <BasicDataType.hh>

namespace Runtime {

namespace {

class PassThrough : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        m_in = addInPort<RTC::TimedLong>("in");
        m_out = addOutPort<RTC::TimedLong>("out");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        RTC::TimedLong sample;
        while (m_in->isNew() && m_in->read(&sample)) {
            sample.data = transform(sample.data);
            m_out->write(sample);
            setStatus("last_value", std::to_string(sample.data));
        }
        return RTC::RTC_OK;
    }
    virtual CORBA::Long transform(CORBA::Long value) { return value; }

private:
    InPort<RTC::TimedLong> *m_in = nullptr;
    OutPort<RTC::TimedLong> *m_out = nullptr;
};

class Motor : public PassThrough
{
public:
    using PassThrough::PassThrough;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        configuration().bindParameter("motor_id", "0", [this](const std::string &text) {
            try {
                m_motorId = std::stoi(text);
                return true;
            } catch (...) {
                return false;
            }
        });
        return PassThrough::onInitialize();
    }
    CORBA::Long transform(CORBA::Long value) override { return value + m_motorId; }

private:
    int m_motorId = 0;
};

} // namespace

std::vector<ComponentFactory> controlLoopFactories()
{
    return {builtinFactory<PassThrough>("Sensor", "Sensor component"),
            builtinFactory<PassThrough>("Controller", "Controller component"),
            builtinFactory<Motor>("Motor", "Motor component")};
}

} // namespace Runtime
