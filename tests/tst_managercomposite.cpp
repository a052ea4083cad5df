// SPDX-License-Identifier: MIT
// The composite component PeriodicECSharedComposite in a real rtmanager next to a real omniNames:
// created at start from rtc.conf keys and its own configuration file as OpenRTM-aist's Composite
// example does it, members listed through its SDO organization, run on its execution context,
// exported ports carrying data, an unknown member refused, and rtctl showing it.
#include "livesystem.h"

#include <Manager.hh>
#include <omniORB4/omniORB.h>

#include "common/nvlist.h"
#include "common/rtctlrunner.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QtTest>

namespace {

const char compositeName[] = "PeriodicECSharedComposite0";
const char hostContext[] = "comphost";

QString text(const char *value)
{
    return QString::fromUtf8(value);
}

void setNv(SDOPackage::NVList &list, const char *name, const char *value)
{
    const CORBA::ULong n = list.length();
    list.length(n + 1);
    list[n].name = name;
    list[n].value <<= value;
}

QStringList memberNames(const SDOPackage::SDOList &members)
{
    QStringList names;
    for (CORBA::ULong i = 0; i < members.length(); ++i) {
        CORBA::String_var id = members[i]->get_sdo_id();
        names << text(id.in());
    }
    return names;
}

QStringList portNames(RTC::RTObject_ptr rtc)
{
    QStringList names;
    RTC::PortServiceList_var ports = rtc->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        names << text(profile->name.in());
    }
    return names;
}

RTC::PortService_ptr portNamed(RTC::RTObject_ptr rtc, const QString &name)
{
    RTC::PortServiceList_var ports = rtc->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        if (text(profile->name.in()) == name)
            return RTC::PortService::_duplicate(ports[i]);
    }
    return RTC::PortService::_nil();
}

/// A status value (SDO get_status) as a number; -1 when it is not set yet.
int statusNumber(RTC::RTObject_ptr rtc, const char *name)
{
    try {
        CORBA::Any_var value = rtc->get_status(name);
        const char *s = nullptr;
        if (!(value.in() >>= s))
            return -1;
        bool ok = false;
        const int number = QString::fromUtf8(s).toInt(&ok);
        return ok ? number : -1;
    } catch (const CORBA::Exception &) {
        return -1;
    }
}

RTC::LifeCycleState stateIn(RTC::ExecutionContext_ptr context, RTC::RTObject_ptr rtc)
{
    return context->get_component_state(rtc);
}

} // namespace

class TestManagerComposite : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void cleanup();
    void cleanupTestCase();

    void compositeIsAnRtc();
    void membersThroughOrganization();
    void activationRunsMembersOnOneContext();
    void exportedPortsCarryData();
    void removedMemberRunsOnItsOwnAgain();
    void exportedPortsFollowConfiguration();
    void exitReleasesMembers();
    void requestGivesExportedPorts();
    void composedAfterCreation();
    void unknownMemberIsRefused();
    void rtctlShowsComposite();

private:
    RTC::RTObject_ptr component(const char *name);
    RTC::ExecutionContext_ptr ownContext(RTC::RTObject_ptr rtc);
    void connect(RTC::PortService_ptr out, RTC::PortService_ptr in);

    CORBA::ORB_var m_orb;
    std::unique_ptr<LiveTest::LiveSystem> m_live;
    std::unique_ptr<QTemporaryDir> m_dir;
    RTM::Manager_var m_manager;
    RTC::RTObject_var m_composite;
};

void TestManagerComposite::initTestCase()
{
    int argc = 0;
    m_orb = CORBA::ORB_init(argc, nullptr);
    omniORB::setClientCallTimeout(15000);
}

