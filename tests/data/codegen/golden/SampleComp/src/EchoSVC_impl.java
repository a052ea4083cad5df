// -*- Java -*-
/*!
 * @file  EchoSVC_impl.java
 * @brief Servant of IDL interface Sample::Echo (SampleService.idl)
 */

/*!
 * @class EchoSVC_impl
 * Servant of IDL interface Sample::Echo
 */
public class EchoSVC_impl extends Sample.EchoPOA {

    public EchoSVC_impl() {
        // Please add extra constructor code here.
    }

    // <rtc-template block="operations">
    // string version()
    public String version() {
        // Please insert your code here.
        return "";
    }

    // long gain()
    public int gain() {
        // Please insert your code here.
        return 0;
    }

    // void gain(in long value)
    public void gain(int value) {
        // Please insert your code here.
    }

    // void reset()
    public void reset() {
        // Please insert your code here.
    }

    // string say(in string message)
    public String say(String message) {
        // Please insert your code here.
        return "";
    }

    // boolean numbers(in short s, out long l, inout double d, in octet o, out char c)
    public boolean numbers(short s, org.omg.CORBA.IntHolder l, org.omg.CORBA.DoubleHolder d, byte o, org.omg.CORBA.CharHolder c) {
        // Please insert your code here.
        return false;
    }

    // Sample::Point move(in Sample::Point from, out Sample::Point to, inout Sample::Point via)
    public Sample.Point move(Sample.Point from, Sample.PointHolder to, Sample.PointHolder via) {
        // Please insert your code here.
        return null;
    }

    // Sample::Label tag(in Sample::Label item, out Sample::Label copy, inout Sample::Label edited)
    public Sample.Label tag(Sample.Label item, Sample.LabelHolder copy, Sample.LabelHolder edited) {
        // Please insert your code here.
        return null;
    }

    // Sample::NameList names(in Sample::NameList filter, out Sample::PointList points, inout Sample::NameList edited)
    public String[] names(String[] filter, Sample.PointListHolder points, Sample.NameListHolder edited) {
        // Please insert your code here.
        return new String[0];
    }

    // Sample::Matrix rotate(in Sample::Matrix m, out Sample::Matrix inverse, inout Sample::Matrix scratch)
    public double[][] rotate(double[][] m, Sample.MatrixHolder inverse, Sample.MatrixHolder scratch) {
        // Please insert your code here.
        return null;
    }

    // Sample::Mode switchMode(in Sample::Mode next, out Sample::Mode previous, inout Sample::Mode current)
    public Sample.Mode switchMode(Sample.Mode next, Sample.ModeHolder previous, Sample.ModeHolder current) {
        // Please insert your code here.
        return null;
    }

    // any convert(in any value, out any result, inout any both)
    public org.omg.CORBA.Any convert(org.omg.CORBA.Any value, org.omg.CORBA.AnyHolder result, org.omg.CORBA.AnyHolder both) {
        // Please insert your code here.
        return null;
    }

    // Sample::Clock exchange(in Sample::Clock other, out Sample::Clock mine, inout Sample::Clock shared)
    public Sample.Clock exchange(Sample.Clock other, Sample.ClockHolder mine, Sample.ClockHolder shared) {
        // Please insert your code here.
        return null;
    }

    // Sample::Count tally(in Sample::Count c, out Sample::Count total)
    public int tally(int c, org.omg.CORBA.IntHolder total) {
        // Please insert your code here.
        return 0;
    }

    // RTC::TimedLong sample(in RTC::Time when, out RTC::TimedLong value)
    public RTC.TimedLong sample(RTC.Time when, RTC.TimedLongHolder value) {
        // Please insert your code here.
        return null;
    }

    // void notify(in string event)
    public void notify(String event) {
        // Please insert your code here.
    }

    // </rtc-template>
}
