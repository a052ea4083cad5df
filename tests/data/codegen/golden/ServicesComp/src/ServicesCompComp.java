// -*- Java -*-
// ServicesCompComp.java: a program that starts a manager and creates one ServicesComp in it.

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.ModuleInitProc;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.util.Properties;

public class ServicesCompComp implements ModuleInitProc {

    public void myModuleInit(Manager mgr) {
        Properties prop = new Properties(ServicesComp.component_conf);
        mgr.registerFactory(prop, new ServicesComp(), new ServicesComp());
        RTObject_impl comp = mgr.createComponent("ServicesComp");
        if (comp == null) {
            System.err.println("ServicesCompComp: the manager could not create ServicesComp");
            System.exit(1);
        }
    }

    public static void main(String[] args) {
        ServicesCompComp init = new ServicesCompComp();
        final Manager manager = Manager.init(args);
        manager.setModuleInitProc(init);
        manager.activateManager();
        manager.runManager();
    }
}