void TestManagerComposite::init()
{
    m_live = std::make_unique<LiveTest::LiveSystem>();
    QString error;
    QVERIFY2(m_live->startNameServer(&error), qPrintable(error));
    // The composite's configuration as OpenRTM-aist's Composite example gives it: a file named by
    // `composite.<category suffix>.<instance>.config_file` in rtc.conf.
    m_dir = std::make_unique<QTemporaryDir>();
    const QString conf = m_dir->filePath("composite.conf");
    QFile file(conf);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Text));
    file.write("conf.default.members: ConsoleIn0, ConsoleOut0\n"
               "conf.default.exported_ports: ConsoleIn0.out, ConsoleOut0.in\n");
    file.close();
    const quint16 port = LiveTest::freePort();
    const QStringList options {"corba.nameservers=" + m_live->namingServer(),
                               QStringLiteral("naming.formats=%1.host_cxt/%n.rtc").arg(hostContext),
                               QStringLiteral("manager.naming_formats=%1.host_cxt/%n.mgr").arg(hostContext),
                               "exec_cxt.periodic.rate=200",
                               "manager.components.precreate=ConsoleIn, ConsoleOut, PeriodicECSharedComposite",
                               "composite.PeriodicECShared.PeriodicECSharedComposite0.config_file=" + conf};
    QVERIFY2(m_live->startManager(RTMANAGER_PATH, port, options, &error), qPrintable(error));
    CORBA::Object_var object = m_orb->string_to_object(LiveTest::managerLocation(port).constData());
    m_manager = RTM::Manager::_narrow(object);
    QVERIFY(!CORBA::is_nil(m_manager));
    m_composite = component(compositeName);
    QVERIFY2(!CORBA::is_nil(m_composite), "the precreated composite is missing");
}

void TestManagerComposite::cleanup()
{
    m_composite = RTC::RTObject::_nil();
    m_manager = RTM::Manager::_nil();
    m_live.reset();
    m_dir.reset();
}

void TestManagerComposite::cleanupTestCase()
{
    m_orb->destroy();
}

RTC::RTObject_ptr TestManagerComposite::component(const char *name)
{
    RTC::RTCList_var found = m_manager->get_components_by_name(name);
    return found->length() == 1 ? RTC::RTObject::_duplicate(found[0]) : RTC::RTObject::_nil();
}

RTC::ExecutionContext_ptr TestManagerComposite::ownContext(RTC::RTObject_ptr rtc)
{
    RTC::ExecutionContextList_var owned = rtc->get_owned_contexts();
    return owned->length() > 0 ? RTC::ExecutionContext::_duplicate(owned[0]) : RTC::ExecutionContext::_nil();
}

void TestManagerComposite::connect(RTC::PortService_ptr out, RTC::PortService_ptr in)
{
    RTC::ConnectorProfile profile;
    profile.name = "composite";
    profile.connector_id = "";
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(out);
    profile.ports[1] = RTC::PortService::_duplicate(in);
    setNv(profile.properties, "dataport.interface_type", "corba_cdr");
    setNv(profile.properties, "dataport.dataflow_type", "push");
    setNv(profile.properties, "dataport.subscription_type", "flush");
    setNv(profile.properties, "dataport.data_type", "IDL:RTC/TimedLong:1.0");
    QCOMPARE(out->connect(profile), RTC::RTC_OK);
}

void TestManagerComposite::compositeIsAnRtc()
{
    RTC::ComponentProfile_var profile = m_composite->get_component_profile();
    QCOMPARE(text(profile->type_name), QStringLiteral("PeriodicECSharedComposite"));
    QCOMPARE(text(profile->category), QStringLiteral("composite.PeriodicECShared"));
    QCOMPARE(nv(profile->properties, "implementation_id"), QStringLiteral("PeriodicECSharedComposite"));
    QCOMPARE(text(profile->vendor), QStringLiteral("jp.go.aist"));
    // The factory is there in every rtmanager, as OpenRTM-aist's manager has it by default.
    RTM::ModuleProfileList_var factories = m_manager->get_factory_profiles();
    QStringList ids;
    for (CORBA::ULong i = 0; i < factories->length(); ++i)
        ids << nv(factories[i].properties, "implementation_id");
    QVERIFY2(ids.contains("PeriodicECSharedComposite"), qPrintable(ids.join(',')));
    // Its configuration set holds the two parameters, from the configuration file.
    SDOPackage::Configuration_var configuration = m_composite->get_configuration();
    SDOPackage::ConfigurationSet_var set = configuration->get_configuration_set("default");
    QCOMPARE(nv(set->configuration_data, "members").remove(' '), QStringLiteral("ConsoleIn0,ConsoleOut0"));
    QCOMPARE(nv(set->configuration_data, "exported_ports").remove(' '),
             QStringLiteral("ConsoleIn0.out,ConsoleOut0.in"));
}

