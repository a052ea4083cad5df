// SPDX-License-Identifier: MIT
// Checks the wire contract of the project's IDL through the omniidl-generated C++ code:
// repository ids, enumerator order, struct member order and operation
// signatures (parameter modes) that OpenRTM-aist 2.x peers rely on.

#include <BasicDataType.hh>
#include <CameraCommonInterface.hh>
#include <ComponentObserver.hh>
#include <DataPort.hh>
#include <DataPortUDP.hh>
#include <DataPort_OpenRTM.hh>
#include <ExtendedFsmService.hh>
#include <ExtendedDataTypes.hh>
#include <InterfaceDataTypes.hh>
#include <Manager.hh>
#include <ManipulatorCommonInterface_Common.hh>
#include <ManipulatorCommonInterface_DataTypes.hh>
#include <ManipulatorCommonInterface_Middle.hh>
#include <OpenRTM.hh>
#include <RTC.hh>
#include <RTStudioManager.hh>
#include <SDOPackage.hh>
#include <SharedMemory.hh>
#include <SimpleService.hh>

#include <QDir>
#include <QFile>
#include <QSysInfo>
#include <QTest>

#include <type_traits>

// Operation presence and parameter modes are checked at compile time: the
// member-function type of each generated operation encodes return and parameter
// passing (in string = const char*, inout struct = T&, out sequence = T_out).
#define RTSTUDIO_EXPECT_OP(Cls, Ret, Op, Params)                                 \
    static_assert(std::is_same_v<decltype(&Cls::Op), Ret(Cls::*) Params>,       \
                  #Cls "::" #Op " has an unexpected signature")

namespace {

using RTC::ExecutionContextHandle_t;
using RTC::ReturnCode_t;

RTSTUDIO_EXPECT_OP(RTC::_objref_ComponentAction, ReturnCode_t, on_initialize, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_ComponentAction, ReturnCode_t, on_activated,
                   (ExecutionContextHandle_t));
RTSTUDIO_EXPECT_OP(RTC::_objref_ComponentAction, ReturnCode_t, on_reset,
                   (ExecutionContextHandle_t));
RTSTUDIO_EXPECT_OP(RTC::_objref_LightweightRTObject, CORBA::Boolean, is_alive,
                   (RTC::ExecutionContext_ptr));
RTSTUDIO_EXPECT_OP(RTC::_objref_LightweightRTObject, ExecutionContextHandle_t,
                   attach_context, (RTC::ExecutionContext_ptr));
RTSTUDIO_EXPECT_OP(RTC::_objref_LightweightRTObject, RTC::ExecutionContextList *,
                   get_owned_contexts, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_LightweightRTObject, RTC::ExecutionContextList *,
                   get_participating_contexts, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_LightweightRTObject, ExecutionContextHandle_t,
                   get_context_handle, (RTC::ExecutionContext_ptr));
RTSTUDIO_EXPECT_OP(RTC::_objref_ExecutionContext, CORBA::Double, get_rate, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_ExecutionContext, ReturnCode_t, set_rate, (CORBA::Double));
RTSTUDIO_EXPECT_OP(RTC::_objref_ExecutionContext, ReturnCode_t, activate_component,
                   (RTC::LightweightRTObject_ptr));
RTSTUDIO_EXPECT_OP(RTC::_objref_ExecutionContext, RTC::LifeCycleState, get_component_state,
                   (RTC::LightweightRTObject_ptr));
RTSTUDIO_EXPECT_OP(RTC::_objref_ExecutionContext, RTC::ExecutionKind, get_kind, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_ExecutionContextService, RTC::ExecutionContextProfile *,
                   get_profile, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_DataFlowComponentAction, ReturnCode_t, on_execute,
                   (ExecutionContextHandle_t));
RTSTUDIO_EXPECT_OP(RTC::_objref_FsmParticipantAction, ReturnCode_t, on_action,
                   (ExecutionContextHandle_t));
RTSTUDIO_EXPECT_OP(RTC::_objref_ModeCapable, ReturnCode_t, set_mode,
                   (RTC::Mode_ptr, CORBA::Boolean));
RTSTUDIO_EXPECT_OP(RTC::_objref_MultiModeComponentAction, ReturnCode_t, on_mode_changed,
                   (ExecutionContextHandle_t));
RTSTUDIO_EXPECT_OP(RTC::_objref_PortService, RTC::PortProfile *, get_port_profile, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_PortService, ReturnCode_t, connect, (RTC::ConnectorProfile &));
RTSTUDIO_EXPECT_OP(RTC::_objref_PortService, ReturnCode_t, notify_connect,
                   (RTC::ConnectorProfile &));
RTSTUDIO_EXPECT_OP(RTC::_objref_PortService, ReturnCode_t, disconnect, (const char *));
RTSTUDIO_EXPECT_OP(RTC::_objref_PortService, ReturnCode_t, disconnect_all, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_RTObject, RTC::ComponentProfile *, get_component_profile, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_RTObject, RTC::PortServiceList *, get_ports, ());
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_SDO, SDOPackage::Configuration_ptr, get_configuration,
                   ());
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_SDO, CORBA::Any *, get_status, (const char *));
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_SDOSystemElement, SDOPackage::OrganizationList *,
                   get_owned_organizations, ());
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_Configuration, CORBA::Boolean,
                   set_configuration_parameter, (const char *, const CORBA::Any &));
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_Configuration, CORBA::Boolean,
                   set_configuration_set_values, (const SDOPackage::ConfigurationSet &));
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_Configuration, CORBA::Boolean,
                   activate_configuration_set, (const char *));
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_Configuration, CORBA::Boolean, add_service_profile,
                   (const SDOPackage::ServiceProfile &));
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_Configuration, SDOPackage::ConfigurationSet *,
                   get_active_configuration_set, ());
RTSTUDIO_EXPECT_OP(SDOPackage::_objref_Organization, CORBA::Boolean, set_dependency,
                   (SDOPackage::DependencyType));
RTSTUDIO_EXPECT_OP(OpenRTM::_objref_InPortCdr, OpenRTM::PortStatus, put,
                   (const OpenRTM::CdrData &));
