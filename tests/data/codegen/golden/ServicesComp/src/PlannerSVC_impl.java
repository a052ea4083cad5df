// -*- Java -*-
// PlannerSVC_impl.java: the servant of Nav::Planner (Robotics.idl); write each
// operation's body where it says TODO.

public class PlannerSVC_impl extends Nav.PlannerPOA {

    public PlannerSVC_impl() {
    }

    // <rtc-template block="operations">
    // Robot::Control::Status state()
    public Robot.Control.Status state() {
        // TODO: implement state
        return null;
    }

    // Robot::Geometry::Path plan(in Robot::Geometry::Pose start, in Robot::Geometry::Pose goal, out Robot::Geometry::Weights costs)
    public Robot.Geometry.Path plan(Robot.Geometry.Pose start, Robot.Geometry.Pose goal, Robot.Geometry.WeightsHolder costs) {
        // TODO: implement plan
        return null;
    }

    // string name()
    public String name() {
        // TODO: implement name
        return "";
    }

    // void configure(in string key, inout string value, out string previous)
    public void configure(String key, org.omg.CORBA.StringHolder value, org.omg.CORBA.StringHolder previous) {
        // TODO: implement configure
    }

    // Robot::Geometry::Path replan(in Robot::Geometry::Path previous, inout Robot::Geometry::Vector3 offset, out unsigned long count)
    public Robot.Geometry.Path replan(Robot.Geometry.Path previous, Robot.Geometry.Vector3Holder offset, org.omg.CORBA.IntHolder count) {
        // TODO: implement replan
        return null;
    }

    // Robot::Control::Motor driver(in Robot::Control::Status wanted)
    public Robot.Control.Motor driver(Robot.Control.Status wanted) {
        // TODO: implement driver
        return null;
    }

    // void cancel(in string reason)
    public void cancel(String reason) {
        // TODO: implement cancel
    }

    // </rtc-template>
}
