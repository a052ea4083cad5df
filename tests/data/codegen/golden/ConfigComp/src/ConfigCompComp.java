// -*- Java -*-
// ConfigCompComp.java: a program that starts a manager and creates one ConfigComp in it.

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.ModuleInitProc;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.util.Properties;

public class ConfigCompComp implements ModuleInitProc {

    public void myModuleInit(Manager mgr) {
        Properties prop = new Properties(ConfigComp.component_conf);
        mgr.registerFactory(prop, new ConfigComp(), new ConfigComp());
        RTObject_impl comp = mgr.createComponent("ConfigComp");
        if (comp == null) {
            System.err.println("ConfigCompComp: the manager could not create ConfigComp");
            System.exit(1);
        }
    }

    public static void main(String[] args) {
        ConfigCompComp init = new ConfigCompComp();
        final Manager manager = Manager.init(args);
        manager.setModuleInitProc(init);
        manager.activateManager();
        manager.runManager();
    }
}
