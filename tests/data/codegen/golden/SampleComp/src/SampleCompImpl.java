// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file SampleCompImpl.java
 * @brief Sample component with "all" port kinds
 */
// </rtc-template>

import RTC.ReturnCode_t;
import jp.go.aist.rtm.RTC.DataFlowComponentBase;
import jp.go.aist.rtm.RTC.Manager;
import jp.go.aist.rtm.RTC.port.CorbaConsumer;
import jp.go.aist.rtm.RTC.port.CorbaPort;
import jp.go.aist.rtm.RTC.port.InPort;
import jp.go.aist.rtm.RTC.port.OutPort;
import jp.go.aist.rtm.RTC.util.*;

/*!
 * @class SampleCompImpl
 * @brief Sample component with "all" port kinds
 */
public class SampleCompImpl extends DataFlowComponentBase {

    public SampleCompImpl(Manager manager) {
        super(manager);
        // <rtc-template block="initializer">
        m_in_val = new RTC.TimedLong(new RTC.Time(0, 0), 0);
        m_in = new DataRef<RTC.TimedLong>(m_in_val);
        m_inIn = new InPort<RTC.TimedLong>("in", m_in);
        m_result_val = new RTC.TimedDouble(new RTC.Time(0, 0), 0.0);
        m_result = new DataRef<RTC.TimedDouble>(m_result_val);
        m_resultOut = new OutPort<RTC.TimedDouble>("out", m_result);
        m_EchoPortPort = new CorbaPort("EchoPort");
        m_ClockPortPort = new CorbaPort("ClockPort");
        // </rtc-template>
    }

    @Override
    protected ReturnCode_t onInitialize() {
        // Adds the profile's ports to the component.
        // <rtc-template block="registration">
        addInPort("in", m_inIn);
        addOutPort("out", m_resultOut);
        m_EchoPortPort.registerProvider("echo", "Sample::Echo", m_echo0);
        addPort(m_EchoPortPort);
        m_ClockPortPort.registerConsumer("clock", "Sample::Clock", m_clockBase);
        addPort(m_ClockPortPort);
        // </rtc-template>

        // Ties each configuration parameter to its member, with its default.
        // <rtc-template block="bind_config">
        bindParameter("gain_value", m_gain, "10");
        bindParameter("mode", m_mode, "fast");
        bindParameter("rate", m_rate, "0.5");
        // </rtc-template>
        return super.onInitialize();
    }

//    @Override
//    protected ReturnCode_t onFinalize() {
//        return super.onFinalize();
//    }

//    @Override
//    protected ReturnCode_t onStartup(int ec_id) {
//        return super.onStartup(ec_id);
//    }

//    @Override
//    protected ReturnCode_t onShutdown(int ec_id) {
//        return super.onShutdown(ec_id);
//    }

    @Override
    protected ReturnCode_t onActivated(int ec_id) {
        return super.onActivated(ec_id);
    }

//    @Override
//    protected ReturnCode_t onDeactivated(int ec_id) {
//        return super.onDeactivated(ec_id);
//    }

//    @Override
//    protected ReturnCode_t onAborting(int ec_id) {
//        return super.onAborting(ec_id);
//    }

//    @Override
//    protected ReturnCode_t onError(int ec_id) {
//        return super.onError(ec_id);
//    }

//    @Override
//    protected ReturnCode_t onReset(int ec_id) {
//        return super.onReset(ec_id);
//    }

    @Override
    protected ReturnCode_t onExecute(int ec_id) {
        return super.onExecute(ec_id);
    }

//    @Override
//    protected ReturnCode_t onStateUpdate(int ec_id) {
//        return super.onStateUpdate(ec_id);
//    }

//    @Override
//    protected ReturnCode_t onRateChanged(int ec_id) {
//        return super.onRateChanged(ec_id);
//    }

    // Configuration parameters, bound in onInitialize()
    // <rtc-template block="config_declare">
    /*!
     * Amplification
     * - Name: gain_value
     * - Default: 10
     */
    protected IntegerHolder m_gain = new IntegerHolder();
    /*!
     * 
     * - Name: mode
     * - Default: fast
     */
    protected StringHolder m_mode = new StringHolder();
    /*!
     * 
     * - Name: rate
     * - Default: 0.5
     */
    protected DoubleHolder m_rate = new DoubleHolder();
    // </rtc-template>

    // InPorts: the sample last read, its holder, and the port
    // <rtc-template block="inport_declare">
    protected RTC.TimedLong m_in_val;
    protected DataRef<RTC.TimedLong> m_in;
    protected InPort<RTC.TimedLong> m_inIn;
    // </rtc-template>

    // OutPorts: the sample to write, its holder, and the port
    // <rtc-template block="outport_declare">
    protected RTC.TimedDouble m_result_val;
    protected DataRef<RTC.TimedDouble> m_result;
    protected OutPort<RTC.TimedDouble> m_resultOut;
    // </rtc-template>

    // Service ports
    // <rtc-template block="corbaport_declare">
    protected CorbaPort m_EchoPortPort;
    protected CorbaPort m_ClockPortPort;
    // </rtc-template>

    // Servants of the provided interfaces, one per interface
    // <rtc-template block="service_declare">
    protected EchoSVC_impl m_echo0 = new EchoSVC_impl();
    // </rtc-template>

    // The required interfaces: each holds the peer's reference once its port is connected
    // <rtc-template block="consumer_declare">
    protected CorbaConsumer<Sample.Clock> m_clockBase =
        new CorbaConsumer<Sample.Clock>(Sample.Clock.class);
    protected Sample.Clock m_clock;
    // </rtc-template>
}
