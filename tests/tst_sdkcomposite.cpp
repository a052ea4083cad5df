// SPDX-License-Identifier: MIT
// The component SDK's PeriodicECSharedComposite in one process: an SDK program's RTC::Manager
// offers the type, and the composite drives components written against the SDK on its own
// execution context, in member order, from one thread.
#include "sdkinprocess.h"

#include <rtm/DataFlowComponentBase.h>
#include <rtm/Manager.h>
#include <rtm/PeriodicECSharedComposite.h>

#include <QtTest>

#include <algorithm>
#include <mutex>
#include <thread>
#include <vector>

namespace {

struct Call
{
    std::string instance;
    std::thread::id thread;
};

std::mutex callsMutex;
std::vector<Call> calls;

std::vector<Call> recordedCalls()
{
    std::lock_guard<std::mutex> lock(callsMutex);
    return calls;
}

int callsOf(const std::string &instance)
{
    const std::vector<Call> all = recordedCalls();
    return int(std::count_if(all.begin(), all.end(), [&](const Call &c) { return c.instance == instance; }));
}

const char *const recorderSpec[] = {"implementation_id", "Recorder", "type_name", "Recorder", "version", "1.0.0",
                                    "vendor", "RTStudioTests", "category", "test", "language", "C++",
                                    "exec_cxt.periodic.rate", "100", ""};

/// Records each onExecute with its thread; counts activations and deactivations.
class Recorder : public RTC::DataFlowComponentBase
{
public:
    explicit Recorder(RTC::Manager *manager)
        : RTC::DataFlowComponentBase(manager)
    {
    }
    RTC::ReturnCode_t onActivated(RTC::UniqueId) override
    {
        ++activations;
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onDeactivated(RTC::UniqueId) override
    {
        ++deactivations;
        return RTC::RTC_OK;
    }
    RTC::ReturnCode_t onExecute(RTC::UniqueId) override
    {
        std::lock_guard<std::mutex> lock(callsMutex);
        calls.push_back({getInstanceName(), std::this_thread::get_id()});
        return RTC::RTC_OK;
    }

    std::atomic<int> activations {0};
    std::atomic<int> deactivations {0};
};

} // namespace

class TestSdkComposite : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();

    void factoryIsRegistered();
    void membersRunInOrderOnOneThread();

private:
    RTC::Manager *m_manager = nullptr;
};

void TestSdkComposite::initTestCase()
{
    m_manager = SdkTest::startInProcessManager("tst_sdkcomposite");
    QVERIFY(m_manager != nullptr);
    coil::Properties recorder(recorderSpec);
    QVERIFY(m_manager->registerFactory(recorder, RTC::Create<Recorder>, RTC::Delete<Recorder>));
}

void TestSdkComposite::cleanupTestCase()
{
    QVERIFY(SdkTest::stopInProcessManager(m_manager));
}

void TestSdkComposite::factoryIsRegistered()
{
    // Without any module or call of its own, as in an OpenRTM-aist component program.
    const std::vector<std::string> factories = m_manager->getModulesFactories();
    QVERIFY(std::find(factories.begin(), factories.end(), "PeriodicECSharedComposite") != factories.end());
}

void TestSdkComposite::membersRunInOrderOnOneThread()
{
    std::vector<Recorder *> members;
    for (const char *name : {"A0", "B0", "C0"}) {
        auto *member = dynamic_cast<Recorder *>(
            m_manager->createComponent((std::string("Recorder?instance_name=") + name).c_str()));
        QVERIFY(member != nullptr);
        members.push_back(member);
    }
    RTC::RTObject_impl *created = m_manager->createComponent(
        "PeriodicECSharedComposite?instance_name=Comp0&conf.default.members=C0, A0, B0&exec_cxt.periodic.rate=100");
    auto *composite = dynamic_cast<RTC::PeriodicECSharedComposite *>(created);
    QVERIFY(composite != nullptr);
    QCOMPARE(std::string(composite->getCategory()), std::string("composite.PeriodicECShared"));

    SDOPackage::OrganizationList_var organizations = composite->get_owned_organizations();
    QCOMPARE(organizations->length(), CORBA::ULong(1));
    SDOPackage::SDOList_var sdos = organizations[0]->get_members();
    QStringList names;
    for (CORBA::ULong i = 0; i < sdos->length(); ++i)
        names << QString::fromUtf8(CORBA::String_var(sdos[i]->get_sdo_id()).in());
    QCOMPARE(names, QStringList({"C0", "A0", "B0"}));
    for (Recorder *member : members)
        QVERIFY(!RTC::ExecutionContext_var(member->getExecutionContext(0))->is_running());

    RTC::ExecutionContext_var shared = composite->getExecutionContext(0);
    RTC::RTObject_var self = composite->getObjRef();
    QCOMPARE(shared->activate_component(self), RTC::RTC_OK);
    for (Recorder *member : members)
        QTRY_COMPARE(member->activations.load(), 1);
    QTRY_VERIFY(callsOf("A0") >= 5 && callsOf("B0") >= 5 && callsOf("C0") >= 5);
    QCOMPARE(shared->deactivate_component(self), RTC::RTC_OK);
    for (Recorder *member : members)
        QTRY_COMPARE(member->deactivations.load(), 1);

    // One thread, and each period runs the members in the order the composite lists them.
    const std::vector<Call> all = recordedCalls();
    const std::vector<std::string> order {"C0", "A0", "B0"};
    for (std::size_t i = 0; i < all.size(); ++i) {
        QVERIFY(all[i].thread == all.front().thread);
        QCOMPARE(all[i].instance, order[i % order.size()]);
    }
}

QTEST_GUILESS_MAIN(TestSdkComposite)
#include "tst_sdkcomposite.moc"
