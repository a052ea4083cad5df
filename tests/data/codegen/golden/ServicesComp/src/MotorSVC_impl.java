// -*- Java -*-
// MotorSVC_impl.java: the servant of Robot::Control::Motor (Robotics.idl); write each
// operation's body where it says TODO.

public class MotorSVC_impl extends Robot.Control.MotorPOA {

    public MotorSVC_impl() {
    }

    // <rtc-template block="operations">
    // Robot::Control::Status state()
    public Robot.Control.Status state() {
        // TODO: implement state
        return null;
    }

    // double speed()
    public double speed() {
        // TODO: implement speed
        return 0.0;
    }

    // void speed(in double value)
    public void speed(double value) {
        // TODO: implement speed
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

    // boolean move(in Robot::Geometry::Pose target, out Robot::Geometry::Pose reached, inout Robot::Geometry::Weights gains)
    public boolean move(Robot.Geometry.Pose target, Robot.Geometry.PoseHolder reached, Robot.Geometry.WeightsHolder gains) {
        // TODO: implement move
        return false;
    }

    // Robot::Geometry::PoseList trajectory(in Robot::Geometry::Path path, out Robot::Geometry::Path smoothed, inout Robot::Geometry::PoseList buffer)
    public Robot.Geometry.Pose[] trajectory(Robot.Geometry.Path path, Robot.Geometry.PathHolder smoothed, Robot.Geometry.PoseListHolder buffer) {
        // TODO: implement trajectory
        return new Robot.Geometry.Pose[0];
    }

    // void report(out Robot::Control::Status code, out string text, inout Robot::Geometry::Vector3 drift)
    public void report(Robot.Control.StatusHolder code, org.omg.CORBA.StringHolder text, Robot.Geometry.Vector3Holder drift) {
        // TODO: implement report
    }

    // RTC::TimedDoubleSeq sample(in RTC::Time at, out RTC::TimedString label)
    public RTC.TimedDoubleSeq sample(RTC.Time at, RTC.TimedStringHolder label) {
        // TODO: implement sample
        return null;
    }

    // </rtc-template>
}
