// -*- Java -*-
// EchoSVC_impl.java: the servant of Sample::Echo (SampleService.idl); write each
// operation's body where it says TODO.

public class EchoSVC_impl extends Sample.EchoPOA {

    public EchoSVC_impl() {
    }

    // <rtc-template block="operations">
    // string version()
    public String version() {
        // TODO: implement version
        return "";
    }

    // long gain()
    public int gain() {
        // TODO: implement gain
        return 0;
    }

    // void gain(in long value)
    public void gain(int value) {
        // TODO: implement gain
    }

    // void reset()
    public void reset() {
        // TODO: implement reset
    }

    // string say(in string message)
    public String say(String message) {
        // TODO: implement say
        return "";
    }

    // boolean numbers(in short s, out long l, inout double d, in octet o, out char c)
    public boolean numbers(short s, org.omg.CORBA.IntHolder l, org.omg.CORBA.DoubleHolder d, byte o, org.omg.CORBA.CharHolder c) {
        // TODO: implement numbers
        return false;
    }

    // Sample::Point move(in Sample::Point from, out Sample::Point to, inout Sample::Point via)
    public Sample.Point move(Sample.Point from, Sample.PointHolder to, Sample.PointHolder via) {
        // TODO: implement move
        return null;
    }

    // Sample::Label tag(in Sample::Label item, out Sample::Label copy, inout Sample::Label edited)
    public Sample.Label tag(Sample.Label item, Sample.LabelHolder copy, Sample.LabelHolder edited) {
        // TODO: implement tag
        return null;
    }

    // Sample::NameList names(in Sample::NameList filter, out Sample::PointList points, inout Sample::NameList edited)
    public String[] names(String[] filter, Sample.PointListHolder points, Sample.NameListHolder edited) {
        // TODO: implement names
        return new String[0];
    }

    // Sample::Matrix rotate(in Sample::Matrix m, out Sample::Matrix inverse, inout Sample::Matrix scratch)
    public double[][] rotate(double[][] m, Sample.MatrixHolder inverse, Sample.MatrixHolder scratch) {
        // TODO: implement rotate
        return null;
    }

    // Sample::Mode switchMode(in Sample::Mode next, out Sample::Mode previous, inout Sample::Mode current)
    public Sample.Mode switchMode(Sample.Mode next, Sample.ModeHolder previous, Sample.ModeHolder current) {
        // TODO: implement switchMode
        return null;
    }

    // any convert(in any value, out any result, inout any both)
    public org.omg.CORBA.Any convert(org.omg.CORBA.Any value, org.omg.CORBA.AnyHolder result, org.omg.CORBA.AnyHolder both) {
        // TODO: implement convert
        return null;
    }

    // Sample::Clock exchange(in Sample::Clock other, out Sample::Clock mine, inout Sample::Clock shared)
    public Sample.Clock exchange(Sample.Clock other, Sample.ClockHolder mine, Sample.ClockHolder shared) {
        // TODO: implement exchange
        return null;
    }

    // Sample::Count tally(in Sample::Count c, out Sample::Count total)
    public int tally(int c, org.omg.CORBA.IntHolder total) {
        // TODO: implement tally
        return 0;
    }

    // RTC::TimedLong sample(in RTC::Time when, out RTC::TimedLong value)
    public RTC.TimedLong sample(RTC.Time when, RTC.TimedLongHolder value) {
        // TODO: implement sample
        return null;
    }

    // void notify(in string event)
    public void notify(String event) {
        // TODO: implement notify
    }

    // </rtc-template>
}
