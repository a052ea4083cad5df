// -*- Java -*-
// <rtc-template block="description">
/*!
 * @file DataPortsCompImpl.java
 * @brief Data ports of many types
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
 * @class DataPortsCompImpl
 * @brief Data ports of many types
 */
public class DataPortsCompImpl extends DataFlowComponentBase {

    public DataPortsCompImpl(Manager manager) {
        super(manager);
        // <rtc-template block="initializer">
        m_in_long_val = new RTC.TimedLong(new RTC.Time(0, 0), 0);
        m_in_long = new DataRef<RTC.TimedLong>(m_in_long_val);
        m_in_longIn = new InPort<RTC.TimedLong>("in_long", m_in_long);
        m_doubles_val = new RTC.TimedDoubleSeq(new RTC.Time(0, 0), new double[0]);
        m_doubles = new DataRef<RTC.TimedDoubleSeq>(m_doubles_val);
        m_doublesIn = new InPort<RTC.TimedDoubleSeq>("in_doubles", m_doubles);
        m_in_text_val = new RTC.TimedString(new RTC.Time(0, 0), "");
        m_in_text = new DataRef<RTC.TimedString>(m_in_text_val);
        m_in_textIn = new InPort<RTC.TimedString>("in_text", m_in_text);
        m_in_pose_val = new RTC.TimedPose2D(new RTC.Time(0, 0), new RTC.Pose2D(new RTC.Point2D(0.0, 0.0), 0.0));
        m_in_pose = new DataRef<RTC.TimedPose2D>(m_in_pose_val);
        m_in_poseIn = new InPort<RTC.TimedPose2D>("in_pose", m_in_pose);
        m_image_val = new RTC.CameraImage(new RTC.Time(0, 0), (short)0, (short)0, (short)0, "", 0.0, new byte[0]);
        m_image = new DataRef<RTC.CameraImage>(m_image_val);
        m_imageIn = new InPort<RTC.CameraImage>("in_image", m_image);
        m_out_wide_val = new RTC.TimedWString(new RTC.Time(0, 0), "");
        m_out_wide = new DataRef<RTC.TimedWString>(m_out_wide_val);
        m_out_wideOut = new OutPort<RTC.TimedWString>("out_wide", m_out_wide);
        m_out_octets_val = new RTC.TimedOctetSeq(new RTC.Time(0, 0), new byte[0]);
        m_out_octets = new DataRef<RTC.TimedOctetSeq>(m_out_octets_val);
        m_out_octetsOut = new OutPort<RTC.TimedOctetSeq>("out_octets", m_out_octets);
        m_out_flags_val = new RTC.TimedBooleanSeq(new RTC.Time(0, 0), new boolean[0]);
        m_out_flags = new DataRef<RTC.TimedBooleanSeq>(m_out_flags_val);
        m_out_flagsOut = new OutPort<RTC.TimedBooleanSeq>("out_flags", m_out_flags);
        m_out_vector_val = new RTC.TimedVector3D(new RTC.Time(0, 0), new RTC.Vector3D(0.0, 0.0, 0.0));
        m_out_vector = new DataRef<RTC.TimedVector3D>(m_out_vector_val);
        m_out_vectorOut = new OutPort<RTC.TimedVector3D>("out_vector", m_out_vector);
        m_ranges_val = new RTC.RangeData(new RTC.Time(0, 0), new double[0], new RTC.RangerGeometry(new RTC.Geometry3D(new RTC.Pose3D(new RTC.Point3D(0.0, 0.0, 0.0), new RTC.Orientation3D(0.0, 0.0, 0.0)), new RTC.Size3D(0.0, 0.0, 0.0)), new RTC.Geometry3D[0]), new RTC.RangerConfig(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0));
        m_ranges = new DataRef<RTC.RangeData>(m_ranges_val);
        m_rangesOut = new OutPort<RTC.RangeData>("out_range", m_ranges);
        m_out_cloud_val = new RTC.PointCloud(new RTC.Time(0, 0), new RTC.PointCloudPoint[0]);
        m_out_cloud = new DataRef<RTC.PointCloud>(m_out_cloud_val);
        m_out_cloudOut = new OutPort<RTC.PointCloud>("out_cloud", m_out_cloud);
        // </rtc-template>
    }

    @Override
    protected ReturnCode_t onInitialize() {
        // Adds the profile's ports to the component.
        // <rtc-template block="registration">
        addInPort("in_long", m_in_longIn);
        addInPort("in_doubles", m_doublesIn);
        addInPort("in_text", m_in_textIn);
        addInPort("in_pose", m_in_poseIn);
        addInPort("in_image", m_imageIn);
        addOutPort("out_wide", m_out_wideOut);
        addOutPort("out_octets", m_out_octetsOut);
        addOutPort("out_flags", m_out_flagsOut);
        addOutPort("out_vector", m_out_vectorOut);
        addOutPort("out_range", m_rangesOut);
        addOutPort("out_cloud", m_out_cloudOut);
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

    @Override
    protected ReturnCode_t onActivated(int ec_id) {
        return super.onActivated(ec_id);
    }

    @Override
    protected ReturnCode_t onDeactivated(int ec_id) {
        return super.onDeactivated(ec_id);
    }

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
    protected RTC.TimedLong m_in_long_val;
    protected DataRef<RTC.TimedLong> m_in_long;
    protected InPort<RTC.TimedLong> m_in_longIn;
    protected RTC.TimedDoubleSeq m_doubles_val;
    protected DataRef<RTC.TimedDoubleSeq> m_doubles;
    protected InPort<RTC.TimedDoubleSeq> m_doublesIn;
    protected RTC.TimedString m_in_text_val;
    protected DataRef<RTC.TimedString> m_in_text;
    protected InPort<RTC.TimedString> m_in_textIn;
    protected RTC.TimedPose2D m_in_pose_val;
    protected DataRef<RTC.TimedPose2D> m_in_pose;
    protected InPort<RTC.TimedPose2D> m_in_poseIn;
    protected RTC.CameraImage m_image_val;
    protected DataRef<RTC.CameraImage> m_image;
    protected InPort<RTC.CameraImage> m_imageIn;
    // </rtc-template>

    // OutPorts: the sample to write, its holder, and the port
    // <rtc-template block="outport_declare">
    protected RTC.TimedWString m_out_wide_val;
    protected DataRef<RTC.TimedWString> m_out_wide;
    protected OutPort<RTC.TimedWString> m_out_wideOut;
    protected RTC.TimedOctetSeq m_out_octets_val;
    protected DataRef<RTC.TimedOctetSeq> m_out_octets;
    protected OutPort<RTC.TimedOctetSeq> m_out_octetsOut;
    protected RTC.TimedBooleanSeq m_out_flags_val;
    protected DataRef<RTC.TimedBooleanSeq> m_out_flags;
    protected OutPort<RTC.TimedBooleanSeq> m_out_flagsOut;
    protected RTC.TimedVector3D m_out_vector_val;
    protected DataRef<RTC.TimedVector3D> m_out_vector;
    protected OutPort<RTC.TimedVector3D> m_out_vectorOut;
    protected RTC.RangeData m_ranges_val;
    protected DataRef<RTC.RangeData> m_ranges;
    protected OutPort<RTC.RangeData> m_rangesOut;
    protected RTC.PointCloud m_out_cloud_val;
    protected DataRef<RTC.PointCloud> m_out_cloud;
    protected OutPort<RTC.PointCloud> m_out_cloudOut;
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