void TestManagerComposite::membersThroughOrganization()
{
    SDOPackage::OrganizationList_var organizations = m_composite->get_owned_organizations();
    QCOMPARE(organizations->length(), CORBA::ULong(1));
    SDOPackage::Organization_var organization = SDOPackage::Organization::_duplicate(organizations[0]);
    SDOPackage::SDOList_var members = organization->get_members();
    QCOMPARE(memberNames(members.in()), QStringList({"ConsoleIn0", "ConsoleOut0"}));
    SDOPackage::SDOSystemElement_var owner = organization->get_owner();
    QVERIFY(owner->_is_equivalent(m_composite));
    SDOPackage::OrganizationProperty_var property = organization->get_organization_property();
    QCOMPARE(nv(property->properties, "members"), QStringLiteral("ConsoleIn0,ConsoleOut0"));
    QCOMPARE(nv(property->properties, "exported_ports"), QStringLiteral("ConsoleIn0.out,ConsoleOut0.in"));

    // Each member lists the organization among its own, and takes part in the composite's context
    // after the composite, in member order; their own contexts are stopped.
    CORBA::String_var id = organization->get_organization_id();
    RTC::ExecutionContext_var shared = ownContext(m_composite);
    RTC::ExecutionContextProfile_var ecProfile = RTC::ExecutionContextService::_narrow(shared)->get_profile();
    QCOMPARE(ecProfile->participants.length(), CORBA::ULong(3));
    QVERIFY(ecProfile->participants[0]->_is_equivalent(m_composite));
    const char *const names[] = {"ConsoleIn0", "ConsoleOut0"};
    for (CORBA::ULong i = 0; i < 2; ++i) {
        RTC::RTObject_var member = component(names[i]);
        QVERIFY(!CORBA::is_nil(member));
        QVERIFY2(ecProfile->participants[i + 1]->_is_equivalent(member), names[i]);
        SDOPackage::OrganizationList_var joined = member->get_organizations();
        QCOMPARE(joined->length(), CORBA::ULong(1));
        CORBA::String_var joinedId = joined[0]->get_organization_id();
        QCOMPARE(text(joinedId.in()), text(id.in()));
        RTC::ExecutionContext_var own = ownContext(member);
        QVERIFY2(!own->is_running(), names[i]);
        QVERIFY(member->is_alive(shared));
    }
}

void TestManagerComposite::activationRunsMembersOnOneContext()
{
    RTC::RTObject_var in = component("ConsoleIn0");
    RTC::RTObject_var out = component("ConsoleOut0");
    RTC::ExecutionContext_var shared = ownContext(m_composite);
    RTC::ExecutionContext_var ownIn = ownContext(in);
    QCOMPARE(stateIn(shared, in), RTC::INACTIVE_STATE);

    QCOMPARE(shared->activate_component(m_composite), RTC::RTC_OK);
    QTRY_COMPARE(stateIn(shared, m_composite), RTC::ACTIVE_STATE);
    QTRY_COMPARE(stateIn(shared, in), RTC::ACTIVE_STATE);
    QTRY_COMPARE(stateIn(shared, out), RTC::ACTIVE_STATE);
    // The member runs: its counter goes up, driven by the shared context while its own stays idle.
    QTRY_VERIFY(statusNumber(in, "sent_count") > 3);
    QCOMPARE(stateIn(ownIn, in), RTC::INACTIVE_STATE);
    QVERIFY(!ownIn->is_running());

    QCOMPARE(shared->deactivate_component(m_composite), RTC::RTC_OK);
    QTRY_COMPARE(stateIn(shared, m_composite), RTC::INACTIVE_STATE);
    QTRY_COMPARE(stateIn(shared, in), RTC::INACTIVE_STATE);
    QTRY_COMPARE(stateIn(shared, out), RTC::INACTIVE_STATE);
}

