// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file DataPortsComp.java
 * @brief Data ports of many types
 */
// </rtc-template>

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.RegisterModuleFunc;
import jp.go.aist.rtm.RTC.RtcDeleteFunc;
import jp.go.aist.rtm.RTC.RtcNewFunc;
import jp.go.aist.rtm.RTC.util.Properties;

/*!
 * @class DataPortsComp
 * @brief Data ports of many types
 */
public class DataPortsComp implements RtcNewFunc, RtcDeleteFunc, RegisterModuleFunc {

    // The component type as the manager registers it (the profile's properties).
    // <rtc-template block="module_spec">
    public static String component_conf[] = {
            "implementation_id", "DataPortsComp",
            "type_name", "DataPortsComp",
            "description", "Data ports of many types",
            "version", "1.0.0",
            "vendor", "Example",
            "category", "Converter",
            "activity_type", "PERIODIC",
            "kind", "DataFlowComponent",
            "max_instance", "1",
            "language", "Java",
            "lang_type", "compile",
            ""
    };
    // </rtc-template>

    public RTObject_impl createRtc(Manager mgr) {
        return new DataPortsCompImpl(mgr);
    }

    public void deleteRtc(RTObject_impl rtcBase) {
        rtcBase = null;
    }

    public void registerModule() {
        Properties prop = new Properties(component_conf);
        final Manager manager = Manager.instance();
        manager.registerFactory(prop, new DataPortsComp(), new DataPortsComp());
    }
}
