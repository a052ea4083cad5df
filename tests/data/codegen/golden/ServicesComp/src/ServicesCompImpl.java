// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file ServicesCompImpl.java
 * @brief Provided and required services from a multi-module IDL
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
 * @class ServicesCompImpl
 * @brief Provided and required services from a multi-module IDL
 */
public class ServicesCompImpl extends DataFlowComponentBase {

    public ServicesCompImpl(Manager manager) {
        super(manager);
        // <rtc-template block="initializer">
        m_MotorPortPort = new CorbaPort("MotorPort");
        m_PlannerPortPort = new CorbaPort("PlannerPort");
        m_DevicePortPort = new CorbaPort("DevicePort");
        // </rtc-template>
    }

    @Override
    protected ReturnCode_t onInitialize() {
        // Adds the profile's ports to the component.
        // <rtc-template block="registration">
        m_MotorPortPort.registerProvider("motor0", "Robot::Control::Motor", m_motor);
        addPort(m_MotorPortPort);
        m_PlannerPortPort.registerProvider("planner", "Nav::Planner", m_plannerImpl);
        m_PlannerPortPort.registerConsumer("mapper", "Robot::Geometry::Mapper", m_mapperRefBase);
        addPort(m_PlannerPortPort);
        m_DevicePortPort.registerConsumer("device", "Robot::Control::Device", m_deviceBase);
        m_DevicePortPort.registerConsumer("driver", "Robot::Control::Motor", m_driverBase);
        addPort(m_DevicePortPort);
        // </rtc-template>

        // Ties each configuration parameter to its member, with its default.
        // <rtc-template block="bind_config">
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
    // </rtc-template>

    // InPorts: the sample last read, its holder, and the port
    // <rtc-template block="inport_declare">
    // </rtc-template>

    // OutPorts: the sample to write, its holder, and the port
    // <rtc-template block="outport_declare">
    // </rtc-template>

    // Service ports
    // <rtc-template block="corbaport_declare">
    protected CorbaPort m_MotorPortPort;
    protected CorbaPort m_PlannerPortPort;
    protected CorbaPort m_DevicePortPort;
    // </rtc-template>

    // Servants of the provided interfaces, one per interface
    // <rtc-template block="service_declare">
    protected MotorSVC_impl m_motor = new MotorSVC_impl();
    protected PlannerSVC_impl m_plannerImpl = new PlannerSVC_impl();
    // </rtc-template>

    // The required interfaces: each holds the peer's reference once its port is connected
    // <rtc-template block="consumer_declare">
    protected CorbaConsumer<Robot.Geometry.Mapper> m_mapperRefBase =
        new CorbaConsumer<Robot.Geometry.Mapper>(Robot.Geometry.Mapper.class);
    protected Robot.Geometry.Mapper m_mapperRef;
    protected CorbaConsumer<Robot.Control.Device> m_deviceBase =
        new CorbaConsumer<Robot.Control.Device>(Robot.Control.Device.class);
    protected Robot.Control.Device m_device;
    protected CorbaConsumer<Robot.Control.Motor> m_driverBase =
        new CorbaConsumer<Robot.Control.Motor>(Robot.Control.Motor.class);
    protected Robot.Control.Motor m_driver;
    // </rtc-template>
}