RTSTUDIO_EXPECT_OP(OpenRTM::_objref_OutPortCdr, OpenRTM::PortStatus, get,
                   (OpenRTM::CdrData_out));
RTSTUDIO_EXPECT_OP(OpenRTM::_objref_ExtTrigExecutionContextService, void, tick, ());
RTSTUDIO_EXPECT_OP(RTC::_objref_ComponentObserver, void, update_status,
                   (RTC::StatusKind, const char *));
RTSTUDIO_EXPECT_OP(SimpleService::_objref_MyService, char *, echo, (const char *));
RTSTUDIO_EXPECT_OP(SimpleService::_objref_MyService, SimpleService::EchoList *,
                   get_echo_history, ());
RTSTUDIO_EXPECT_OP(SimpleService::_objref_MyService, void, set_value, (CORBA::Float));
RTSTUDIO_EXPECT_OP(SimpleService::_objref_MyService, CORBA::Float, get_value, ());
RTSTUDIO_EXPECT_OP(SimpleService::_objref_MyService, SimpleService::ValueList *,
                   get_value_history, ());

using RTM::_objref_Manager;
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, load_module, (const char *, const char *));
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, unload_module, (const char *));
RTSTUDIO_EXPECT_OP(_objref_Manager, RTM::ModuleProfileList *, get_loadable_modules, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, RTM::ModuleProfileList *, get_loaded_modules, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, RTM::ModuleProfileList *, get_factory_profiles, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, RTC::RTObject_ptr, create_component, (const char *));
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, delete_component, (const char *));
RTSTUDIO_EXPECT_OP(_objref_Manager, RTC::RTCList *, get_components, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, RTC::ComponentProfileList *, get_component_profiles, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, RTC::RTCList *, get_components_by_name, (const char *));
RTSTUDIO_EXPECT_OP(_objref_Manager, RTM::ManagerProfile *, get_profile, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, SDOPackage::NVList *, get_configuration, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, set_configuration,
                   (const char *, const char *));
RTSTUDIO_EXPECT_OP(_objref_Manager, CORBA::Boolean, is_master, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, RTM::ManagerList *, get_master_managers, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, add_master_manager, (RTM::Manager_ptr));
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, remove_master_manager, (RTM::Manager_ptr));
RTSTUDIO_EXPECT_OP(_objref_Manager, RTM::ManagerList *, get_slave_managers, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, add_slave_manager, (RTM::Manager_ptr));
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, remove_slave_manager, (RTM::Manager_ptr));
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, fork, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, shutdown, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, ReturnCode_t, restart, ());
RTSTUDIO_EXPECT_OP(_objref_Manager, CORBA::Object_ptr, get_service, (const char *));

// Device data members whose C++ type follows from their IDL type: a changed
// integer width or a lost typedef would make these fail to compile.
#define RTSTUDIO_EXPECT_MEMBER(Struct, Member, Type)                               \
    static_assert(std::is_same_v<decltype(Struct::Member), Type>,                \
                  #Struct "::" #Member " has an unexpected type")

RTSTUDIO_EXPECT_MEMBER(RTC::ActArrayActuatorPos, index, CORBA::UShort);
RTSTUDIO_EXPECT_MEMBER(RTC::Actuator, status, RTC::ActArrayActuatorStatus);
RTSTUDIO_EXPECT_MEMBER(RTC::ActArrayState, actuators, RTC::ActuatorList);
RTSTUDIO_EXPECT_MEMBER(RTC::FiducialInfo, id, CORBA::ULong);
RTSTUDIO_EXPECT_MEMBER(RTC::GPSTime, msec, CORBA::ULong);
RTSTUDIO_EXPECT_MEMBER(RTC::GPSData, numSatellites, CORBA::UShort);
RTSTUDIO_EXPECT_MEMBER(RTC::GPSData, fixType, RTC::GPSFixType);
RTSTUDIO_EXPECT_MEMBER(RTC::LimbState, oapMatrix, RTC::OAP);
RTSTUDIO_EXPECT_MEMBER(RTC::Hypothesis3D, covariance, RTC::Covariance3D);
RTSTUDIO_EXPECT_MEMBER(RTC::OGMapTile, cells, RTC::OGMapCells);
RTSTUDIO_EXPECT_MEMBER(RTC::LineFeature, covariance, RTC::PointCovariance2D);
RTSTUDIO_EXPECT_MEMBER(RTC::Waypoint3D, timeLimit, RTC::Time);
RTSTUDIO_EXPECT_MEMBER(RTC::RangeData, ranges, RTC::RangeList);
RTSTUDIO_EXPECT_MEMBER(RTC::IntensityData, intensities, RTC::IntensityList);
RTSTUDIO_EXPECT_MEMBER(RTC::TimedQuaternion, data, RTC::Quaternion);

QStringList memberNames(CORBA::TypeCode_ptr tc)
{
    QStringList names;
    const CORBA::ULong count = tc->member_count();
    for (CORBA::ULong i = 0; i < count; ++i)
        names << QString::fromLatin1(tc->member_name(i));
    return names;
}

// Spells each member's type as IDL would: named types (structs, enums,
// typedefs) by repository id, anonymous sequences by element, basic types by
// keyword. Two structs with the same names but other member types differ here.
QString typeName(CORBA::TypeCode_ptr tc)
{
    switch (tc->kind()) {
    case CORBA::tk_struct:
    case CORBA::tk_enum:
    case CORBA::tk_alias:
    case CORBA::tk_objref:
        return QString::fromLatin1(tc->id());
    case CORBA::tk_sequence: {
        CORBA::TypeCode_var element = tc->content_type();
        return QStringLiteral("sequence<%1>").arg(typeName(element));
    }
    case CORBA::tk_double:
        return QStringLiteral("double");
    case CORBA::tk_ulong:
        return QStringLiteral("unsigned long");
    case CORBA::tk_ushort:
        return QStringLiteral("unsigned short");
    case CORBA::tk_long:
        return QStringLiteral("long");
    case CORBA::tk_boolean:
        return QStringLiteral("boolean");
    case CORBA::tk_octet:
        return QStringLiteral("octet");
    case CORBA::tk_string:
        return QStringLiteral("string");
    default:
        return QStringLiteral("kind %1").arg(int(tc->kind()));
    }
}

QStringList memberTypes(CORBA::TypeCode_ptr tc)
{
    QStringList types;
    const CORBA::ULong count = tc->member_count();
    for (CORBA::ULong i = 0; i < count; ++i) {
        CORBA::TypeCode_var member = tc->member_type(i);
        types << typeName(member);
    }
    return types;
}

QString aliasedType(CORBA::TypeCode_ptr alias)
{
    CORBA::TypeCode_var content = alias->content_type();
    return typeName(content);
}

QByteArray marshal(const RTC::TimedLong &value)
{
    cdrMemoryStream stream;
    value >>= stream;
    return QByteArray(static_cast<const char *>(stream.bufPtr()),
                      static_cast<int>(stream.bufSize()));
}

} // namespace

