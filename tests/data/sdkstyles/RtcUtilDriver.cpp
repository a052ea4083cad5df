// SPDX-License-Identifier: MIT
// A test driver as OpenRTM-aist users write them: finds two components in a name server with
// CorbaNaming, connects their ports by name, activates them and changes a configuration parameter
// with CORBA_RTCUtil, and prints what it saw. Arguments: NAME_SERVER SOURCE_PATH SINK_PATH
// (paths in the name server, e.g. host.host_cxt/Source0.rtc).
#include <rtm/CORBA_RTCUtil.h>
#include <rtm/CorbaConsumer.h>
#include <rtm/CorbaNaming.h>
#include <rtm/NVUtil.h>

#include <chrono>
#include <iostream>
#include <string>
#include <thread>

namespace {
RTC::RTObject_ptr find(RTC::CorbaNaming &naming, const char *path)
{
    return RTC::RTObject::_narrow(naming.resolve(path));
}

void printState(const char *what, RTC::RTObject_ptr rtc)
{
    RTC::LifeCycleState state = RTC::CREATED_STATE;
    const bool known = CORBA_RTCUtil::get_state(state, rtc);
    std::cout << "RtcUtilDriver state " << what << " " << (known ? int(state) : -1) << " active "
              << CORBA_RTCUtil::is_in_active(rtc) << std::endl;
}
} // namespace

int main(int argc, char **argv)
{
    if (argc != 4) {
        std::cerr << "usage: RtcUtilDriver NAME_SERVER SOURCE_PATH SINK_PATH" << std::endl;
        return 2;
    }
    CORBA::ORB_var orb = CORBA::ORB_init(argc, argv);
    RTC::CorbaNaming naming(orb, argv[1]);
    RTC::RTObject_var source = find(naming, argv[2]);
    RTC::RTObject_var sink = find(naming, argv[3]);
    if (CORBA::is_nil(source) || CORBA::is_nil(sink) || !CORBA_RTCUtil::is_existing(source)) {
        std::cerr << "RtcUtilDriver: components not found" << std::endl;
        return 1;
    }
    for (const std::string &name : CORBA_RTCUtil::get_outport_names(source))
        std::cout << "RtcUtilDriver outport " << name << std::endl;
    for (const std::string &name : CORBA_RTCUtil::get_inport_names(sink))
        std::cout << "RtcUtilDriver inport " << name << std::endl;

    coil::Properties prop;
    prop["dataport.dataflow_type"] = "push";
    prop["dataport.interface_type"] = "corba_cdr";
    prop["dataport.subscription_type"] = "flush";
    const std::string sourcePort = CORBA_RTCUtil::get_outport_names(source).at(0);
    const std::string sinkPort = CORBA_RTCUtil::get_inport_names(sink).at(0);
    RTC::ReturnCode_t ret = CORBA_RTCUtil::connect_by_name("driven", prop, source, sourcePort, sink, sinkPort);
    std::cout << "RtcUtilDriver connect " << ret << std::endl;
    RTC::PortService_var port = CORBA_RTCUtil::get_port_by_name(source, sourcePort);
    for (const std::string &name : CORBA_RTCUtil::get_connector_names(port))
        std::cout << "RtcUtilDriver connector " << name << std::endl;

    std::cout << "RtcUtilDriver rate " << CORBA_RTCUtil::get_current_rate(source, 0) << std::endl;
    CORBA_RTCUtil::set_current_rate(source, 0, 50.0);
    std::cout << "RtcUtilDriver rate " << CORBA_RTCUtil::get_current_rate(source, 0) << std::endl;

    ret = CORBA_RTCUtil::activate(sink);
    ret = ret == RTC::RTC_OK ? CORBA_RTCUtil::activate(source) : ret;
    std::cout << "RtcUtilDriver activate " << ret << std::endl;
    for (int i = 0; i < 200 && !CORBA_RTCUtil::is_in_active(source); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    printState("source", source);

    std::cout << "RtcUtilDriver config " << CORBA_RTCUtil::get_active_configuration_name(sink) << std::endl;
    CORBA_RTCUtil::deactivate(source);
    CORBA_RTCUtil::deactivate(sink);
    for (int i = 0; i < 200 && CORBA_RTCUtil::is_in_active(source); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    printState("source", source);
    ret = CORBA_RTCUtil::disconnect_connector_name(port, "driven");
    std::cout << "RtcUtilDriver disconnect " << ret << std::endl;
    orb->destroy();
    return 0;
}
