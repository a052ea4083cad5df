// SPDX-License-Identifier: MIT
// Uses a type from each extension IDL file and from ExtendedFsmService.idl: a camera image and joint
// positions go from an OutPort to an InPort of the same component over a push connection (so they are
// marshalled as CDR by the SDK's port code), and each value also makes a round trip through a
// CORBA::Any. Prints what arrived.
#include "CameraCommonInterfaceSkel.h"
#include "ManipulatorCommonInterface_DataTypesSkel.h"
#include "ManipulatorCommonInterface_MiddleSkel.h"
#include <rtm/DataFlowComponentBase.h>
#include <rtm/InPort.h>
#include <rtm/Manager.h>
#include <rtm/OutPort.h>
#include <rtm/idl/ExtendedFsmServiceSkel.h>

#include <iostream>
#include <sstream>
#include <string>

static const char* probe_spec[] =
  {
    "implementation_id", "ExtensionProbe",
    "type_name",         "ExtensionProbe",
    "description",       "Sends extension IDL types to itself",
    "version",           "1.0.0",
    "vendor",            "RTStudioTests",
    "category",          "Probe",
    "activity_type",     "PERIODIC",
    "kind",              "DataFlowComponent",
    "max_instance",      "1",
    "language",          "C++",
    "lang_type",         "compile",
    ""
  };

class ExtensionProbe
  : public RTC::DataFlowComponentBase
{
public:
  explicit ExtensionProbe(RTC::Manager* manager)
    : RTC::DataFlowComponentBase(manager),
      m_imageOut("image", m_image), m_imageIn("imageIn", m_imageRead),
      m_jointsOut("joints", m_joints), m_jointsIn("jointsIn", m_jointsRead)
  {
  }

  RTC::ReturnCode_t onInitialize() override
  {
    addOutPort("image", m_imageOut);
    addInPort("imageIn", m_imageIn);
    addOutPort("joints", m_jointsOut);
    addInPort("jointsIn", m_jointsIn);
    return RTC::RTC_OK;
  }

  Img::TimedCameraImage m_image;
  Img::TimedCameraImage m_imageRead;
  RTC::OutPort<Img::TimedCameraImage> m_imageOut;
  RTC::InPort<Img::TimedCameraImage> m_imageIn;
  JARA_ARM::TimedJointPos m_joints;
  JARA_ARM::TimedJointPos m_jointsRead;
  RTC::OutPort<JARA_ARM::TimedJointPos> m_jointsOut;
  RTC::InPort<JARA_ARM::TimedJointPos> m_jointsIn;
};

static RTC::PortService_ptr findPort(RTC::RTObject_ptr self, const std::string& name)
{
  RTC::PortServiceList_var ports = self->get_ports();
  for (CORBA::ULong i = 0; i < ports->length(); ++i)
    {
      RTC::PortProfile_var profile = ports[i]->get_port_profile();
      if (std::string(profile->name) == "ExtensionProbe0." + name)
        return RTC::PortService::_duplicate(ports[i]);
    }
  return RTC::PortService::_nil();
}

static bool connect(RTC::RTObject_ptr self, const char* out, const char* in, const char* dataType)
{
  RTC::PortService_var outPort = findPort(self, out);
  RTC::PortService_var inPort = findPort(self, in);
  if (CORBA::is_nil(outPort) || CORBA::is_nil(inPort))
    return false;
  RTC::ConnectorProfile profile;
  profile.name = CORBA::string_dup(out);
  profile.connector_id = CORBA::string_dup("");
  profile.ports.length(2);
  profile.ports[0] = RTC::PortService::_duplicate(outPort);
  profile.ports[1] = RTC::PortService::_duplicate(inPort);
  const char* const pairs[][2] = {{"dataport.interface_type", "corba_cdr"},
                                  {"dataport.dataflow_type", "push"},
                                  {"dataport.subscription_type", "flush"},
                                  {"dataport.data_type", dataType}};
  profile.properties.length(4);
  for (CORBA::ULong i = 0; i < 4; ++i)
    {
      profile.properties[i].name = CORBA::string_dup(pairs[i][0]);
      profile.properties[i].value <<= pairs[i][1];
    }
  return outPort->connect(profile) == RTC::RTC_OK;
}

