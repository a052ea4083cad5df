// SPDX-License-Identifier: MIT
// Sensor → Controller → Motor: OpenRTM-aist's three-component loop example, with its port types:
// Sensor turns the TimedLong it receives on "in" into a TimedFloat on "out", Controller passes
// TimedFloat on, Motor turns TimedFloat back into TimedLong and adds its motor_id so that the
// loop is observable (status `last_value`).
#include "builtins.h"
#include "factorytemplate.h"

#include <BasicDataType.hh>

#include <sstream>

namespace Runtime {

namespace {

// Whole numbers print without a fraction ("3", not "3.000000"), whatever the sample type.
template <typename Value>
std::string text(Value value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

template <typename In, typename Out>
class PassThrough : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        m_in = addInPort<In>("in");
        m_out = addOutPort<Out>("out");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        In received;
        while (m_in->isNew() && m_in->read(&received)) {
            Out sent;
            sent.tm = received.tm;
            sent.data = transform(received.data);
            m_out->write(sent);
            setStatus("last_value", text(sent.data));
        }
        return RTC::RTC_OK;
    }
    virtual decltype(Out::data) transform(decltype(In::data) value)
    {
        return static_cast<decltype(Out::data)>(value);
    }

private:
    InPort<In> *m_in = nullptr;
    OutPort<Out> *m_out = nullptr;
};

using Sensor = PassThrough<RTC::TimedLong, RTC::TimedFloat>;
using Controller = PassThrough<RTC::TimedFloat, RTC::TimedFloat>;

class Motor : public PassThrough<RTC::TimedFloat, RTC::TimedLong>
{
public:
    using PassThrough::PassThrough;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        configuration().bindParameter("motor_id", "0", [this](const std::string &value) {
            try {
                m_motorId = std::stoi(value);
                return true;
            } catch (...) {
                return false;
            }
        });
        return PassThrough::onInitialize();
    }
    CORBA::Long transform(CORBA::Float value) override { return CORBA::Long(value) + m_motorId; }

private:
    int m_motorId = 0;
};

// The three examples are SPORADIC in OpenRTM-aist's module specs.
template <typename T>
ComponentFactory sporadicFactory(const std::string &type, const std::string &description)
{
    ComponentFactory factory = builtinFactory<T>(type, description);
    factory.profile.set("activity_type", "SPORADIC");
    return factory;
}

ComponentFactory motorFactory()
{
    ComponentFactory factory = sporadicFactory<Motor>("Motor", "Motor component");
    factory.profile.set("conf.default.motor_id", "0");
    factory.profile.set("conf.__widget__.motor_id", "text");
    factory.profile.set("conf.__type__.motor_id", "int");
    return factory;
}

} // namespace

std::vector<ComponentFactory> controlLoopFactories()
{
    return {sporadicFactory<Sensor>("Sensor", "Sensor component"),
            sporadicFactory<Controller>("Controller", "Controller component"), motorFactory()};
}

} // namespace Runtime
