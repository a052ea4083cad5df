// SPDX-License-Identifier: MIT
// Checks the wire contract of the project's IDL through the omniidl-generated C++ code:
// repository ids, enumerator order, struct member order and operation
// signatures (parameter modes) that OpenRTM-aist 2.x peers rely on.

#include <BasicDataType.hh>
#include <ComponentObserver.hh>
#include <DataPort.hh>
#include <ExtendedDataTypes.hh>
#include <InterfaceDataTypes.hh>
#include <Manager.hh>
#include <OpenRTM.hh>
#include <RTC.hh>
#include <SDOPackage.hh>
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

QStringList memberNames(CORBA::TypeCode_ptr tc)
{
    QStringList names;
    const CORBA::ULong count = tc->member_count();
    for (CORBA::ULong i = 0; i < count; ++i)
        names << QString::fromLatin1(tc->member_name(i));
    return names;
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
    row("IDL:RTC/ComponentObserver:1.0", RTC::ComponentObserver::_PD_repoId);
    row("IDL:SimpleService/MyService:1.0", SimpleService::MyService::_PD_repoId);
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
    row("IDL:RTC/StatusKind:1.0", RTC::_tc_StatusKind);
    row("IDL:SimpleService/EchoList:1.0", SimpleService::_tc_EchoList);
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
    QTest::newRow("DependencyType") << memberNames(SDOPackage::_tc_DependencyType)
                                    << QStringList{"OWN", "OWNED", "NO_DEPENDENCY"};
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
}

void TestCorbaIdl::structMemberOrder()
{
    QFETCH(QStringList, actual);
    QFETCH(QStringList, expected);
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
    const QDir dir(QStringLiteral(RTSTUDIO_IDL_DIR));
    const QStringList expected{"BasicDataType.idl",     "ComponentObserver.idl", "DataPort.idl",
                               "ExtendedDataTypes.idl", "InterfaceDataTypes.idl", "Manager.idl",
                               "OpenRTM.idl",           "RTC.idl",               "SDOPackage.idl",
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
