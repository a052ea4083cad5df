// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file ConfigCompImpl.java
 * @brief Configuration with every widget and constraint
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
 * @class ConfigCompImpl
 * @brief Configuration with every widget and constraint
 */
public class ConfigCompImpl extends DataFlowComponentBase {

    public ConfigCompImpl(Manager manager) {
        super(manager);
        // <rtc-template block="initializer">
        m_in_val = new RTC.TimedDouble(new RTC.Time(0, 0), 0.0);
        m_in = new DataRef<RTC.TimedDouble>(m_in_val);
        m_inIn = new InPort<RTC.TimedDouble>("in", m_in);
        m_out_val = new RTC.TimedDouble(new RTC.Time(0, 0), 0.0);
        m_out = new DataRef<RTC.TimedDouble>(m_out_val);
        m_outOut = new OutPort<RTC.TimedDouble>("out", m_out);
        // </rtc-template>
    }

    @Override
    protected ReturnCode_t onInitialize() {
        // Adds the profile's ports to the component.
        // <rtc-template block="registration">
        addInPort("in", m_inIn);
        addOutPort("out", m_outOut);
        // </rtc-template>

        // Ties each configuration parameter to its member, with its default.
        // <rtc-template block="bind_config">
        bindParameter("label", m_label, "hello world");
        bindParameter("gain", m_gainValue, "1.5");
        bindParameter("count", m_count, "3");
        bindParameter("threshold", m_threshold, "10");
        bindParameter("limit", m_limit, "5");
        bindParameter("mode", m_mode, "fast");
        bindParameter("features", m_features, "camera,lidar");
        bindParameter("order", m_order, "first,second");
        bindParameter("weights", m_weights, "0.5,1.5");
        bindParameter("scale", m_scale, "0.25");
        bindParameter("target", m_target, "42");
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

//    @Override
//    protected ReturnCode_t onActivated(int ec_id) {
//        return super.onActivated(ec_id);
//    }

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
     * 
     * - Name: label
     * - Default: hello world
     */
    protected StringHolder m_label = new StringHolder();
    /*!
     * 
     * - Name: gain
     * - Default: 1.5
     */
    protected DoubleHolder m_gainValue = new DoubleHolder();
    /*!
     * 
     * - Name: count
     * - Default: 3
     */
    protected IntegerHolder m_count = new IntegerHolder();
    /*!
     * 
     * - Name: threshold
     * - Default: 10
     */
    protected LongHolder m_threshold = new LongHolder();
    /*!
     * 
     * - Name: limit
     * - Default: 5
     */
    protected ShortHolder m_limit = new ShortHolder();
    /*!
     * 
     * - Name: mode
     * - Default: fast
     */
    protected StringHolder m_mode = new StringHolder();
    /*!
     * 
     * - Name: features
     * - Default: camera,lidar
     */
    protected StringHolder m_features = new StringHolder();
    /*!
     * 
     * - Name: order
     * - Default: first,second
     */
    protected StringVectorHolder m_order = new StringVectorHolder();
    /*!
     * 
     * - Name: weights
     * - Default: 0.5,1.5
     */
    protected DoubleVectorHolder m_weights = new DoubleVectorHolder();
    /*!
     * 
     * - Name: scale
     * - Default: 0.25
     */
    protected FloatHolder m_scale = new FloatHolder();
    /*!
     * 
     * - Name: target
     * - Default: 42
     */
    protected LongHolder m_target = new LongHolder();
    // </rtc-template>

    // InPorts: the sample last read, its holder, and the port
    // <rtc-template block="inport_declare">
    protected RTC.TimedDouble m_in_val;
    protected DataRef<RTC.TimedDouble> m_in;
    protected InPort<RTC.TimedDouble> m_inIn;
    // </rtc-template>

    // OutPorts: the sample to write, its holder, and the port
    // <rtc-template block="outport_declare">
    protected RTC.TimedDouble m_out_val;
    protected DataRef<RTC.TimedDouble> m_out;
    protected OutPort<RTC.TimedDouble> m_outOut;
    // </rtc-template>

    // Service ports
    // <rtc-template block="corbaport_declare">
    // </rtc-template>

    // Servants of the provided interfaces, one per interface
    // <rtc-template block="service_declare">
    // </rtc-template>

    // The required interfaces: each holds the peer's reference once its port is connected
    // <rtc-template block="consumer_declare">
    // </rtc-template>
}
