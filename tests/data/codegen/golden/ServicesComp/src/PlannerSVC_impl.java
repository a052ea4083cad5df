// -*- Java -*-
/*!
 * @file  PlannerSVC_impl.java
 * @brief Servant of IDL interface Nav::Planner (Robotics.idl)
 */

/*!
 * @class PlannerSVC_impl
 * Servant of IDL interface Nav::Planner
 */
public class PlannerSVC_impl extends Nav.PlannerPOA {

    public PlannerSVC_impl() {
        // Please add extra constructor code here.
    }

    // <rtc-template block="operations">
    // Robot::Control::Status state()
    public Robot.Control.Status state() {
        // Please insert your code here.
        return null;
    }

    // Robot::Geometry::Path plan(in Robot::Geometry::Pose start, in Robot::Geometry::Pose goal, out Robot::Geometry::Weights costs)
    public Robot.Geometry.Path plan(Robot.Geometry.Pose start, Robot.Geometry.Pose goal, Robot.Geometry.WeightsHolder costs) {
        // Please insert your code here.
        return null;
    }

    // string name()
    public String name() {
        // Please insert your code here.
        return "";
    }

    // void configure(in string key, inout string value, out string previous)
    public void configure(String key, org.omg.CORBA.StringHolder value, org.omg.CORBA.StringHolder previous) {
        // Please insert your code here.
    }

    // Robot::Geometry::Path replan(in Robot::Geometry::Path previous, inout Robot::Geometry::Vector3 offset, out unsigned long count)
    public Robot.Geometry.Path replan(Robot.Geometry.Path previous, Robot.Geometry.Vector3Holder offset, org.omg.CORBA.IntHolder count) {
        // Please insert your code here.
        return null;
    }

    // Robot::Control::Motor driver(in Robot::Control::Status wanted)
    public Robot.Control.Motor driver(Robot.Control.Status wanted) {
        // Please insert your code here.
        return null;
    }

    // void cancel(in string reason)
    public void cancel(String reason) {
        // Please insert your code here.
    }

    // </rtc-template>
}
