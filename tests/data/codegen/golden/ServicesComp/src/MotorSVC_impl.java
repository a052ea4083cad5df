// -*- Java -*-
/*!
 * @file  MotorSVC_impl.java
 * @brief Servant of IDL interface Robot::Control::Motor (Robotics.idl)
 */

/*!
 * @class MotorSVC_impl
 * Servant of IDL interface Robot::Control::Motor
 */
public class MotorSVC_impl extends Robot.Control.MotorPOA {

    public MotorSVC_impl() {
        // Please add extra constructor code here.
    }

    // <rtc-template block="operations">
    // Robot::Control::Status state()
    public Robot.Control.Status state() {
        // Please insert your code here.
        return null;
    }

    // double speed()
    public double speed() {
        // Please insert your code here.
        return 0.0;
    }

    // void speed(in double value)
    public void speed(double value) {
        // Please insert your code here.
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

    // boolean move(in Robot::Geometry::Pose target, out Robot::Geometry::Pose reached, inout Robot::Geometry::Weights gains)
    public boolean move(Robot.Geometry.Pose target, Robot.Geometry.PoseHolder reached, Robot.Geometry.WeightsHolder gains) {
        // Please insert your code here.
        return false;
    }

    // Robot::Geometry::PoseList trajectory(in Robot::Geometry::Path path, out Robot::Geometry::Path smoothed, inout Robot::Geometry::PoseList buffer)
    public Robot.Geometry.Pose[] trajectory(Robot.Geometry.Path path, Robot.Geometry.PathHolder smoothed, Robot.Geometry.PoseListHolder buffer) {
        // Please insert your code here.
        return new Robot.Geometry.Pose[0];
    }

    // void report(out Robot::Control::Status code, out string text, inout Robot::Geometry::Vector3 drift)
    public void report(Robot.Control.StatusHolder code, org.omg.CORBA.StringHolder text, Robot.Geometry.Vector3Holder drift) {
        // Please insert your code here.
    }

    // RTC::TimedDoubleSeq sample(in RTC::Time at, out RTC::TimedString label)
    public RTC.TimedDoubleSeq sample(RTC.Time at, RTC.TimedStringHolder label) {
        // Please insert your code here.
        return null;
    }

    // </rtc-template>
}