void TestManagerComposite::exportedPortsCarryData()
{
    // The members' exported ports are listed by the composite under their own names, and are the
    // members' ports themselves.
    QCOMPARE(portNames(m_composite), QStringList({"ConsoleIn0.out", "ConsoleOut0.in"}));
    RTC::RTObject_var in = component("ConsoleIn0");
    RTC::PortService_var exportedOut = portNamed(m_composite, "ConsoleIn0.out");
    RTC::PortService_var memberOut = portNamed(in, "ConsoleIn0.out");
    QVERIFY(exportedOut->_is_equivalent(memberOut));
    RTC::ComponentProfile_var profile = m_composite->get_component_profile();
    QCOMPARE(profile->port_profiles.length(), CORBA::ULong(2));

    // Outside the composite: a source feeding its ConsoleOut0.in, a sink fed by its ConsoleIn0.out.
    RTC::RTObject_var feed = m_manager->create_component("ConsoleIn?instance_name=Feed0");
    RTC::RTObject_var sink = m_manager->create_component("ConsoleOut?instance_name=Sink0");
    QVERIFY(!CORBA::is_nil(feed) && !CORBA::is_nil(sink));
    RTC::PortService_var feedOut = portNamed(feed, "Feed0.out");
    RTC::PortService_var sinkIn = portNamed(sink, "Sink0.in");
    RTC::PortService_var exportedIn = portNamed(m_composite, "ConsoleOut0.in");
    connect(feedOut, exportedIn);
    connect(exportedOut, sinkIn);

    RTC::ExecutionContext_var shared = ownContext(m_composite);
    QCOMPARE(RTC::ExecutionContext_var(ownContext(feed))->activate_component(feed), RTC::RTC_OK);
    QCOMPARE(RTC::ExecutionContext_var(ownContext(sink))->activate_component(sink), RTC::RTC_OK);
    QCOMPARE(shared->activate_component(m_composite), RTC::RTC_OK);
    RTC::RTObject_var out = component("ConsoleOut0");
    QTRY_VERIFY(statusNumber(out, "received_count") > 0);
    QTRY_VERIFY(statusNumber(sink, "received_count") > 0);
}

void TestManagerComposite::removedMemberRunsOnItsOwnAgain()
{
    SDOPackage::OrganizationList_var organizations = m_composite->get_owned_organizations();
    QCOMPARE(organizations->length(), CORBA::ULong(1));
    QVERIFY(organizations[0]->remove_member("ConsoleOut0"));
    SDOPackage::SDOList_var members = organizations[0]->get_members();
    QCOMPARE(memberNames(members.in()), QStringList({"ConsoleIn0"}));
    RTC::RTObject_var out = component("ConsoleOut0");
    RTC::ExecutionContext_var own = ownContext(out);
    QVERIFY(own->is_running());
    SDOPackage::OrganizationList_var joined = out->get_organizations();
    QCOMPARE(joined->length(), CORBA::ULong(0));
    QCOMPARE(portNames(m_composite), QStringList({"ConsoleIn0.out"}));
    RTC::ExecutionContext_var shared = ownContext(m_composite);
    QVERIFY(!out->is_alive(shared));

    // And joins again through the organization.
    SDOPackage::SDOList again;
    again.length(1);
    again[0] = SDOPackage::SDO::_duplicate(out);
    QVERIFY(organizations[0]->add_members(again));
    members = organizations[0]->get_members();
    QCOMPARE(memberNames(members.in()), QStringList({"ConsoleIn0", "ConsoleOut0"}));
    QVERIFY(!own->is_running());
    QVERIFY(out->is_alive(shared));

    // A member does not join twice, and the composite never joins itself.
    again.length(2);
    again[1] = SDOPackage::SDO::_duplicate(m_composite);
    organizations[0]->add_members(again);
    members = organizations[0]->get_members();
    QCOMPARE(memberNames(members.in()), QStringList({"ConsoleIn0", "ConsoleOut0"}));
    QVERIFY(shared->is_running());
    RTC::ExecutionContextProfile_var ecProfile = RTC::ExecutionContextService::_narrow(shared)->get_profile();
    QCOMPARE(ecProfile->participants.length(), CORBA::ULong(3));
}

