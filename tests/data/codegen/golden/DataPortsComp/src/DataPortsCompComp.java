// -*- Java -*-
// DataPortsCompComp.java: a program that starts a manager and creates one DataPortsComp in it.

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.ModuleInitProc;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.util.Properties;

public class DataPortsCompComp implements ModuleInitProc {

    public void myModuleInit(Manager mgr) {
        Properties prop = new Properties(DataPortsComp.component_conf);
        mgr.registerFactory(prop, new DataPortsComp(), new DataPortsComp());
        RTObject_impl comp = mgr.createComponent("DataPortsComp");
        if (comp == null) {
            System.err.println("DataPortsCompComp: the manager could not create DataPortsComp");
            System.exit(1);
        }
    }

    public static void main(String[] args) {
        DataPortsCompComp init = new DataPortsCompComp();
        final Manager manager = Manager.init(args);
        manager.setModuleInitProc(init);
        manager.activateManager();
        manager.runManager();
    }
}
