// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file DocumentedCompImpl.java
 * @brief A component with every documentation field
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
 * @class DocumentedCompImpl
 * @brief A component with every documentation field
 */
public class DocumentedCompImpl extends DataFlowComponentBase {

    public DocumentedCompImpl(Manager manager) {
        super(manager);
        // <rtc-template block="initializer">
        m_command_val = new RTC.TimedLong(new RTC.Time(0, 0), 0);
        m_command = new DataRef<RTC.TimedLong>(m_command_val);
        m_commandIn = new InPort<RTC.TimedLong>("command", m_command);
        m_status_val = new RTC.TimedString(new RTC.Time(0, 0), "");
        m_status = new DataRef<RTC.TimedString>(m_status_val);
        m_statusOut = new OutPort<RTC.TimedString>("status", m_status);
        m_ClockPortPort = new CorbaPort("ClockPort");
        // </rtc-template>
    }

    @Override
    protected ReturnCode_t onInitialize() {
        // Adds the profile's ports to the component.
        // <rtc-template block="registration">
        addInPort("command", m_commandIn);
        addOutPort("status", m_statusOut);
        m_ClockPortPort.registerConsumer("clock", "Sample::Clock", m_clockBase);
        addPort(m_ClockPortPort);
        // </rtc-template>

        // Ties each configuration parameter to its member, with its default.
        // <rtc-template block="bind_config">
        bindParameter("period", m_period, "0.1");
        // </rtc-template>
        return super.onInitialize();
    }

    @Override
    protected ReturnCode_t onFinalize() {
        return super.onFinalize();
    }

    @Override
    protected ReturnCode_t onStartup(int ec_id) {
        return super.onStartup(ec_id);
    }

    @Override
    protected ReturnCode_t onShutdown(int ec_id) {
        return super.onShutdown(ec_id);
    }

    @Override
    protected ReturnCode_t onActivated(int ec_id) {
        return super.onActivated(ec_id);
    }

    @Override
    protected ReturnCode_t onDeactivated(int ec_id) {
        return super.onDeactivated(ec_id);
    }

    @Override
    protected ReturnCode_t onAborting(int ec_id) {
        return super.onAborting(ec_id);
    }

    @Override
    protected ReturnCode_t onError(int ec_id) {
        return super.onError(ec_id);
    }

    @Override
    protected ReturnCode_t onReset(int ec_id) {
        return super.onReset(ec_id);
    }

    @Override
    protected ReturnCode_t onExecute(int ec_id) {
        return super.onExecute(ec_id);
    }

    @Override
    protected ReturnCode_t onStateUpdate(int ec_id) {
        return super.onStateUpdate(ec_id);
    }

    @Override
    protected ReturnCode_t onRateChanged(int ec_id) {
        return super.onRateChanged(ec_id);
    }

    // Configuration parameters, bound in onInitialize()
    // <rtc-template block="config_declare">
    /*!
     * Sampling period of the sensor
     * - Name: period
     * - Default: 0.1
     */
    protected DoubleHolder m_period = new DoubleHolder();
    // </rtc-template>

    // InPorts: the sample last read, its holder, and the port
    // <rtc-template block="inport_declare">
    protected RTC.TimedLong m_command_val;
    protected DataRef<RTC.TimedLong> m_command;
    protected InPort<RTC.TimedLong> m_commandIn;
    // </rtc-template>

    // OutPorts: the sample to write, its holder, and the port
    // <rtc-template block="outport_declare">
    protected RTC.TimedString m_status_val;
    protected DataRef<RTC.TimedString> m_status;
    protected OutPort<RTC.TimedString> m_statusOut;
    // </rtc-template>

    // Service ports
    // <rtc-template block="corbaport_declare">
    protected CorbaPort m_ClockPortPort;
    // </rtc-template>

    // Servants of the provided interfaces, one per interface
    // <rtc-template block="service_declare">
    // </rtc-template>

    // The required interfaces: each holds the peer's reference once its port is connected
    // <rtc-template block="consumer_declare">
    protected CorbaConsumer<Sample.Clock> m_clockBase =
        new CorbaConsumer<Sample.Clock>(Sample.Clock.class);
    protected Sample.Clock m_clock;
    // </rtc-template>
}
