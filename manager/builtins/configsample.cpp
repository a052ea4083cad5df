// SPDX-License-Identifier: MIT
// ConfigSample: OpenRTM-aist's configuration example. The bound values are mirrored into the
// status list after each update so that activation of a set is observable from outside.
#include "builtins.h"
#include "factorytemplate.h"

namespace Runtime {

namespace {

// The parameters in OpenRTM-aist's order with the defaults its module spec binds.
const std::vector<std::pair<std::string, std::string>> &defaults()
{
    static const std::vector<std::pair<std::string, std::string>> values {
        {"int_param0", "0"},         {"int_param1", "1"},    {"double_param0", "0.11"},
        {"double_param1", "9.9"},    {"str_param0", "hoge"}, {"str_param1", "dara"},
        {"vector_param0", "0.0,1.0,2.0,3.0,4.0"}};
    return values;
}

class ConfigSample : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        for (const auto &[name, value] : defaults())
            bind(name, value);
        return RTC::RTC_OK;
    }

private:
    // The status carries the value exactly as the variable received it.
    void bind(const std::string &name, const std::string &defaultValue)
    {
        configuration().bindParameter(name, defaultValue, [this, name](const std::string &value) {
            setStatus(name, value);
            return true;
        });
    }
};

ComponentFactory configSampleFactory()
{
    ComponentFactory factory = builtinFactory<ConfigSample>("ConfigSample", "Configuration example component");
    Properties &p = factory.profile;
    // OpenRTM-aist's ConfigSample module spec differs from the other examples' here.
    p.set("version", "1.0");
    p.set("vendor", "Noriaki Ando, AIST");
    p.set("activity_type", "DataFlowComponent");
    p.remove("kind");
    for (const auto &[name, value] : defaults())
        p.set("conf.default." + name, value);
    // The two extra sets, the widget hints and the constraints of the example's configsample.conf.
    const char *const sets[][2] = {
        {"mode0.int_param0", "12345"},
        {"mode0.int_param1", "98765"},
        {"mode0.double_param0", "3.141592653589793238462643383279"},
        {"mode0.double_param1", "2.718281828459045235360287471352"},
        {"mode0.str_param0", "mode0"},
        {"mode0.str_param1", "foo"},
        {"mode0.vector_param0", "0.0,0.1,0.2,0.3,0.4"},
        {"mode1.int_param0", "-999"},
        {"mode1.int_param1", "999"},
        {"mode1.double_param0", "297992458"},
        {"mode1.double_param1", "2.97992458e+8"},
        {"mode1.str_param0", "mode1"},
        {"mode1.str_param1", "AIST"},
        {"mode1.vector_param0", "1,2,3,4,5,6,7,8,9"},
        {"__widget__.int_param0", "slider.10"},
        {"__widget__.int_param1", "spin"},
        {"__widget__.double_param0", "slider.10"},
        {"__widget__.double_param1", "text"},
        {"__widget__.str_param0", "radio"},
        {"__widget__.str_param1", "text"},
        {"__widget__.vector_param0", "text"},
        {"__constraints__.int_param0", "0<=x<=150"},
        {"__constraints__.int_param1", "0<=x<=1000"},
        {"__constraints__.double_param0", "0<=x<=100"},
        {"__constraints__.str_param0", "(default,mode0,mode1)"},
    };
    for (const auto &[key, value] : sets)
        p.set(std::string("conf.") + key, value);
    return factory;
}

} // namespace

std::vector<ComponentFactory> configSampleFactories()
{
    return {configSampleFactory()};
}

} // namespace Runtime