class TestCorbaIdl : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void interfaceRepositoryIds_data();
    void interfaceRepositoryIds();
    void typeRepositoryIds_data();
    void typeRepositoryIds();
    void enumOrder_data();
    void enumOrder();
    void structMemberOrder_data();
    void structMemberOrder();
    void deviceMemberTypes_data();
    void deviceMemberTypes();
    void deviceTypedefs_data();
    void deviceTypedefs();
    void enumWireValues();
    void timedLongCdrLayout();
    void idlFolderHoldsEveryFile();

private:
    CORBA::ORB_var m_orb;
};

void TestCorbaIdl::initTestCase()
{
    // TypeCodes need an initialised ORB; nothing is activated, so no socket opens.
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    QVERIFY(!CORBA::is_nil(m_orb));
}

void TestCorbaIdl::cleanupTestCase()
{
    if (!CORBA::is_nil(m_orb))
        m_orb->destroy();
}

void TestCorbaIdl::interfaceRepositoryIds_data()
{
    QTest::addColumn<QString>("actual");
    QTest::addColumn<QString>("expected");
    const auto row = [](const char *expected, const char *actual) {
        QTest::newRow(expected) << QString::fromLatin1(actual) << QString::fromLatin1(expected);
    };
    row("IDL:org.omg/SDOPackage/SDOSystemElement:1.0", SDOPackage::SDOSystemElement::_PD_repoId);
    row("IDL:org.omg/SDOPackage/SDO:1.0", SDOPackage::SDO::_PD_repoId);
    row("IDL:org.omg/SDOPackage/SDOService:1.0", SDOPackage::SDOService::_PD_repoId);
    row("IDL:org.omg/SDOPackage/Configuration:1.0", SDOPackage::Configuration::_PD_repoId);
    row("IDL:org.omg/SDOPackage/Monitoring:1.0", SDOPackage::Monitoring::_PD_repoId);
    row("IDL:org.omg/SDOPackage/Organization:1.0", SDOPackage::Organization::_PD_repoId);
    row("IDL:omg.org/RTC/ComponentAction:1.0", RTC::ComponentAction::_PD_repoId);
    row("IDL:omg.org/RTC/LightweightRTObject:1.0", RTC::LightweightRTObject::_PD_repoId);
    row("IDL:omg.org/RTC/ExecutionContext:1.0", RTC::ExecutionContext::_PD_repoId);
    row("IDL:omg.org/RTC/DataFlowComponentAction:1.0", RTC::DataFlowComponentAction::_PD_repoId);
    row("IDL:omg.org/RTC/DataFlowComponent:1.0", RTC::DataFlowComponent::_PD_repoId);
    row("IDL:omg.org/RTC/Fsm:1.0", RTC::Fsm::_PD_repoId);
    row("IDL:omg.org/RTC/FsmParticipantAction:1.0", RTC::FsmParticipantAction::_PD_repoId);
    row("IDL:omg.org/RTC/FsmParticipant:1.0", RTC::FsmParticipant::_PD_repoId);
    row("IDL:omg.org/RTC/Mode:1.0", RTC::Mode::_PD_repoId);
    row("IDL:omg.org/RTC/ModeCapable:1.0", RTC::ModeCapable::_PD_repoId);
    row("IDL:omg.org/RTC/MultiModeComponentAction:1.0", RTC::MultiModeComponentAction::_PD_repoId);
    row("IDL:omg.org/RTC/MultiModeObject:1.0", RTC::MultiModeObject::_PD_repoId);
    row("IDL:omg.org/RTC/FsmObject:1.0", RTC::FsmObject::_PD_repoId);
    row("IDL:omg.org/RTC/FsmService:1.0", RTC::FsmService::_PD_repoId);
    row("IDL:omg.org/RTC/PortService:1.0", RTC::PortService::_PD_repoId);
    row("IDL:omg.org/RTC/ExecutionContextService:1.0", RTC::ExecutionContextService::_PD_repoId);
    row("IDL:omg.org/RTC/RTObject:1.0", RTC::RTObject::_PD_repoId);
    row("IDL:openrtm.aist.go.jp/OpenRTM/DataFlowComponent:1.0",
        OpenRTM::DataFlowComponent::_PD_repoId);
    row("IDL:openrtm.aist.go.jp/OpenRTM/ExtTrigExecutionContextService:1.0",
        OpenRTM::ExtTrigExecutionContextService::_PD_repoId);
    row("IDL:OpenRTM/InPortCdr:1.0", OpenRTM::InPortCdr::_PD_repoId);
    row("IDL:OpenRTM/OutPortCdr:1.0", OpenRTM::OutPortCdr::_PD_repoId);
    row("IDL:RTM/Manager:1.0", RTM::Manager::_PD_repoId);
    row("IDL:rtstudio/RTStudio/Manager:1.0", RTStudio::Manager::_PD_repoId);
    row("IDL:omg.org/RTC/ComponentObserver:1.0", RTC::ComponentObserver::_PD_repoId);
    row("IDL:SimpleService/MyService:1.0", SimpleService::MyService::_PD_repoId);
    row("IDL:omg.org/RTC/DataPushService:1.0", RTC::DataPushService::_PD_repoId);
    row("IDL:omg.org/RTC/DataPullService:1.0", RTC::DataPullService::_PD_repoId);
    row("IDL:OpenRTM/PortSharedMemory:1.0", OpenRTM::PortSharedMemory::_PD_repoId);
    row("IDL:openrtm.aist.go.jp/OpenRTM/InPortCdrUDP:1.0", OpenRTM::InPortCdrUDP::_PD_repoId);
    row("IDL:omg.org/RTC/ExtendedFsmService:1.0", RTC::ExtendedFsmService::_PD_repoId);
    row("IDL:Img/CameraCaptureService:1.0", Img::CameraCaptureService::_PD_repoId);
    row("IDL:JARA_ARM/ManipulatorCommonInterface_Common:1.0",
        JARA_ARM::ManipulatorCommonInterface_Common::_PD_repoId);
    row("IDL:JARA_ARM/ManipulatorCommonInterface_Middle:1.0",
        JARA_ARM::ManipulatorCommonInterface_Middle::_PD_repoId);
}