void TestManagerComposite::exportedPortsFollowConfiguration()
{
    // Written as OpenRTM-aist's tools write it; a three-part name keeps its first and last parts.
    SDOPackage::Configuration_var configuration = m_composite->get_configuration();
    SDOPackage::ConfigurationSet set;
    set.id = "default";
    set.description = "";
    setNv(set.configuration_data, "exported_ports", "ConsoleOut0.extra.in");
    QVERIFY(configuration->set_configuration_set_values(set));
    QTRY_COMPARE(portNames(m_composite), QStringList({"ConsoleOut0.in"}));
    SDOPackage::OrganizationList_var organizations = m_composite->get_owned_organizations();
    SDOPackage::OrganizationProperty_var property = organizations[0]->get_organization_property();
    QCOMPARE(nv(property->properties, "exported_ports"), QStringLiteral("ConsoleOut0.in"));
    SDOPackage::ConfigurationSet_var stored = configuration->get_configuration_set("default");
    QCOMPARE(nv(stored->configuration_data, "exported_ports"), QStringLiteral("ConsoleOut0.in"));
}

void TestManagerComposite::requestGivesExportedPorts()
{
    // As OpenRTM-aist's manager: `exported_ports` in the request becomes the default set's value.
    RTC::RTObject_var feed = m_manager->create_component("ConsoleIn?instance_name=Feed0");
    QVERIFY(!CORBA::is_nil(feed));
    RTC::RTObject_var second = m_manager->create_component(
        "PeriodicECSharedComposite?instance_name=Second0&conf.default.members=Feed0&exported_ports=Feed0.old.out");
    QVERIFY(!CORBA::is_nil(second));
    QCOMPARE(portNames(second), QStringList({"Feed0.out"}));
    SDOPackage::Configuration_var configuration = second->get_configuration();
    SDOPackage::ConfigurationSet_var set = configuration->get_configuration_set("default");
    QCOMPARE(nv(set->configuration_data, "exported_ports"), QStringLiteral("Feed0.out"));
}

void TestManagerComposite::exitReleasesMembers()
{
    RTC::ExecutionContext_var shared = ownContext(m_composite);
    QCOMPARE(shared->activate_component(m_composite), RTC::RTC_OK);
    RTC::RTObject_var in = component("ConsoleIn0");
    QTRY_COMPARE(stateIn(shared, in), RTC::ACTIVE_STATE);

    // An active composite that exits stops its members and gives them their own contexts back.
    QCOMPARE(m_composite->exit(), RTC::RTC_OK);
    QTRY_VERIFY(CORBA::is_nil(RTC::RTObject_var(component(compositeName))));
    for (const char *name : {"ConsoleIn0", "ConsoleOut0"}) {
        RTC::RTObject_var member = component(name);
        RTC::ExecutionContext_var own = ownContext(member);
        QVERIFY2(own->is_running(), name);
        QCOMPARE(stateIn(own, member), RTC::INACTIVE_STATE);
        RTC::ExecutionContextList_var participating = member->get_participating_contexts();
        QCOMPARE(participating->length(), CORBA::ULong(0));
        SDOPackage::OrganizationList_var joined = member->get_organizations();
        QCOMPARE(joined->length(), CORBA::ULong(0));
    }
    // A member can now go on its own.
    QCOMPARE(RTC::ExecutionContext_var(ownContext(in))->activate_component(in), RTC::RTC_OK);
    const int sent = statusNumber(in, "sent_count");
    QTRY_VERIFY(statusNumber(in, "sent_count") > sent + 3);
}

