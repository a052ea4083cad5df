// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file ServicesComp.java
 * @brief Provided and required services from a multi-module IDL
 */
// </rtc-template>

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.RegisterModuleFunc;
import jp.go.aist.rtm.RTC.RtcDeleteFunc;
import jp.go.aist.rtm.RTC.RtcNewFunc;
import jp.go.aist.rtm.RTC.util.Properties;

/*!
 * @class ServicesComp
 * @brief Provided and required services from a multi-module IDL
 */
public class ServicesComp implements RtcNewFunc, RtcDeleteFunc, RegisterModuleFunc {

    // The component type as the manager registers it (the profile's properties).
    // <rtc-template block="module_spec">
    public static String component_conf[] = {
            "implementation_id", "ServicesComp",
            "type_name", "ServicesComp",
            "description", "Provided and required services from a multi-module IDL",
            "version", "1.0.0",
            "vendor", "Example",
            "category", "Controller",
            "activity_type", "SPORADIC",
            "kind", "DataFlowComponent",
            "max_instance", "0",
            "language", "Java",
            "lang_type", "compile",
            ""
    };
    // </rtc-template>

    public RTObject_impl createRtc(Manager mgr) {
        return new ServicesCompImpl(mgr);
    }

    public void deleteRtc(RTObject_impl rtcBase) {
        rtcBase = null;
    }

    public void registerModule() {
        Properties prop = new Properties(component_conf);
        final Manager manager = Manager.instance();
        manager.registerFactory(prop, new ServicesComp(), new ServicesComp());
    }
}