void TestCorbaIdl::interfaceRepositoryIds()
{
    QFETCH(QString, actual);
    QFETCH(QString, expected);
    QCOMPARE(actual, expected);
}

void TestCorbaIdl::typeRepositoryIds_data()
{
    QTest::addColumn<QString>("actual");
    QTest::addColumn<QString>("expected");
    const auto row = [](const char *expected, CORBA::TypeCode_ptr tc) {
        QTest::newRow(expected) << QString::fromLatin1(tc->id()) << QString::fromLatin1(expected);
    };
    row("IDL:org.omg/SDOPackage/NameValue:1.0", SDOPackage::_tc_NameValue);
    row("IDL:org.omg/SDOPackage/NVList:1.0", SDOPackage::_tc_NVList);
    row("IDL:org.omg/SDOPackage/ServiceProfile:1.0", SDOPackage::_tc_ServiceProfile);
    row("IDL:org.omg/SDOPackage/ConfigurationSet:1.0", SDOPackage::_tc_ConfigurationSet);
    row("IDL:org.omg/SDOPackage/DeviceProfile:1.0", SDOPackage::_tc_DeviceProfile);
    row("IDL:org.omg/SDOPackage/OrganizationProperty:1.0", SDOPackage::_tc_OrganizationProperty);
    row("IDL:org.omg/SDOPackage/InvalidParameter:1.0", SDOPackage::_tc_InvalidParameter);
    row("IDL:org.omg/SDOPackage/NotAvailable:1.0", SDOPackage::_tc_NotAvailable);
    row("IDL:org.omg/SDOPackage/InternalError:1.0", SDOPackage::_tc_InternalError);
    row("IDL:org.omg/SDOPackage/InterfaceNotImplemented:1.0",
        SDOPackage::_tc_InterfaceNotImplemented);
    row("IDL:omg.org/RTC/ReturnCode_t:1.0", RTC::_tc_ReturnCode_t);
    row("IDL:omg.org/RTC/LifeCycleState:1.0", RTC::_tc_LifeCycleState);
    row("IDL:omg.org/RTC/ExecutionKind:1.0", RTC::_tc_ExecutionKind);
    row("IDL:omg.org/RTC/ExecutionContextHandle_t:1.0", RTC::_tc_ExecutionContextHandle_t);
    row("IDL:omg.org/RTC/PortInterfacePolarity:1.0", RTC::_tc_PortInterfacePolarity);
    row("IDL:omg.org/RTC/PortInterfaceProfile:1.0", RTC::_tc_PortInterfaceProfile);
    row("IDL:omg.org/RTC/ConnectorProfile:1.0", RTC::_tc_ConnectorProfile);
    row("IDL:omg.org/RTC/PortProfile:1.0", RTC::_tc_PortProfile);
    row("IDL:omg.org/RTC/ExecutionContextProfile:1.0", RTC::_tc_ExecutionContextProfile);
    row("IDL:omg.org/RTC/FsmBehaviorProfile:1.0", RTC::_tc_FsmBehaviorProfile);
    row("IDL:omg.org/RTC/FsmProfile:1.0", RTC::_tc_FsmProfile);
    row("IDL:omg.org/RTC/ComponentProfile:1.0", RTC::_tc_ComponentProfile);
    row("IDL:omg.org/RTC/ComponentProfileList:1.0", RTC::_tc_ComponentProfileList);
    row("IDL:omg.org/RTC/RTCList:1.0", RTC::_tc_RTCList);
    row("IDL:OpenRTM/PortStatus:1.0", OpenRTM::_tc_PortStatus);
    row("IDL:OpenRTM/CdrData:1.0", OpenRTM::_tc_CdrData);
    row("IDL:RTM/ModuleProfile:1.0", RTM::_tc_ModuleProfile);
    row("IDL:omg.org/RTC/PortStatus:1.0", RTC::_tc_PortStatus);
    row("IDL:omg.org/RTC/OctetSeq:1.0", RTC::_tc_OctetSeq);
    row("IDL:omg.org/RTC/FsmEventProfile:1.0", RTC::_tc_FsmEventProfile);
    row("IDL:omg.org/RTC/FsmStructure:1.0", RTC::_tc_FsmStructure);
    row("IDL:Img/ColorFormat:1.0", Img::_tc_ColorFormat);
    row("IDL:Img/TimedCameraImage:1.0", Img::_tc_TimedCameraImage);
    row("IDL:Img/TimedMultiCameraImage:1.0", Img::_tc_TimedMultiCameraImage);
    row("IDL:Img/CameraDeviceProfile:1.0", Img::_tc_CameraDeviceProfile);
    row("IDL:JARA_ARM/TimedJointPos:1.0", JARA_ARM::_tc_TimedJointPos);
    row("IDL:JARA_ARM/RETURN_ID:1.0", JARA_ARM::_tc_RETURN_ID);
    row("IDL:JARA_ARM/ManipInfo:1.0", JARA_ARM::_tc_ManipInfo);
    row("IDL:JARA_ARM/CarPosWithElbow:1.0", JARA_ARM::_tc_CarPosWithElbow);
    row("IDL:RTM/ManagerProfile:1.0", RTM::_tc_ManagerProfile);
    row("IDL:RTM/ManagerList:1.0", RTM::_tc_ManagerList);
    row("IDL:RTC/Time:1.0", RTC::_tc_Time);
    row("IDL:RTC/TimedLong:1.0", RTC::_tc_TimedLong);
    row("IDL:RTC/TimedDouble:1.0", RTC::_tc_TimedDouble);
    row("IDL:RTC/TimedString:1.0", RTC::_tc_TimedString);
    row("IDL:RTC/TimedOctetSeq:1.0", RTC::_tc_TimedOctetSeq);
    row("IDL:RTC/TimedDoubleSeq:1.0", RTC::_tc_TimedDoubleSeq);
    row("IDL:RTC/TimedPose2D:1.0", RTC::_tc_TimedPose2D);
    row("IDL:RTC/CameraImage:1.0", RTC::_tc_CameraImage);
    row("IDL:omg.org/RTC/StatusKind:1.0", RTC::_tc_StatusKind);
    row("IDL:SimpleService/EchoList:1.0", SimpleService::_tc_EchoList);
    row("IDL:RTC/Acceleration2D:1.0", RTC::_tc_Acceleration2D);
    row("IDL:RTC/Covariance2D:1.0", RTC::_tc_Covariance2D);
    row("IDL:RTC/PointCovariance2D:1.0", RTC::_tc_PointCovariance2D);
    row("IDL:RTC/Covariance3D:1.0", RTC::_tc_Covariance3D);
    row("IDL:RTC/TimedAcceleration2D:1.0", RTC::_tc_TimedAcceleration2D);
    row("IDL:RTC/TimedCovariance2D:1.0", RTC::_tc_TimedCovariance2D);
    row("IDL:RTC/TimedPointCovariance2D:1.0", RTC::_tc_TimedPointCovariance2D);
    row("IDL:RTC/TimedCovariance3D:1.0", RTC::_tc_TimedCovariance3D);
    row("IDL:RTC/Quaternion:1.0", RTC::_tc_Quaternion);
    row("IDL:RTC/TimedQuaternion:1.0", RTC::_tc_TimedQuaternion);
    row("IDL:RTC/ActArrayActuatorPos:1.0", RTC::_tc_ActArrayActuatorPos);
    row("IDL:RTC/ActArrayActuatorStatus:1.0", RTC::_tc_ActArrayActuatorStatus);
    row("IDL:RTC/ActuatorList:1.0", RTC::_tc_ActuatorList);
    row("IDL:RTC/ActArrayState:1.0", RTC::_tc_ActArrayState);
    row("IDL:RTC/ActArrayGeometry:1.0", RTC::_tc_ActArrayGeometry);
    row("IDL:RTC/BumperArrayGeometry:1.0", RTC::_tc_BumperArrayGeometry);
    row("IDL:RTC/CameraInfo:1.0", RTC::_tc_CameraInfo);
    row("IDL:RTC/Fiducials:1.0", RTC::_tc_Fiducials);
    row("IDL:RTC/FiducialFOV:1.0", RTC::_tc_FiducialFOV);
    row("IDL:RTC/GPSFixType:1.0", RTC::_tc_GPSFixType);
    row("IDL:RTC/GPSData:1.0", RTC::_tc_GPSData);
    row("IDL:RTC/GripperState:1.0", RTC::_tc_GripperState);
    row("IDL:RTC/GripperGeometry:1.0", RTC::_tc_GripperGeometry);
    row("IDL:RTC/INSData:1.0", RTC::_tc_INSData);
    row("IDL:RTC/LimbState:1.0", RTC::_tc_LimbState);
    row("IDL:RTC/Hypotheses2D:1.0", RTC::_tc_Hypotheses2D);
    row("IDL:RTC/Hypotheses3D:1.0", RTC::_tc_Hypotheses3D);
    row("IDL:RTC/OGMapConfig:1.0", RTC::_tc_OGMapConfig);
    row("IDL:RTC/OGMapTile:1.0", RTC::_tc_OGMapTile);
    row("IDL:RTC/Features:1.0", RTC::_tc_Features);
    row("IDL:RTC/MultiCameraImages:1.0", RTC::_tc_MultiCameraImages);
    row("IDL:RTC/MulticameraInfoList:1.0", RTC::_tc_MulticameraInfoList);
    row("IDL:RTC/MulticameraGeometry:1.0", RTC::_tc_MulticameraGeometry);
    row("IDL:RTC/Path2D:1.0", RTC::_tc_Path2D);
    row("IDL:RTC/Path3D:1.0", RTC::_tc_Path3D);
    row("IDL:RTC/PointCloud:1.0", RTC::_tc_PointCloud);
    row("IDL:RTC/PanTiltAngles:1.0", RTC::_tc_PanTiltAngles);
    row("IDL:RTC/PanTiltState:1.0", RTC::_tc_PanTiltState);
    row("IDL:RTC/RangerGeometry:1.0", RTC::_tc_RangerGeometry);
    row("IDL:RTC/RangerConfig:1.0", RTC::_tc_RangerConfig);
    row("IDL:RTC/RangeData:1.0", RTC::_tc_RangeData);
    row("IDL:RTC/IntensityData:1.0", RTC::_tc_IntensityData);
    row("IDL:RTC/RFIDTagData:1.0", RTC::_tc_RFIDTagData);
    row("IDL:SimpleService/ValueList:1.0", SimpleService::_tc_ValueList);
}