void TestManagerComposite::composedAfterCreation()
{
    // rtshell's rtcomp: an empty composite, then the exported ports through its configuration,
    // then the members through its organization.
    RTC::RTObject_var source = m_manager->create_component("ConsoleIn?instance_name=Loose0");
    RTC::RTObject_var composite = m_manager->create_component("PeriodicECSharedComposite?&instance_name=Later0");
    QVERIFY(!CORBA::is_nil(source) && !CORBA::is_nil(composite));
    QCOMPARE(portNames(composite), QStringList());
    SDOPackage::Configuration_var configuration = composite->get_configuration();
    SDOPackage::ConfigurationSet set;
    set.id = "default";
    set.description = "";
    setNv(set.configuration_data, "exported_ports", "Loose0.out");
    QVERIFY(configuration->set_configuration_set_values(set));
    QVERIFY(configuration->activate_configuration_set("default"));
    SDOPackage::OrganizationList_var organizations = composite->get_owned_organizations();
    QCOMPARE(organizations->length(), CORBA::ULong(1));
    SDOPackage::SDOList added;
    added.length(1);
    added[0] = SDOPackage::SDO::_duplicate(source);
    QVERIFY(organizations[0]->add_members(added));
    QCOMPARE(portNames(composite), QStringList({"Loose0.out"}));
    RTC::ExecutionContext_var shared = ownContext(composite);
    QCOMPARE(shared->activate_component(composite), RTC::RTC_OK);
    QTRY_VERIFY(statusNumber(source, "sent_count") > 3);
    QVERIFY(!RTC::ExecutionContext_var(ownContext(source))->is_running());
}

void TestManagerComposite::unknownMemberIsRefused()
{
    RTC::RTObject_var refused = m_manager->create_component(
        "PeriodicECSharedComposite?instance_name=Broken0&conf.default.members=ConsoleIn0,Nobody7");
    QVERIFY(CORBA::is_nil(refused));
    RTM::ManagerProfile_var profile = m_manager->get_profile();
    const QString error = nv(profile->properties, "last_error");
    QVERIFY2(error.contains("Nobody7"), qPrintable(error));
    QVERIFY2(error.contains("Broken0"), qPrintable(error));
    QVERIFY(CORBA::is_nil(RTC::RTObject_var(component("Broken0"))));
    // The existing member it named is left as it was.
    RTC::RTObject_var in = component("ConsoleIn0");
    SDOPackage::OrganizationList_var joined = in->get_organizations();
    QCOMPARE(joined->length(), CORBA::ULong(1));
}

void TestManagerComposite::rtctlShowsComposite()
{
    const QString host = QStringLiteral("/%1/%2.host_cxt").arg(m_live->namingServer(), hostContext);
    const RtctlResult ls = runRtctlAt(host, {"ls"});
    QCOMPARE(ls.code, 0);
    QVERIFY2(ls.out.contains("PeriodicECSharedComposite0.rtc"), qPrintable(ls.out));
    const RtctlResult cat = runRtctlAt(host, {"cat", "PeriodicECSharedComposite0.rtc"});
    QVERIFY2(cat.code == 0, qPrintable(cat.err));
    QVERIFY2(cat.out.contains("composite.PeriodicECShared"), qPrintable(cat.out));
    QVERIFY2(cat.out.contains("DataOutPort: out") && cat.out.contains("DataInPort: in"), qPrintable(cat.out));
    // As rtshell's rtcat: the composite lists its members, a member names its composite.
    QVERIFY2(cat.out.contains(QRegularExpression("Type +Composite\n")), qPrintable(cat.out));
    QVERIFY2(cat.out.contains(QRegularExpression("Members +ConsoleIn0, ConsoleOut0\n")), qPrintable(cat.out));
    const RtctlResult member = runRtctlAt(host, {"cat", "ConsoleOut0.rtc"});
    QVERIFY2(member.out.contains(QRegularExpression("Parent +PeriodicECSharedComposite0\n")), qPrintable(member.out));
    QVERIFY2(member.out.contains(QRegularExpression("Type +Monolithic composite member\n")), qPrintable(member.out));
    // Its ports are the members' exported ones, named after their owners.
    const RtctlResult json = runRtctlAt(host, {"cat", "--json", "PeriodicECSharedComposite0.rtc"});
    QVERIFY2(json.code == 0, qPrintable(json.err));
    QStringList fullNames;
    for (const QJsonValue &port : json.json().object().value("ports").toArray())
        fullNames << port.toObject().value("fullName").toString();
    QCOMPARE(fullNames, QStringList({"ConsoleIn0.out", "ConsoleOut0.in"}));
    QCOMPARE(json.json().object().value("members").toVariant().toStringList(),
             QStringList({"ConsoleIn0", "ConsoleOut0"}));
}

QTEST_GUILESS_MAIN(TestManagerComposite)
#include "tst_managercomposite.moc"
