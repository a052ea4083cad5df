// -*- Java -*-
// SampleCompComp.java: a program that starts a manager and creates one SampleComp in it.

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.ModuleInitProc;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.util.Properties;

public class SampleCompComp implements ModuleInitProc {

    public void myModuleInit(Manager mgr) {
        Properties prop = new Properties(SampleComp.component_conf);
        mgr.registerFactory(prop, new SampleComp(), new SampleComp());
        RTObject_impl comp = mgr.createComponent("SampleComp");
        if (comp == null) {
            System.err.println("SampleCompComp: the manager could not create SampleComp");
            System.exit(1);
        }
    }

    public static void main(String[] args) {
        SampleCompComp init = new SampleCompComp();
        final Manager manager = Manager.init(args);
        manager.setModuleInitProc(init);
        manager.activateManager();
        manager.runManager();
    }
}