void TestCorbaIdl::typeRepositoryIds()
{
    QFETCH(QString, actual);
    QFETCH(QString, expected);
    QCOMPARE(actual, expected);
}

void TestCorbaIdl::enumOrder_data()
{
    QTest::addColumn<QStringList>("actual");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("ReturnCode_t")
        << memberNames(RTC::_tc_ReturnCode_t)
        << QStringList{"RTC_OK", "RTC_ERROR", "BAD_PARAMETER", "UNSUPPORTED", "OUT_OF_RESOURCES",
                       "PRECONDITION_NOT_MET"};
    QTest::newRow("LifeCycleState")
        << memberNames(RTC::_tc_LifeCycleState)
        << QStringList{"CREATED_STATE", "INACTIVE_STATE", "ACTIVE_STATE", "ERROR_STATE"};
    QTest::newRow("ExecutionKind") << memberNames(RTC::_tc_ExecutionKind)
                                   << QStringList{"PERIODIC", "EVENT_DRIVEN", "OTHER"};
    QTest::newRow("PortInterfacePolarity") << memberNames(RTC::_tc_PortInterfacePolarity)
                                           << QStringList{"PROVIDED", "REQUIRED"};
    QTest::newRow("PortStatus")
        << memberNames(OpenRTM::_tc_PortStatus)
        << QStringList{"PORT_OK", "PORT_ERROR", "BUFFER_FULL", "BUFFER_EMPTY", "BUFFER_TIMEOUT",
                       "UNKNOWN_ERROR"};
    QTest::newRow("StatusKind")
        << memberNames(RTC::_tc_StatusKind)
        << QStringList{"COMPONENT_PROFILE", "RTC_STATUS",    "EC_STATUS",   "PORT_PROFILE",
                       "CONFIGURATION",     "RTC_HEARTBEAT", "EC_HEARTBEAT", "FSM_PROFILE",
                       "FSM_STATUS",        "FSM_STRUCTURE", "USER_DEFINED", "STATUS_KIND_NUM"};
    QTest::newRow("DependencyType") << memberNames(SDOPackage::_tc_DependencyType)
                                    << QStringList{"OWN", "OWNED", "NO_DEPENDENCY"};
    QTest::newRow("ActArrayActuatorStatus")
        << memberNames(RTC::_tc_ActArrayActuatorStatus)
        << QStringList{"ACTUATOR_STATUS_IDLE", "ACTUATOR_STATUS_MOVING", "ACTUATOR_STATUS_BRAKED",
                       "ACTUATOR_STATUS_STALLED"};
    QTest::newRow("ActArrayActuatorType")
        << memberNames(RTC::_tc_ActArrayActuatorType)
        << QStringList{"ACTARRAY_ACTUATORTYPE_LINEAR", "ACTARRAY_ACTUATORTYPE_ROTARY"};
    QTest::newRow("GPSFixType") << memberNames(RTC::_tc_GPSFixType)
                                << QStringList{"GPS_FIX_NONE", "GPS_FIX_NORMAL", "GPS_FIX_DGPS"};
    QTest::newRow("GripperStatus")
        << memberNames(RTC::_tc_GripperStatus)
        << QStringList{"GRIPPER_STATE_OPEN", "GRIPPER_STATE_CLOSED", "GRIPPER_STATE_MOVING",
                       "GRIPPER_STATE_UNKNOWN"};
    QTest::newRow("LimbStatus")
        << memberNames(RTC::_tc_LimbStatus)
        << QStringList{"LIMB_STATUS_IDLE", "LIMB_STATUS_BRAKED", "LIMB_STATUS_MOVING",
                       "LIMB_STATUS_OOR", "LIMB_STATUS_COLLISION"};
}

