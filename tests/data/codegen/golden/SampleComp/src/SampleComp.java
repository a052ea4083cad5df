// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file SampleComp.java
 * @brief Sample component with "all" port kinds
 */
// </rtc-template>

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.RegisterModuleFunc;
import jp.go.aist.rtm.RTC.RtcDeleteFunc;
import jp.go.aist.rtm.RTC.RtcNewFunc;
import jp.go.aist.rtm.RTC.util.Properties;

/*!
 * @class SampleComp
 * @brief Sample component with "all" port kinds
 */
public class SampleComp implements RtcNewFunc, RtcDeleteFunc, RegisterModuleFunc {

    // The component type as the manager registers it (the profile's properties).
    // <rtc-template block="module_spec">
    public static String component_conf[] = {
            "implementation_id", "SampleComp",
            "type_name", "SampleComp",
            "description", "Sample component with \"all\" port kinds",
            "version", "1.2.0",
            "vendor", "Example",
            "category", "Test",
            "activity_type", "PERIODIC",
            "kind", "DataFlowComponent",
            "max_instance", "1",
            "language", "Java",
            "lang_type", "compile",
            "conf.default.gain_value", "10",
            "conf.default.mode", "fast",
            "conf.default.rate", "0.5",
            "conf.__widget__.gain_value", "slider.1",
            "conf.__widget__.mode", "radio",
            "conf.__constraints__.gain_value", "0<=x<=100",
            "conf.__constraints__.mode", "(fast,slow)",
            "conf.__type__.gain_value", "int",
            "conf.__type__.mode", "string",
            "conf.__type__.rate", "double",
            ""
    };
    // </rtc-template>

    public RTObject_impl createRtc(Manager mgr) {
        return new SampleCompImpl(mgr);
    }

    public void deleteRtc(RTObject_impl rtcBase) {
        rtcBase = null;
    }

    public void registerModule() {
        Properties prop = new Properties(component_conf);
        final Manager manager = Manager.instance();
        manager.registerFactory(prop, new SampleComp(), new SampleComp());
    }
}
