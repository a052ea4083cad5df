// SPDX-License-Identifier: MIT
// SeqOut / SeqIn: OpenRTM-aist's example with one port per basic type and sequence type.
// SeqOut writes a counter into every port; SeqIn counts what arrives on each.
#include "builtins.h"
#include "factorytemplate.h"

#include <BasicDataType.hh>

#include <functional>

namespace Runtime {

namespace {

class SeqOut : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        configuration().bindParameter("data_type", "serial", [](const std::string &) { return true; });
        m_octet = addOutPort<RTC::TimedOctet>("Octet");
        m_short = addOutPort<RTC::TimedShort>("Short");
        m_long = addOutPort<RTC::TimedLong>("Long");
        m_float = addOutPort<RTC::TimedFloat>("Float");
        m_double = addOutPort<RTC::TimedDouble>("Double");
        m_octetSeq = addOutPort<RTC::TimedOctetSeq>("OctetSeq");
        m_shortSeq = addOutPort<RTC::TimedShortSeq>("ShortSeq");
        m_longSeq = addOutPort<RTC::TimedLongSeq>("LongSeq");
        m_floatSeq = addOutPort<RTC::TimedFloatSeq>("FloatSeq");
        m_doubleSeq = addOutPort<RTC::TimedDoubleSeq>("DoubleSeq");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        ++m_counter;
        writeScalar(m_octet, CORBA::Octet(m_counter));
        writeScalar(m_short, CORBA::Short(m_counter));
        writeScalar(m_long, CORBA::Long(m_counter));
        writeScalar(m_float, CORBA::Float(m_counter));
        writeScalar(m_double, CORBA::Double(m_counter));
        writeSequence(m_octetSeq, CORBA::Octet(m_counter));
        writeSequence(m_shortSeq, CORBA::Short(m_counter));
        writeSequence(m_longSeq, CORBA::Long(m_counter));
        writeSequence(m_floatSeq, CORBA::Float(m_counter));
        writeSequence(m_doubleSeq, CORBA::Double(m_counter));
        return RTC::RTC_OK;
    }

private:
    template <typename Sample, typename Value>
    static void writeScalar(OutPort<Sample> *port, Value value)
    {
        Sample sample{};
        sample.data = value;
        port->write(sample);
    }
    template <typename Sample, typename Value>
    static void writeSequence(OutPort<Sample> *port, Value value)
    {
        Sample sample{};
        sample.data.length(10);
        for (CORBA::ULong i = 0; i < 10; ++i)
            sample.data[i] = Value(value + Value(i));
        port->write(sample);
    }

    long m_counter = 0;
    OutPort<RTC::TimedOctet> *m_octet = nullptr;
    OutPort<RTC::TimedShort> *m_short = nullptr;
    OutPort<RTC::TimedLong> *m_long = nullptr;
    OutPort<RTC::TimedFloat> *m_float = nullptr;
    OutPort<RTC::TimedDouble> *m_double = nullptr;
    OutPort<RTC::TimedOctetSeq> *m_octetSeq = nullptr;
    OutPort<RTC::TimedShortSeq> *m_shortSeq = nullptr;
    OutPort<RTC::TimedLongSeq> *m_longSeq = nullptr;
    OutPort<RTC::TimedFloatSeq> *m_floatSeq = nullptr;
    OutPort<RTC::TimedDoubleSeq> *m_doubleSeq = nullptr;
};

class SeqIn : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        add<RTC::TimedOctet>("Octet");
        add<RTC::TimedShort>("Short");
        add<RTC::TimedLong>("Long");
        add<RTC::TimedFloat>("Float");
        add<RTC::TimedDouble>("Double");
        add<RTC::TimedOctetSeq>("OctetSeq");
        add<RTC::TimedShortSeq>("ShortSeq");
        add<RTC::TimedLongSeq>("LongSeq");
        add<RTC::TimedFloatSeq>("FloatSeq");
        add<RTC::TimedDoubleSeq>("DoubleSeq");
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::ExecutionContextHandle_t) override
    {
        for (auto &reader : m_readers)
            reader();
        return RTC::RTC_OK;
    }

private:
    template <typename Sample>
    void add(const std::string &name)
    {
        InPort<Sample> *port = addInPort<Sample>(name);
        auto count = std::make_shared<long>(0);
        m_readers.push_back([this, port, count, name] {
            // Pushed samples first; then, as OpenRTM-aist's SeqIn reads every cycle, one read
            // that asks a pull connector's OutPort.
            Sample sample;
            bool pushed = false;
            while (port->isNew() && port->read(&sample)) {
                ++*count;
                pushed = true;
            }
            if (!pushed && port->read(&sample))
                ++*count;
            setStatus(name + "_count", std::to_string(*count));
        });
    }

    std::vector<std::function<void()>> m_readers;
};

} // namespace

std::vector<ComponentFactory> sequenceFactories()
{
    return {builtinFactory<SeqOut>("SeqOut", "Sequence OutPort component"),
            builtinFactory<SeqIn>("SeqIn", "Sequence InPort component")};
}

} // namespace Runtime