void TestCorbaIdl::enumOrder()
{
    QFETCH(QStringList, actual);
    QFETCH(QStringList, expected);
    QCOMPARE(actual, expected);
}

void TestCorbaIdl::structMemberOrder_data()
{
    QTest::addColumn<QStringList>("actual");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("ComponentProfile")
        << memberNames(RTC::_tc_ComponentProfile)
        << QStringList{"instance_name", "type_name", "description", "version", "vendor",
                       "category", "port_profiles", "parent", "properties"};
    QTest::newRow("PortProfile")
        << memberNames(RTC::_tc_PortProfile)
        << QStringList{"name", "interfaces", "port_ref", "connector_profiles", "owner",
                       "properties"};
    QTest::newRow("ConnectorProfile")
        << memberNames(RTC::_tc_ConnectorProfile)
        << QStringList{"name", "connector_id", "ports", "properties"};
    QTest::newRow("ExecutionContextProfile")
        << memberNames(RTC::_tc_ExecutionContextProfile)
        << QStringList{"kind", "rate", "owner", "participants", "properties"};
    QTest::newRow("PortInterfaceProfile")
        << memberNames(RTC::_tc_PortInterfaceProfile)
        << QStringList{"instance_name", "type_name", "polarity"};
    QTest::newRow("ServiceProfile")
        << memberNames(SDOPackage::_tc_ServiceProfile)
        << QStringList{"id", "interface_type", "properties", "service"};
    QTest::newRow("ConfigurationSet")
        << memberNames(SDOPackage::_tc_ConfigurationSet)
        << QStringList{"id", "description", "configuration_data"};
    QTest::newRow("NameValue") << memberNames(SDOPackage::_tc_NameValue)
                               << QStringList{"name", "value"};
    QTest::newRow("Time") << memberNames(RTC::_tc_Time) << QStringList{"sec", "nsec"};
    QTest::newRow("TimedLong") << memberNames(RTC::_tc_TimedLong) << QStringList{"tm", "data"};
    QTest::newRow("TimedLongSeq") << memberNames(RTC::_tc_TimedLongSeq)
                                  << QStringList{"tm", "data"};
    QTest::newRow("Pose2D") << memberNames(RTC::_tc_Pose2D)
                            << QStringList{"position", "heading"};
    QTest::newRow("Acceleration2D") << memberNames(RTC::_tc_Acceleration2D)
                                    << QStringList{"ax", "ay"};
    QTest::newRow("Covariance2D") << memberNames(RTC::_tc_Covariance2D)
                                  << QStringList{"xx", "xy", "xt", "yy", "yt", "tt"};
    QTest::newRow("PointCovariance2D") << memberNames(RTC::_tc_PointCovariance2D)
                                       << QStringList{"xx", "xy", "yy"};
    QTest::newRow("Covariance3D")
        << memberNames(RTC::_tc_Covariance3D)
        << QStringList{"xx", "xy", "xz", "xr", "xp", "xa", "yy", "yz", "yr", "yp", "ya",
                       "zz", "zr", "zp", "za", "rr", "rp", "ra", "pp", "pa", "aa"};
    QTest::newRow("Quaternion") << memberNames(RTC::_tc_Quaternion)
                                << QStringList{"x", "y", "z", "w"};
    QTest::newRow("TimedCovariance3D") << memberNames(RTC::_tc_TimedCovariance3D)
                                       << QStringList{"tm", "data"};
    QTest::newRow("Actuator") << memberNames(RTC::_tc_Actuator)
                              << QStringList{"position", "speed", "accel", "current", "status"};
    QTest::newRow("ActArrayActuatorGeometry")
        << memberNames(RTC::_tc_ActArrayActuatorGeometry)
        << QStringList{"type",     "length",   "orientation",  "axis",     "minRange",
                       "centre",   "maxRange", "homePosition", "hasBrakes"};
    QTest::newRow("CameraImage")
        << memberNames(RTC::_tc_CameraImage)
        << QStringList{"tm", "width", "height", "bpp", "format", "fDiv", "pixels"};
    QTest::newRow("CameraInfo")
        << memberNames(RTC::_tc_CameraInfo)
        << QStringList{"focalLength", "principalPoint", "k1", "k2", "p1", "p2"};
    QTest::newRow("FiducialInfo")
        << memberNames(RTC::_tc_FiducialInfo)
        << QStringList{"id", "pose", "poseUncertainty", "size", "sizeUncertainty"};
    QTest::newRow("GPSData")
        << memberNames(RTC::_tc_GPSData)
        << QStringList{"tm",           "timeFromGPS",     "latitude",        "longitude",
                       "altitude",     "horizontalError", "verticalError",   "heading",
                       "horizontalSpeed", "verticalSpeed", "numSatellites", "fixType"};
    QTest::newRow("INSData")
        << memberNames(RTC::_tc_INSData)
        << QStringList{"tm",         "latitude",    "longitude",  "altitude",
                       "heightAMSL", "velocityENU", "orientation"};
    QTest::newRow("LineFeature")
        << memberNames(RTC::_tc_LineFeature)
        << QStringList{"probability", "rho", "alpha",        "covariance",
                       "start",       "end", "startSighted", "endSighted"};
    QTest::newRow("OGMapTile") << memberNames(RTC::_tc_OGMapTile)
                               << QStringList{"column", "row", "width", "height", "cells"};
    QTest::newRow("Waypoint2D")
        << memberNames(RTC::_tc_Waypoint2D)
        << QStringList{"target", "distanceTolerance", "headingTolerance", "timeLimit",
                       "maxSpeed"};
    QTest::newRow("PanTiltState") << memberNames(RTC::_tc_PanTiltState)
                                  << QStringList{"tm", "angles", "panSpeed", "tiltSpeed"};
    QTest::newRow("RangerConfig")
        << memberNames(RTC::_tc_RangerConfig)
        << QStringList{"minAngle", "maxAngle", "angularRes", "minRange", "maxRange", "rangeRes",
                       "frequency"};
    QTest::newRow("RangeData") << memberNames(RTC::_tc_RangeData)
                               << QStringList{"tm", "ranges", "geometry", "config"};
    QTest::newRow("IntensityData") << memberNames(RTC::_tc_IntensityData)
                                   << QStringList{"tm", "intensities", "geometry", "config"};
}

