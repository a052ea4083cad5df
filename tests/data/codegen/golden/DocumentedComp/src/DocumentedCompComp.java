// -*- Java -*-
// DocumentedCompComp.java: a program that starts a manager and creates one DocumentedComp in it.

import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.ModuleInitProc;
import jp.go.aist.rtm.RTC.RTObject_impl;
import jp.go.aist.rtm.RTC.util.Properties;

public class DocumentedCompComp implements ModuleInitProc {

    public void myModuleInit(Manager mgr) {
        Properties prop = new Properties(DocumentedComp.component_conf);
        mgr.registerFactory(prop, new DocumentedComp(), new DocumentedComp());
        RTObject_impl comp = mgr.createComponent("DocumentedComp");
        if (comp == null) {
            System.err.println("DocumentedCompComp: the manager could not create DocumentedComp");
            System.exit(1);
        }
    }

    public static void main(String[] args) {
        DocumentedCompComp init = new DocumentedCompComp();
        final Manager manager = Manager.init(args);
        manager.setModuleInitProc(init);
        manager.activateManager();
        manager.runManager();
    }
}