template <class T>
static bool throughAny(const T& value, T& back)
{
  CORBA::Any any;
  any <<= value;
  const T* extracted = 0;
  if (!(any >>= extracted))
    return false;
  back = *extracted;
  return true;
}

int main()
{
  static char program[] = "ExtensionProbe";
  static char o[] = "-o";
  static char naming[] = "naming.enable:NO";
  static char master[] = "corba.master_manager:";
  static char endpoint[] = "corba.endpoints:127.0.0.1:";
  static char logging[] = "logger.enable:NO";
  char* argv[] = {program, o, naming, o, master, o, endpoint, o, logging, 0};
  RTC::Manager* manager = RTC::Manager::init(9, argv);
  manager->activateManager();
  manager->runManager(true);
  coil::Properties profile(probe_spec);
  manager->registerFactory(profile, RTC::Create<ExtensionProbe>, RTC::Delete<ExtensionProbe>);
  ExtensionProbe* probe = dynamic_cast<ExtensionProbe*>(manager->createComponent("ExtensionProbe"));
  if (probe == 0)
    return 1;
  RTC::RTObject_var self = probe->getObjRef();
  if (!connect(self, "image", "imageIn", "IDL:Img/TimedCameraImage:1.0")
      || !connect(self, "joints", "jointsIn", "IDL:JARA_ARM/TimedJointPos:1.0"))
    return 2;

  probe->m_image.data.image.width = 4;
  probe->m_image.data.image.height = 2;
  probe->m_image.data.image.format = Img::CF_GRAY;
  probe->m_image.data.image.raw_data.length(8);
  for (CORBA::ULong i = 0; i < 8; ++i)
    probe->m_image.data.image.raw_data[i] = static_cast<CORBA::Octet>(i * 10);
  probe->m_image.data.extrinsic[3][3] = 1.0;
  probe->m_image.error_code = 0;
  probe->m_joints.pos.length(3);
  probe->m_joints.pos[0] = 0.5;
  probe->m_joints.pos[1] = -1.25;
  probe->m_joints.pos[2] = 2.0;
  probe->m_imageOut.write();
  probe->m_jointsOut.write();
  if (!probe->m_imageIn.isNew() || !probe->m_jointsIn.isNew())
    return 3;
  probe->m_imageIn.read();
  probe->m_jointsIn.read();

  Img::TimedCameraImage image;
  JARA_ARM::TimedJointPos joints;
  RTC::FsmStructure fsm;
  fsm.name = CORBA::string_dup("arm");
  fsm.event_profiles.length(1);
  fsm.event_profiles[0].name = CORBA::string_dup("grip");
  fsm.event_profiles[0].data_type = CORBA::string_dup("IDL:JARA_ARM/TimedJointPos:1.0");
  RTC::FsmStructure fsmBack;
  if (!throughAny(probe->m_imageRead, image) || !throughAny(probe->m_jointsRead, joints)
      || !throughAny(fsm, fsmBack))
    return 4;

  const Img::ImageData& data = image.data.image;
  std::ostringstream out;
  out << "extension " << data.width << "x" << data.height << " gray=" << (data.format == Img::CF_GRAY)
      << " px7=" << int(data.raw_data[7]) << " m33=" << image.data.extrinsic[3][3] << " joints=" << joints.pos.length()
      << " j1=" << joints.pos[1] << " ok=" << JARA_ARM::OK << " " << fsmBack.name << ":"
      << fsmBack.event_profiles[0].name;
  manager->terminate();
  manager->join();
  std::cout << out.str() << std::endl;
  return 0;
}