void TestCorbaIdl::structMemberOrder()
{
    QFETCH(QStringList, actual);
    QFETCH(QStringList, expected);
    QCOMPARE(actual, expected);
}

void TestCorbaIdl::deviceMemberTypes_data()
{
    QTest::addColumn<QStringList>("actual");
    QTest::addColumn<QStringList>("expected");
    QTest::newRow("ActArrayActuatorPos")
        << memberTypes(RTC::_tc_ActArrayActuatorPos)
        << QStringList{"IDL:RTC/Time:1.0", "unsigned short", "double"};
    QTest::newRow("ActArrayActuatorGeometry")
        << memberTypes(RTC::_tc_ActArrayActuatorGeometry)
        << QStringList{"IDL:RTC/ActArrayActuatorType:1.0", "double",
                       "IDL:RTC/Orientation3D:1.0",        "IDL:RTC/Vector3D:1.0",
                       "double",                           "double",
                       "double",                           "double",
                       "boolean"};
    QTest::newRow("CameraImage")
        << memberTypes(RTC::_tc_CameraImage)
        << QStringList{"IDL:RTC/Time:1.0", "unsigned short", "unsigned short", "unsigned short",
                       "string",           "double",         "sequence<octet>"};
    QTest::newRow("FiducialInfo")
        << memberTypes(RTC::_tc_FiducialInfo)
        << QStringList{"unsigned long", "IDL:RTC/Pose3D:1.0", "IDL:RTC/Pose3D:1.0",
                       "IDL:RTC/Size3D:1.0", "IDL:RTC/Size3D:1.0"};
    QTest::newRow("GPSTime") << memberTypes(RTC::_tc_GPSTime)
                             << QStringList{"unsigned long", "unsigned long"};
    QTest::newRow("GPSData")
        << memberTypes(RTC::_tc_GPSData)
        << QStringList{"IDL:RTC/Time:1.0", "IDL:RTC/GPSTime:1.0", "double", "double",
                       "double",           "double",              "double", "double",
                       "double",           "double",              "unsigned short",
                       "IDL:RTC/GPSFixType:1.0"};
    QTest::newRow("Hypothesis3D")
        << memberTypes(RTC::_tc_Hypothesis3D)
        << QStringList{"IDL:RTC/Pose3D:1.0", "IDL:RTC/Covariance3D:1.0", "double"};
    QTest::newRow("OGMapConfig")
        << memberTypes(RTC::_tc_OGMapConfig)
        << QStringList{"double", "double", "unsigned long", "unsigned long",
                       "IDL:RTC/Pose2D:1.0"};
    QTest::newRow("PoseFeature")
        << memberTypes(RTC::_tc_PoseFeature)
        << QStringList{"double", "IDL:RTC/Pose2D:1.0", "IDL:RTC/Covariance2D:1.0"};
    QTest::newRow("Features")
        << memberTypes(RTC::_tc_Features)
        << QStringList{"IDL:RTC/Time:1.0", "IDL:RTC/PointFeatureList:1.0",
                       "IDL:RTC/PoseFeatureList:1.0", "IDL:RTC/LineFeatureList:1.0"};
    QTest::newRow("MultiCameraImages")
        << memberTypes(RTC::_tc_MultiCameraImages)
        << QStringList{"IDL:RTC/Time:1.0", "IDL:RTC/MulticameraImageList:1.0"};
    QTest::newRow("Waypoint3D")
        << memberTypes(RTC::_tc_Waypoint3D)
        << QStringList{"IDL:RTC/Pose3D:1.0", "double", "double", "IDL:RTC/Time:1.0",
                       "IDL:RTC/Velocity3D:1.0"};
    QTest::newRow("PointCloudPoint")
        << memberTypes(RTC::_tc_PointCloudPoint)
        << QStringList{"IDL:RTC/Point3D:1.0", "IDL:RTC/RGBColour:1.0"};
    QTest::newRow("RangerGeometry")
        << memberTypes(RTC::_tc_RangerGeometry)
        << QStringList{"IDL:RTC/Geometry3D:1.0", "IDL:RTC/ElementGeometryList:1.0"};
    QTest::newRow("IntensityData")
        << memberTypes(RTC::_tc_IntensityData)
        << QStringList{"IDL:RTC/Time:1.0", "IDL:RTC/IntensityList:1.0",
                       "IDL:RTC/RangerGeometry:1.0", "IDL:RTC/RangerConfig:1.0"};
    QTest::newRow("TimedPointCovariance2D")
        << memberTypes(RTC::_tc_TimedPointCovariance2D)
        << QStringList{"IDL:RTC/Time:1.0", "IDL:RTC/PointCovariance2D:1.0"};
}

