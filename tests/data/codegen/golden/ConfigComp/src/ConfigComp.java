// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file ConfigComp.java
 * @brief Configuration with every widget and constraint
 */
// </rtc-template>

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.RegisterModuleFunc;
import jp.go.aist.rtm.RTC.RtcDeleteFunc;
import jp.go.aist.rtm.RTC.RtcNewFunc;
import jp.go.aist.rtm.RTC.util.Properties;

/*!
 * @class ConfigComp
 * @brief Configuration with every widget and constraint
 */
public class ConfigComp implements RtcNewFunc, RtcDeleteFunc, RegisterModuleFunc {

    // The component type as the manager registers it (the profile's properties).
    // <rtc-template block="module_spec">
    public static String component_conf[] = {
            "implementation_id", "ConfigComp",
            "type_name", "ConfigComp",
            "description", "Configuration with every widget and constraint",
            "version", "1.0.0",
            "vendor", "Example",
            "category", "Controller",
            "activity_type", "EVENTDRIVEN",
            "kind", "DataFlowComponent",
            "max_instance", "4",
            "language", "Java",
            "lang_type", "compile",
            "conf.default.label", "hello world",
            "conf.default.gain", "1.5",
            "conf.default.count", "3",
            "conf.default.threshold", "10",
            "conf.default.limit", "5",
            "conf.default.mode", "fast",
            "conf.default.features", "camera,lidar",
            "conf.default.order", "first,second",
            "conf.default.weights", "0.5,1.5",
            "conf.default.scale", "0.25",
            "conf.default.target", "42",
            "conf.__widget__.label", "text",
            "conf.__widget__.gain", "slider.0.5",
            "conf.__widget__.count", "spin",
            "conf.__widget__.threshold", "text",
            "conf.__widget__.mode", "radio",
            "conf.__widget__.features", "checkbox",
            "conf.__widget__.order", "ordered_list",
            "conf.__widget__.weights", "text",
            "conf.__widget__.scale", "spin",
            "conf.__constraints__.gain", "0<=x<=10",
            "conf.__constraints__.count", "0<=x<=100",
            "conf.__constraints__.threshold", "x>0",
            "conf.__constraints__.limit", "x<8",
            "conf.__constraints__.mode", "(fast,slow,idle)",
            "conf.__constraints__.features", "(camera,lidar,sonar)",
            "conf.__constraints__.order", "(first,second,third)",
            "conf.__constraints__.weights", "0<=x<=1,0<=x<=2",
            "conf.__constraints__.scale", "x>=0",
            "conf.__constraints__.target", "42",
            "conf.__type__.label", "string",
            "conf.__type__.gain", "double",
            "conf.__type__.count", "int",
            "conf.__type__.threshold", "long",
            "conf.__type__.limit", "short",
            "conf.__type__.mode", "string",
            "conf.__type__.features", "string",
            "conf.__type__.order", "vector<string>",
            "conf.__type__.weights", "vector<double>",
            "conf.__type__.scale", "float",
            "conf.__type__.target", "long",
            ""
    };
    // </rtc-template>

    public RTObject_impl createRtc(Manager mgr) {
        return new ConfigCompImpl(mgr);
    }

    public void deleteRtc(RTObject_impl rtcBase) {
        rtcBase = null;
    }

    public void registerModule() {
        Properties prop = new Properties(component_conf);
        final Manager manager = Manager.instance();
        manager.registerFactory(prop, new ConfigComp(), new ConfigComp());
    }
}
