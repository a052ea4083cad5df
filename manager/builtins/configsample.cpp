// SPDX-License-Identifier: MIT
// ConfigSample: OpenRTM-aist's configuration example. The bound values are mirrored into the
// status list after each update so that activation of a set is observable from outside.
#include "builtins.h"
#include "factorytemplate.h"

namespace Runtime {

namespace {

class ConfigSample : public RtObject
{
public:
    using RtObject::RtObject;

protected:
    RTC::ReturnCode_t onInitialize() override
    {
        bind("int_param0", "0");
        bind("int_param1", "1");
        bind("double_param0", "0.11");
        bind("double_param1", "9.9");
        bind("str_param0", "hoge");
        bind("str_param1", "dara");
        bind("vector_param0", "0.0,1.0,2.0,3.0,4.0");
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
    // The two extra sets OpenRTM-aist's ConfigSample.conf defines, and the widget hints.
    p.set("conf.mode0.int_param0", "12345");
    p.set("conf.mode0.int_param1", "-12345");
    p.set("conf.mode0.double_param0", "3.141592653589793238462643383279");
    p.set("conf.mode0.double_param1", "-3.141592653589793238462643383279");
    p.set("conf.mode0.str_param0", "mode0");
    p.set("conf.mode0.str_param1", "foo");
    p.set("conf.mode0.vector_param0", "0.0,0.1,0.2,0.3,0.4");
    p.set("conf.mode1.int_param0", "-999");
    p.set("conf.mode1.int_param1", "999");
    p.set("conf.mode1.double_param0", "2.718281828459045235360287471352");
    p.set("conf.mode1.double_param1", "-2.718281828459045235360287471352");
    p.set("conf.mode1.str_param0", "mode1");
    p.set("conf.mode1.str_param1", "bar");
    p.set("conf.mode1.vector_param0", "0.1,0.01,0.001,0.0001,0.00001");
    p.set("conf.__widget__.int_param0", "slider.1");
    p.set("conf.__widget__.int_param1", "spin");
    p.set("conf.__widget__.double_param0", "slider.0.1");
    p.set("conf.__widget__.double_param1", "text");
    p.set("conf.__widget__.str_param0", "radio");
    p.set("conf.__widget__.str_param1", "text");
    p.set("conf.__widget__.vector_param0", "text");
    p.set("conf.__constraints__.int_param0", "0<=x<=150");
    p.set("conf.__constraints__.int_param1", "0<=x<=1000");
    p.set("conf.__constraints__.double_param0", "0<=x<=100");
    p.set("conf.__constraints__.str_param0", "(default,mode0,mode1)");
    return factory;
}

} // namespace

std::vector<ComponentFactory> configSampleFactories()
{
    return {configSampleFactory()};
}

} // namespace Runtime