void TestCorbaIdl::deviceMemberTypes()
{
    QFETCH(QStringList, actual);
    QFETCH(QStringList, expected);
    QCOMPARE(actual, expected);
}

void TestCorbaIdl::deviceTypedefs_data()
{
    // A typedef is part of the TypeCode a peer compares, so what it stands
    // for matters as much as its name.
    QTest::addColumn<QString>("actual");
    QTest::addColumn<QString>("expected");
    const auto row = [](const char *name, CORBA::TypeCode_ptr tc, const char *expected) {
        QTest::newRow(name) << aliasedType(tc) << QString::fromLatin1(expected);
    };
    row("ActuatorList", RTC::_tc_ActuatorList, "sequence<IDL:RTC/Actuator:1.0>");
    row("ActArrayActuatorGeometryList", RTC::_tc_ActArrayActuatorGeometryList,
        "sequence<IDL:RTC/ActArrayActuatorGeometry:1.0>");
    row("BumperGeometryList", RTC::_tc_BumperGeometryList,
        "sequence<IDL:RTC/BumperGeometry:1.0>");
    row("FiducialInfoList", RTC::_tc_FiducialInfoList, "sequence<IDL:RTC/FiducialInfo:1.0>");
    row("OGMapCells", RTC::_tc_OGMapCells, "sequence<octet>");
    row("MulticameraImageList", RTC::_tc_MulticameraImageList,
        "sequence<IDL:RTC/CameraImage:1.0>");
    row("MulticameraInfoList", RTC::_tc_MulticameraInfoList,
        "sequence<IDL:RTC/CameraInfo:1.0>");
    row("MulticameraGeometryList", RTC::_tc_MulticameraGeometryList,
        "sequence<IDL:RTC/Geometry3D:1.0>");
    row("Waypoint2DList", RTC::_tc_Waypoint2DList, "sequence<IDL:RTC/Waypoint2D:1.0>");
    row("ElementGeometryList", RTC::_tc_ElementGeometryList, "sequence<IDL:RTC/Geometry3D:1.0>");
    row("RangeList", RTC::_tc_RangeList, "sequence<double>");
    row("IntensityList", RTC::_tc_IntensityList, "sequence<double>");
    row("RFIDTagData", RTC::_tc_RFIDTagData, "sequence<octet>");
}

void TestCorbaIdl::deviceTypedefs()
{
    QFETCH(QString, actual);
    QFETCH(QString, expected);
    QCOMPARE(actual, expected);
}

void TestCorbaIdl::enumWireValues()
{
    // The enumerator's index is what travels in CDR.
    QCOMPARE(int(RTC::RTC_OK), 0);
    QCOMPARE(int(RTC::PRECONDITION_NOT_MET), 5);
    QCOMPARE(int(RTC::ERROR_STATE), 3);
    QCOMPARE(int(RTC::EVENT_DRIVEN), 1);
    QCOMPARE(int(OpenRTM::BUFFER_TIMEOUT), 4);
    QCOMPARE(int(RTC::STATUS_KIND_NUM), 11);
}

void TestCorbaIdl::timedLongCdrLayout()
{
    // Time{sec, nsec} then the value, each a 4-byte integer: what an
    // OpenRTM-aist ConsoleIn writes into an InPortCdr::put().
    RTC::TimedLong value;
    value.tm.sec = 1;
    value.tm.nsec = 2;
    value.data = -3;
    const QByteArray bytes = marshal(value);
    const QByteArray little = QByteArray::fromHex("0100000002000000fdffffff");
    const QByteArray big = QByteArray::fromHex("0000000100000002fffffffd");
    QCOMPARE(bytes, QSysInfo::ByteOrder == QSysInfo::LittleEndian ? little : big);
}

void TestCorbaIdl::idlFolderHoldsEveryFile()
{
    const QDir dir(RTSTUDIO_IDL_DIR);
    const QStringList expected {"BasicDataType.idl",
                                "CameraCommonInterface.idl",
                                "ComponentObserver.idl",
                                "DataPort.idl",
                                "DataPortUDP.idl",
                                "DataPort_OpenRTM.idl",
                                "ExtendedDataTypes.idl",
                                "ExtendedFsmService.idl",
                                "InterfaceDataTypes.idl",
                                "Manager.idl",
                                "ManipulatorCommonInterface_Common.idl",
                                "ManipulatorCommonInterface_DataTypes.idl",
                                "ManipulatorCommonInterface_Middle.idl",
                                "OpenRTM.idl",
                                "RTC.idl",
                                "RTStudioManager.idl",
                                "RTStudioPackages.idl",
                                "SDOPackage.idl",
                                "SharedMemory.idl",
                                "SimpleService.idl"};
    QStringList actual = dir.entryList({"*.idl"}, QDir::Files, QDir::Name);
    QCOMPARE(actual, expected);
    for (const QString &name : expected) {
        QFile file(dir.filePath(name));
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(name));
        QCOMPARE(file.readLine().trimmed(), QByteArray("// SPDX-License-Identifier: MIT"));
    }
}

QTEST_GUILESS_MAIN(TestCorbaIdl)
#include "tst_corbaidl.moc"
