// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file DocumentedComp.java
 * @brief A component with every documentation field
 */
// </rtc-template>

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.RegisterModuleFunc;
import jp.go.aist.rtm.RTC.RtcDeleteFunc;
import jp.go.aist.rtm.RTC.RtcNewFunc;
import jp.go.aist.rtm.RTC.util.Properties;

/*!
 * @class DocumentedComp
 * @brief A component with every documentation field
 */
public class DocumentedComp implements RtcNewFunc, RtcDeleteFunc, RegisterModuleFunc {

    // The component type as the manager registers it (the profile's properties).
    // <rtc-template block="module_spec">
    public static String component_conf[] = {
            "implementation_id", "DocumentedComp",
            "type_name", "DocumentedComp",
            "description", "A component with every documentation field",
            "version", "1.0.0",
            "vendor", "Example",
            "category", "Sensor",
            "activity_type", "PERIODIC",
            "kind", "DataFlowComponent",
            "max_instance", "1",
            "language", "Java",
            "lang_type", "compile",
            "conf.default.period", "0.1",
            "conf.__widget__.period", "text",
            "conf.__constraints__.period", "0.01<=x<=1.0",
            "conf.__type__.period", "double",
            ""
    };
    // </rtc-template>

    public RTObject_impl createRtc(Manager mgr) {
        return new DocumentedCompImpl(mgr);
    }

    public void deleteRtc(RTObject_impl rtcBase) {
        rtcBase = null;
    }

    public void registerModule() {
        Properties prop = new Properties(component_conf);
        final Manager manager = Manager.instance();
        manager.registerFactory(prop, new DocumentedComp(), new DocumentedComp());
    }
}
