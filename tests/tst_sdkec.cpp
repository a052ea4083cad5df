// SPDX-License-Identifier: MIT
// Execution contexts of the component SDK and the manager's internals OpenRTM-aist code reaches:
// ExtTrig, OpenHRP and Simulator contexts driven by tick(), the type chosen by
// `exec_cxt.periodic.type` (in this process and in rtmanager), and the Manager's members for
// contexts, components, modules and naming.
#include "sdkinprocess.h"

#include <rtm/DataFlowComponentBase.h>
#include <rtm/ECFactory.h>
#include <rtm/ExtTrigExecutionContext.h>
#include <rtm/Manager.h>
#include <rtm/MultilayerCompositeEC.h>
#include <rtm/ManagerServant.h>
#include <rtm/NamingManager.h>
#include <rtm/ObjectManager.h>
#include <rtm/OpenHRPExecutionContext.h>
#include <rtm/PeriodicExecutionContext.h>
#include <rtm/SimulatorExecutionContext.h>
#include <rtm/CorbaConsumer.h>
#include <rtm/LogstreamFile.h>
#include <rtm/DefaultPeriodicTask.h>
#include <rtm/ExecutionContextWorker.h>
#include <rtm/PeriodicTaskFactory.h>
#include <rtm/RTObjectStateMachine.h>
#include <rtm/StateMachine.h>
#include <coil/PeriodicTask.h>
#include <rtm/DefaultConfiguration.h>
#include <rtm/ExecutionContextProfile.h>
#include <rtm/FactoryInit.h>
#include <rtm/ManagerConfig.h>
#include <rtm/ModuleManager.h>
#include <rtm/NumberingPolicy.h>
#include <rtm/NamingServiceNumberingPolicy.h>
#include <rtm/NodeNumberingPolicy.h>

#include <manager.h>

#include "livesystem.h"
#include "sdkproject.h"

#include <QtTest>

#include <atomic>
#include <string>
#include <vector>

namespace {

const char *const counterSpec[] = {"implementation_id", "SdkCounter", "type_name", "SdkCounter",
                                   "description", "counts its cycles", "version", "1.0.0", "vendor",
                                   "RTStudioTests", "category", "test", "activity_type", "PERIODIC", "kind",
                                   "DataFlowComponent", "max_instance", "0", "language", "C++", "lang_type",
                                   "compile", ""};

/// Counts the callbacks its contexts make.
class SdkCounter : public RTC::DataFlowComponentBase
{
public:
    explicit SdkCounter(RTC::Manager *manager)
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
        ++executions;
        return RTC::RTC_OK;
    }

    std::atomic<int> activations{0};
    std::atomic<int> deactivations{0};
    std::atomic<int> executions{0};
};

/// A context type that is not one of the built-in engines: the manager must refuse it by name.
class EnginelessContext : public RTC::ExecutionContextBase
{
public:
    EnginelessContext()
        : RTC::ExecutionContextBase("engineless")
    {
    }
};

/// The SDO status value @p name of @p rtc as text; empty when there is none.
QString statusOf(RTC::RTObject_ptr rtc, const char *name)
{
    try {
        CORBA::Any_var value = rtc->get_status(name);
        const char *text = nullptr;
        if (value >>= text)
            return QString::fromUtf8(text);
    } catch (const CORBA::Exception &) {
    }
    return {};
}

/// Records the actions a StateMachine calls.
struct Recorder
{
    using States = RTC_Utils::StateHolder<int>;
    void entry(const States &s) { log.push_back("entry" + std::to_string(s.curr)); }
    void exit(const States &s) { log.push_back("exit" + std::to_string(s.curr)); }
    void run(const States &s) { log.push_back("do" + std::to_string(s.curr)); }
    std::vector<std::string> log;
};

struct ByName
{
    explicit ByName(const std::string *object)
        : name(*object)
    {
    }
    explicit ByName(const std::string &id)
        : name(id)
    {
    }
    bool operator()(const std::string *object) const { return *object == name; }
    std::string name;
};

} // namespace

class TestSdkEc : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void extTrigRunsOneCyclePerRemoteTick();
    void extTrigTickedLocally();
    void synchronousTicks_data();
    void synchronousTicks();
    void simulatorChangesStatesAtOnce();
    void unknownTypeRefused();
    void registeredContextTypes();
    void createContextFromArguments();
    void managerMembers();
    void namingOnManagerAndObjectManager();
    void numberingPolicies();
    void moduleManager();
    void managerConfig();
    void executionContextProfile();
    void stateMachine();
    void executionContextWorker();
    void periodicTaskFactory();
    void logstreamFile();
    void rtmanagerHonoursContextType();
    void extTriggerExample();
    void multilayerCompositeRunsLayers();
    void cycleStepsAndTaskInterface();

private:
    SdkCounter *create(const QString &request);

    RTC::Manager *m_manager = nullptr;
};

void TestSdkEc::initTestCase()
{
    m_manager = SdkTest::startInProcessManager(
        "tst_sdkec", {"manager.modules.load_path:" + QFileInfo(MANAGER_TEST_MODULE).path().toUtf8()});
    QVERIFY(m_manager != nullptr);
    coil::Properties counter(counterSpec);
    QVERIFY(m_manager->registerFactory(counter, RTC::Create<SdkCounter>, RTC::Delete<SdkCounter>));
}

void TestSdkEc::cleanupTestCase()
{
    QVERIFY(SdkTest::stopInProcessManager(m_manager));
}

SdkCounter *TestSdkEc::create(const QString &request)
{
    return dynamic_cast<SdkCounter *>(m_manager->createComponent(request.toUtf8().constData()));
}

void TestSdkEc::extTrigRunsOneCyclePerRemoteTick()
{
    SdkCounter *counter = create("SdkCounter?instance_name=remoteTicked&exec_cxt.periodic.type=ExtTrigExecutionContext");
    QVERIFY(counter);
    // As OpenRTM's ConnectorComp: the component's own context from its reference, narrowed to
    // the ExtTrig service through a stringified reference, then activate and tick.
    CORBA::ORB_var orb = m_manager->getORB();
    RTC::RTObject_var rtc = counter->getObjRef();
    CORBA::String_var ior = orb->object_to_string(rtc);
    RTC::CorbaConsumer<RTC::RTObject> component;
    QVERIFY(component.setObject(CORBA::Object_var(orb->string_to_object(ior)).in()));
    RTC::ExecutionContextList_var owned = component->get_owned_contexts();
    QCOMPARE(owned->length(), CORBA::ULong(1));
    RTC::CorbaConsumer<OpenRTM::ExtTrigExecutionContextService> ec;
    QVERIFY(ec.setObject(owned[CORBA::ULong(0)]));
    QCOMPARE(owned[CORBA::ULong(0)]->activate_component(component._ptr()), RTC::RTC_OK);
    QCOMPARE(counter->activations.load(), 1);
    RTC::ExecutionContextProfile_var profile = ec->get_profile();
    const char *type = nullptr;
    QVERIFY(profile->properties.length() > 0 && (profile->properties[0].value >>= type));
    QCOMPARE(QString(type), QString("ExtTrigExecutionContext"));

    // As OpenRTM's, activating runs one cycle of its own; then one per tick.
    QTRY_COMPARE_WITH_TIMEOUT(counter->executions.load(), 1, 5000);
    for (int i = 0; i < 3; ++i)
        ec->tick();
    QTRY_COMPARE_WITH_TIMEOUT(counter->executions.load(), 4, 5000);
    ec->tick();
    QTRY_COMPARE_WITH_TIMEOUT(counter->executions.load(), 5, 5000);
    // A context that only runs when ticked: a periodic one next to it runs many cycles meanwhile.
    SdkCounter *periodic = create("SdkCounter?instance_name=freeRunning&exec_cxt.periodic.rate=500");
    QVERIFY(periodic);
    QCOMPARE(periodic->activate(0), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(periodic->executions.load() >= 20, 5000);
    QCOMPARE(counter->executions.load(), 5);
    m_manager->deleteComponent(periodic);
    QCOMPARE(ec->deactivate_component(component._ptr()), RTC::RTC_OK);
    ec->tick();
    QCOMPARE(ec->get_component_state(component._ptr()), RTC::INACTIVE_STATE);
    m_manager->deleteComponent(counter);
}

void TestSdkEc::extTrigTickedLocally()
{
    SdkCounter *counter = create("SdkCounter?instance_name=localTicked&exec_cxt.periodic.type=ExtTrigExecutionContext");
    QVERIFY(counter);
    // The component's context is the SDK's class: C++ code reaches it as ExecutionContextBase.
    std::vector<Runtime::ExecutionContext *> contexts = counter->ownedContexts();
    QCOMPARE(contexts.size(), size_t(1));
    auto *ec = dynamic_cast<RTC::ExtTrigExecutionContext *>(contexts.front());
    QVERIFY(ec);
    QVERIFY(ec->isRunning());
    RTC::RTObject_var rtc = counter->getObjRef();
    QCOMPARE(ec->activateComponent(rtc), RTC::RTC_OK);
    QCOMPARE(ec->getComponentState(rtc), RTC::ACTIVE_STATE);
    QTRY_COMPARE_WITH_TIMEOUT(counter->executions.load(), 1, 5000);
    ec->tick();
    ec->tick();
    QTRY_COMPARE_WITH_TIMEOUT(counter->executions.load(), 3, 5000);
    // A stopped context ignores ticks.
    QCOMPARE(ec->stop(), RTC::RTC_OK);
    ec->tick();
    QCOMPARE(ec->pendingTicks(), 0UL);
    QCOMPARE(counter->executions.load(), 3);

    // A context from the factory, bound to the component, runs it when ticked too.
    RTC::ExecutionContextBase *extra = RTC::ExecutionContextFactory::instance().createObject("ExtTrigExecutionContext");
    QVERIFY(extra);
    QCOMPARE(extra->bindComponent(counter), RTC::RTC_OK);
    QCOMPARE(counter->ownedContexts().size(), size_t(2));
    QCOMPARE(extra->start(), RTC::RTC_OK);
    QCOMPARE(extra->activateComponent(rtc), RTC::RTC_OK);
    auto *extraTrig = dynamic_cast<RTC::ExtTrigExecutionContext *>(extra);
    QVERIFY(extraTrig);
    QTRY_COMPARE_WITH_TIMEOUT(counter->executions.load(), 4, 5000);
    extraTrig->tick();
    QTRY_COMPARE_WITH_TIMEOUT(counter->executions.load(), 5, 5000);
    m_manager->deleteComponent(counter);
}

void TestSdkEc::synchronousTicks_data()
{
    QTest::addColumn<QString>("type");
    QTest::newRow("OpenHRP") << "OpenHRPExecutionContext";
    QTest::newRow("Simulator") << "SimulatorExecutionContext";
}

void TestSdkEc::synchronousTicks()
{
    QFETCH(QString, type);
    SdkCounter *counter = create("SdkCounter?instance_name=sync" + type + "&exec_cxt.periodic.type=" + type);
    QVERIFY(counter);
    RTC::ExecutionContext_var context = counter->getExecutionContext(0);
    OpenRTM::ExtTrigExecutionContextService_var ec = OpenRTM::ExtTrigExecutionContextService::_narrow(context);
    QVERIFY(!CORBA::is_nil(ec));
    RTC::RTObject_var rtc = counter->getObjRef();
    QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    // Synchronous: the cycle is over when tick() returns.
    for (int i = 1; i <= 5; ++i) {
        ec->tick();
        QCOMPARE(counter->executions.load(), i);
    }
    auto *base = dynamic_cast<RTC::ExecutionContextBase *>(counter->ownedContexts().front());
    QVERIFY(base);
    QCOMPARE(QString::fromStdString(base->getProperties().getProperty("type")).isEmpty(), false);
    m_manager->deleteComponent(counter);
}

void TestSdkEc::simulatorChangesStatesAtOnce()
{
    SdkCounter *counter = create("SdkCounter?instance_name=simulated&exec_cxt.periodic.type=SimulatorExecutionContext");
    QVERIFY(counter);
    auto *ec = dynamic_cast<RTC::SimulatorExecutionContext *>(counter->ownedContexts().front());
    QVERIFY(ec);
    RTC::RTObject_var rtc = counter->getObjRef();
    QCOMPARE(ec->activate_component(rtc), RTC::RTC_OK);
    QCOMPARE(counter->activations.load(), 1);
    QCOMPARE(ec->get_component_state(rtc), RTC::ACTIVE_STATE);
    ec->tick();
    QCOMPARE(counter->executions.load(), 1);
    QCOMPARE(ec->deactivate_component(rtc), RTC::RTC_OK);
    QCOMPARE(counter->deactivations.load(), 1);
    QCOMPARE(ec->get_component_state(rtc), RTC::INACTIVE_STATE);
    ec->tick();
    QCOMPARE(counter->executions.load(), 1);
    m_manager->deleteComponent(counter);
}

void TestSdkEc::unknownTypeRefused()
{
    const size_t before = m_manager->getComponents().size();
    QVERIFY(!create("SdkCounter?instance_name=refused&exec_cxt.periodic.type=NoSuchExecutionContext"));
    QCOMPARE(m_manager->getComponents().size(), before);
    const QString error = QString::fromStdString(m_manager->runtime()->lastError());
    QVERIFY2(error.contains("unknown execution context type 'NoSuchExecutionContext'"), qPrintable(error));
    for (const char *known : {"PeriodicExecutionContext", "ExtTrigExecutionContext", "OpenHRPExecutionContext",
                              "SimulatorExecutionContext"})
        QVERIFY2(error.contains(known), qPrintable(error));
    QVERIFY(!RTC::ExecutionContextFactory::instance().createObject("NoSuchExecutionContext"));
}

void TestSdkEc::registeredContextTypes()
{
    RTC::ExecutionContextFactory &factory = RTC::ExecutionContextFactory::instance();
    QVERIFY(factory.hasFactory("PeriodicExecutionContext"));
    QVERIFY(!factory.hasFactory("SdkStepped"));
    QVERIFY(m_manager->registerECFactory("SdkStepped", RTC::ECCreate<RTC::OpenHRPExecutionContext>,
                                         RTC::ECDelete<RTC::OpenHRPExecutionContext>));
    QVERIFY(!m_manager->registerECFactory("SdkStepped", RTC::ECCreate<RTC::OpenHRPExecutionContext>,
                                          RTC::ECDelete<RTC::OpenHRPExecutionContext>));
    const std::vector<std::string> ids = factory.getIdentifiers();
    QVERIFY(std::find(ids.begin(), ids.end(), "SdkStepped") != ids.end());
    SdkCounter *counter = create("SdkCounter?instance_name=stepped&exec_cxt.periodic.type=SdkStepped");
    QVERIFY(counter);
    QVERIFY(dynamic_cast<RTC::OpenHRPExecutionContext *>(counter->ownedContexts().front()));
    m_manager->deleteComponent(counter);

    // Registered as OpenRTM-aist's own context modules do, straight in the factory.
    QCOMPARE(factory.addFactory("SdkGlobal", coil::Creator<RTC::ExecutionContextBase, RTC::ExtTrigExecutionContext>,
                                coil::Destructor<RTC::ExecutionContextBase, RTC::ExtTrigExecutionContext>),
             coil::FactoryReturn::OK);
    counter = create("SdkCounter?instance_name=global&exec_cxt.periodic.type=SdkGlobal");
    QVERIFY(counter);
    QVERIFY(dynamic_cast<RTC::ExtTrigExecutionContext *>(counter->ownedContexts().front()));
    m_manager->deleteComponent(counter);
    QCOMPARE(factory.removeFactory("SdkGlobal"), coil::FactoryReturn::OK);

    // A context class without an engine is refused when a component asks for it, naming it.
    QVERIFY(m_manager->registerECFactory("Engineless", RTC::ECCreate<EnginelessContext>,
                                         RTC::ECDelete<EnginelessContext>));
    QVERIFY(!create("SdkCounter?instance_name=engineless&exec_cxt.periodic.type=Engineless"));
    const QString error = QString::fromStdString(m_manager->runtime()->lastError());
    QVERIFY2(error.contains("'Engineless' has no runtime engine"), qPrintable(error));
    QCOMPARE(factory.removeFactory("Engineless"), coil::FactoryReturn::OK);
    QCOMPARE(factory.removeFactory("SdkStepped"), coil::FactoryReturn::OK);
    QVERIFY(!factory.hasFactory("SdkStepped"));
    // Its calls fail and say why instead of doing nothing.
    EnginelessContext engineless;
    QCOMPARE(engineless.start(), RTC::RTC_ERROR);
    QVERIFY(!engineless.isRunning());
}

void TestSdkEc::createContextFromArguments()
{
    RTC::ExecutionContextBase *ec = m_manager->createContext("OpenHRPExecutionContext?exec_cxt.periodic.rate=50");
    QVERIFY(ec);
    QCOMPARE(ec->getRate(), 50.0);
    QCOMPARE(ec->getPeriod(), std::chrono::nanoseconds(20000000));
    QCOMPARE(ec->getKind(), RTC::PERIODIC);
    QCOMPARE(QString(RTC::ExecutionContextBase::getKindString(ec->getKind())), QString("PERIODIC"));
    QVERIFY(!ec->isRunning());
    QCOMPARE(RTC::ExecutionContextFactory::instance().deleteObject(ec), coil::FactoryReturn::OK);
    QVERIFY(ec == nullptr);
    QVERIFY(!m_manager->createContext("NoSuchExecutionContext"));
}

void TestSdkEc::managerMembers()
{
    SdkCounter *first = create("SdkCounter?instance_name=listedA");
    SdkCounter *second = create("SdkCounter?instance_name=listedB");
    QVERIFY(first && second);
    std::vector<RTC::RTObject_impl *> components = m_manager->getComponents();
    QVERIFY(std::find(components.begin(), components.end(), first) != components.end());
    QVERIFY(std::find(components.begin(), components.end(), second) != components.end());
    QCOMPARE(m_manager->getComponent("listedB"), static_cast<RTC::RTObject_impl *>(second));
    QVERIFY(!m_manager->getComponent("nobody"));
    std::vector<std::string> factories = m_manager->getModulesFactories();
    QVERIFY(std::find(factories.begin(), factories.end(), "SdkCounter") != factories.end());

    // A component the program made itself, registered afterwards.
    auto *own = new SdkCounter(m_manager);
    own->setInstanceName("programMade");
    QCOMPARE(own->initialize(), RTC::RTC_OK);
    QVERIFY(m_manager->registerComponent(own));
    QCOMPARE(m_manager->getComponent("programMade"), static_cast<RTC::RTObject_impl *>(own));
    QVERIFY(!m_manager->registerComponent(own));
    QVERIFY(m_manager->unregisterComponent(own));
    QVERIFY(!m_manager->getComponent("programMade"));
    QVERIFY(m_manager->registerComponent(own));

    // Finalized components go at cleanupComponents().
    m_manager->notifyFinalized(first);
    m_manager->notifyFinalized(own);
    QVERIFY(m_manager->getComponent("listedA"));
    m_manager->cleanupComponents();
    QTRY_VERIFY_WITH_TIMEOUT(!m_manager->getComponent("listedA"), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!m_manager->getComponent("programMade"), 5000);
    QVERIFY(m_manager->getComponent("listedB"));
    m_manager->deleteComponent(second);

    QCOMPARE(m_manager->load(MANAGER_TEST_MODULE.toStdString(), ""), RTC::RTC_OK);
    const std::vector<coil::Properties> loaded = m_manager->getLoadedModules();
    QCOMPARE(loaded.size(), size_t(1));
    m_manager->unload(qPrintable(MANAGER_TEST_MODULE));
    QVERIFY(m_manager->getLoadedModules().empty());

    // Periodic tasks and delayed calls run on the manager's timer thread.
    std::atomic<int> periodic{0};
    std::atomic<int> delayed{0};
    RTC::Manager::TaskId task = m_manager->addTask([&periodic] { ++periodic; }, std::chrono::milliseconds(100));
    m_manager->invoke([&delayed] { ++delayed; });
    QTRY_VERIFY_WITH_TIMEOUT(periodic.load() >= 2, 5000);
    QTRY_COMPARE_WITH_TIMEOUT(delayed.load(), 1, 5000);
    RTC::Manager::removeTask(task);
    const int stoppedAt = periodic.load();
    std::atomic<int> later{0};
    m_manager->invoke([&later] { ++later; }, std::chrono::milliseconds(300));
    QTRY_COMPARE_WITH_TIMEOUT(later.load(), 1, 5000);
    QVERIFY(periodic.load() <= stoppedAt + 1);
    QCOMPARE(delayed.load(), 1);

    // What the loggers write reaches the streams added to the manager's buffer.
    struct Capture : coil::LogStreamBuffer
    {
        void write(int level, const std::string &name, const std::string &, const std::string &mes) override
        {
            std::lock_guard<std::mutex> lock(mutex);
            lines.push_back(std::to_string(level) + " " + name + " " + mes);
        }
        std::mutex mutex;
        std::vector<std::string> lines;
    } capture;
    m_manager->getLogStreamBuf().addStream(&capture);
    RTC::Logger &rtclog = m_manager->getLogbuf("sdkec");
    RTC_ERROR(("logged %d", 42));
    m_manager->getLogStreamBuf().removeStream(&capture);
    RTC_ERROR(("not seen"));
    {
        const std::vector<std::string> expected{std::to_string(RTC::Logger::RTL_ERROR) + " sdkec logged 42"};
        std::lock_guard<std::mutex> lock(capture.mutex);
        QCOMPARE(capture.lines, expected);
    }

    PortableServer::POA_var poa = m_manager->getPOA();
    PortableServer::POA_var shortcut = m_manager->getShortCutPOA();
    QVERIFY(poa->_is_equivalent(shortcut));
    RTM::Manager_var self = m_manager->getManagerServant().getObjRef();
    QVERIFY(!CORBA::is_nil(self));
    QCOMPARE(bool(m_manager->getManagerServant().is_master()), m_manager->runtime()->isMaster());
}

void TestSdkEc::namingOnManagerAndObjectManager()
{
    SdkCounter *counter = create("SdkCounter?instance_name=named");
    QVERIFY(counter);
    RTC::NamingManager naming(m_manager);
    naming.registerNameServer("manager", "");
    naming.registerNameServer("nonsense", "");
    QCOMPARE(naming.getNameServices().size(), size_t(1));
    RTC::RTCList found = naming.string_to_component("named");
    QCOMPARE(found.length(), CORBA::ULong(1));
    RTC::RTObject_var rtc = counter->getObjRef();
    QVERIFY(found[0]->_is_equivalent(rtc));
    naming.bindObject("named", counter);
    QCOMPARE(naming.getObjects().size(), size_t(1));
    naming.unbindObject("named");
    QVERIFY(naming.getObjects().empty());
    m_manager->deleteComponent(counter);

    std::string a("a"), b("b");
    ObjectManager<std::string, std::string, ByName> objects;
    QVERIFY(objects.registerObject(&a));
    QVERIFY(objects.registerObject(&b));
    std::string again("a");
    QVERIFY(!objects.registerObject(&again));
    QCOMPARE(objects.find("b"), &b);
    QCOMPARE(objects.getObjects().size(), size_t(2));
    QCOMPARE(objects.unregisterObject("a"), &a);
    QVERIFY(!objects.find("a"));
    QCOMPARE(objects.getObjects().size(), size_t(1));
}

void TestSdkEc::numberingPolicies()
{
    RTM::FactoryInit();
    RTM::NumberingPolicyFactory &factory = RTM::NumberingPolicyFactory::instance();
    for (const char *id : {"process_unique", "node_unique", "ns_unique"})
        QVERIFY2(factory.hasFactory(id), id);
    QVERIFY(!factory.createObject("no_such_policy"));

    RTM::NumberingPolicyBase *policy = factory.createObject("process_unique");
    QVERIFY(policy);
    int a = 0, b = 0, c = 0;
    QCOMPARE(policy->onCreate(&a), std::string("0"));
    QCOMPARE(policy->onCreate(&b), std::string("1"));
    policy->onDelete(&a);
    // The freed number is given out again first.
    QCOMPARE(policy->onCreate(&c), std::string("0"));
    QVERIFY_THROWS_EXCEPTION(RTM::NumberingPolicyBase::ObjectNotFound, policy->onDelete(&a));
    QCOMPARE(factory.deleteObject(policy), coil::FactoryReturn::OK);

    // node_unique skips the numbers of the components that run.
    SdkCounter *first = create("SdkCounter?instance_name=SdkCounter0");
    SdkCounter *second = create("SdkCounter?instance_name=SdkCounter1");
    QVERIFY(first && second);
    RTM::NodeNumberingPolicy node;
    QCOMPARE(node.onCreate(first), std::string("2"));
    node.onDelete(first);
    m_manager->deleteComponent(first);
    QTRY_VERIFY_WITH_TIMEOUT(!m_manager->getComponent("SdkCounter0"), 5000);
    QCOMPARE(node.onCreate(second), std::string("0"));
    m_manager->deleteComponent(second);
}

void TestSdkEc::moduleManager()
{
    const QFileInfo module(MANAGER_TEST_MODULE);
    coil::Properties prop;
    prop.setProperty("manager.modules.load_path", module.path().toStdString());
    RTC::ModuleManager modules(prop);
    QCOMPARE(modules.getLoadPath().size(), size_t(1));
    QCOMPARE(modules.getInitFuncName("/x/ManagerTestModule.so"), std::string("ManagerTestModuleInit"));
    bool listed = false;
    for (coil::Properties &loadable : modules.getLoadableModules())
        listed = listed || loadable.getProperty("module_file_name") == module.fileName().toStdString();
    QVERIFY(listed);
    // Found in the load path by its stem, loaded once.
    const std::string path = modules.load("ManagerTestModule");
    QCOMPARE(QFileInfo(QString::fromStdString(path)).canonicalFilePath(), module.canonicalFilePath());
    QCOMPARE(modules.getLoadedModules().size(), size_t(1));
    QVERIFY(modules.symbol(path, "ManagerTestModuleInit") != nullptr);
    QVERIFY_THROWS_EXCEPTION(RTC::ModuleManager::SymbolNotFound, modules.symbol(path, "noSuchFunction"));
    QVERIFY_THROWS_EXCEPTION(RTC::ModuleManager::FileNotFound, modules.load("NoSuchModule"));
    QVERIFY_THROWS_EXCEPTION(RTC::ModuleManager::NotAllowedOperation,
                             modules.load(module.absoluteFilePath().toStdString()));
    modules.allowAbsolutePath();
    // The same file by its absolute path: still one module.
    QCOMPARE(modules.load(module.absoluteFilePath().toStdString()), module.absoluteFilePath().toStdString());
    QCOMPARE(modules.getLoadedModules().size(), size_t(1));
    modules.unload(path);
    QVERIFY(modules.getLoadedModules().empty());
    modules.load("ManagerTestModule");
    QCOMPARE(modules.getLoadedModules().size(), size_t(1));
    modules.unloadAll();
    QVERIFY(modules.getLoadedModules().empty());
    QVERIFY_THROWS_EXCEPTION(RTC::ModuleManager::NotFound, modules.unload(path));
}

void TestSdkEc::managerConfig()
{
    const char *args[] = {"prog", "-o", "exec_cxt.periodic.type:ExtTrigExecutionContext", "-f", "/nonexistent/rtc.conf",
                          "-i"};
    std::vector<char *> argv;
    for (const char *arg : args)
        argv.push_back(const_cast<char *>(arg));
    RTC::ManagerConfig config(int(argv.size()), argv.data());
    coil::Properties prop;
    config.configure(prop);
    QCOMPARE(prop.getProperty("exec_cxt.periodic.type"), std::string("ExtTrigExecutionContext"));
    QCOMPARE(prop.getProperty("exec_cxt.periodic.rate"), std::string("1000"));
    QVERIFY(!prop.getProperty("os.name").empty());
    QCOMPARE(config.getConfig().getProperty("exec_cxt.periodic.type"), std::string("ExtTrigExecutionContext"));
    const char *bad[] = {"prog", "-f", "/nonexistent/rtc.conf"};
    std::vector<char *> badArgv;
    for (const char *arg : bad)
        badArgv.push_back(const_cast<char *>(arg));
    RTC::ManagerConfig refused;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, refused.init(int(badArgv.size()), badArgv.data()));
    coil::Properties defaults(RTC::default_config);
    QCOMPARE(defaults.getProperty("exec_cxt.periodic.type"), std::string("PeriodicExecutionContext"));
}

void TestSdkEc::executionContextProfile()
{
    RTC_impl::ExecutionContextProfile profile;
    QCOMPARE(profile.getKind(), RTC::PERIODIC);
    QCOMPARE(QString(profile.getKindString()), QString("PERIODIC"));
    QCOMPARE(profile.setRate(0.0), RTC::BAD_PARAMETER);
    QCOMPARE(profile.setRate(250.0), RTC::RTC_OK);
    QCOMPARE(profile.getPeriod(), std::chrono::nanoseconds(4000000));
    QCOMPARE(profile.setPeriod(std::chrono::milliseconds(20)), RTC::RTC_OK);
    QCOMPARE(profile.getRate(), 50.0);
    SdkCounter *counter = create("SdkCounter?instance_name=profiled");
    QVERIFY(counter);
    RTC::RTObject_var rtc = counter->getObjRef();
    QCOMPARE(profile.addComponent(rtc), RTC::RTC_OK);
    QCOMPARE(profile.setOwner(rtc), RTC::RTC_OK);
    QCOMPARE(profile.getComponentList().length(), CORBA::ULong(1));
    RTC::RTObject_var owner = profile.getOwner();
    QVERIFY(owner->_is_equivalent(rtc));
    coil::Properties props;
    props.setProperty("type", "ExtTrigExecutionContext");
    profile.setProperties(props);
    QCOMPARE(profile.getProperties().getProperty("type"), std::string("ExtTrigExecutionContext"));
    RTC::ExecutionContextProfile_var copy = profile.getProfile();
    QCOMPARE(copy->rate, 50.0);
    QCOMPARE(profile.removeComponent(rtc), RTC::RTC_OK);
    QCOMPARE(profile.removeComponent(rtc), RTC::BAD_PARAMETER);
    QCOMPARE(profile.getComponentList().length(), CORBA::ULong(0));
    m_manager->deleteComponent(counter);
}

void TestSdkEc::stateMachine()
{
    Recorder recorder;
    RTC_Utils::StateMachine<int, Recorder> machine(3);
    machine.setListener(&recorder);
    QVERIFY(machine.setEntryAction(1, &Recorder::entry));
    QVERIFY(machine.setDoAction(1, &Recorder::run));
    QVERIFY(machine.setExitAction(1, &Recorder::exit));
    RTC_Utils::StateHolder<int> start{0, 0, 0};
    machine.setStartState(start);
    machine.worker();
    QVERIFY(recorder.log.empty());
    machine.goTo(1);
    QVERIFY(machine.isIn(0));
    machine.worker();
    QVERIFY(machine.isIn(1));
    machine.worker();
    machine.goTo(2);
    machine.worker();
    QCOMPARE(machine.getState(), 2);
    QCOMPARE(machine.getStates().prev, 1);
    const std::vector<std::string> expected{"entry1", "do1", "exit1"};
    QCOMPARE(recorder.log, expected);
}

void TestSdkEc::executionContextWorker()
{
    SdkCounter *counter = create("SdkCounter?instance_name=worked");
    QVERIFY(counter);
    RTC::RTObject_var rtc = counter->getObjRef();
    // A context of the runtime lends its reference, as a context built on the worker would.
    RTC::ExecutionContextService_var ref = counter->ownedContexts().front()->_this();
    RTC_impl::ExecutionContextWorker worker;
    worker.setECRef(ref);
    QCOMPARE(worker.addComponent(rtc), RTC::RTC_OK);
    QCOMPARE(worker.addComponent(rtc), RTC::PRECONDITION_NOT_MET);
    QCOMPARE(worker.start(), RTC::RTC_OK);
    QCOMPARE(worker.getComponentState(rtc), RTC::INACTIVE_STATE);
    RTC_impl::RTObjectStateMachine *machine = nullptr;
    QCOMPARE(worker.activateComponent(rtc, machine), RTC::RTC_OK);
    QVERIFY(machine);
    QVERIFY(machine->isNextState(RTC::ACTIVE_STATE));
    QCOMPARE(worker.waitActivateComplete(machine), RTC::RTC_OK);
    QCOMPARE(counter->activations.load(), 1);
    QVERIFY(worker.isAllCurrentState(RTC::ACTIVE_STATE));
    worker.invokeWorker();
    worker.invokeWorker();
    QCOMPARE(counter->executions.load(), 2);
    QCOMPARE(worker.activateComponent(rtc, machine), RTC::PRECONDITION_NOT_MET);
    QCOMPARE(worker.deactivateComponent(rtc, machine), RTC::RTC_OK);
    worker.invokeWorker();
    QCOMPARE(counter->deactivations.load(), 1);
    QCOMPARE(counter->executions.load(), 2);
    QCOMPARE(worker.getComponentState(rtc), RTC::INACTIVE_STATE);
    QCOMPARE(worker.removeComponent(rtc), RTC::RTC_OK);
    worker.updateComponentList();
    QCOMPARE(worker.getComponentState(rtc), RTC::CREATED_STATE);
    QCOMPARE(worker.stop(), RTC::RTC_OK);
    m_manager->deleteComponent(counter);
}

void TestSdkEc::periodicTaskFactory()
{
    DefaultPeriodicTaskInit();
    RTC::PeriodicTaskFactory &factory = RTC::PeriodicTaskFactory::instance();
    QVERIFY(factory.hasFactory("default"));
    QVERIFY(!factory.createObject("no_such_task"));
    coil::PeriodicTaskBase *task = factory.createObject("default");
    QVERIFY(dynamic_cast<RTC::DefaultPeriodicTask *>(task));
    std::atomic<int> runs{0};
    task->setTask([&runs] { ++runs; });
    task->setPeriod(std::chrono::milliseconds(1));
    task->activate();
    QTRY_VERIFY_WITH_TIMEOUT(runs.load() >= 3, 5000);
    task->finalize();
    QCOMPARE(factory.deleteObject(task), coil::FactoryReturn::OK);
    QVERIFY(task == nullptr);
}

void TestSdkEc::logstreamFile()
{
    LogstreamFileInit();
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("rtc.log").toStdString();
    RTC::LogstreamBase *stream = RTC::LogstreamFactory::instance().createObject("file");
    QVERIFY(stream);
    coil::Properties prop;
    prop.setProperty("file_name", path);
    QVERIFY(stream->init(prop));
    // One stream per file.
    RTC::LogstreamFile second;
    QVERIFY(!second.init(prop));
    coil::LogStreamBuffer *buffer = stream->getStreamBuffer();
    QVERIFY(buffer);
    buffer->write(RTC::Logger::RTL_ERROR, "sdkec", "Nov 29 01:00:00", "written through the stream");
    buffer->flush();
    QFile file(QString::fromStdString(path));
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray text = file.readAll();
    QVERIFY2(text.contains("ERROR: sdkec: written through the stream"), text.constData());
    QCOMPARE(RTC::LogstreamFactory::instance().deleteObject(stream), coil::FactoryReturn::OK);
    // Once the first is gone the file can be opened again.
    QVERIFY(second.init(prop));
    coil::Properties nowhere;
    nowhere.setProperty("file_name", "/nonexistent/dir/rtc.log");
    RTC::LogstreamFile refused;
    QVERIFY(!refused.init(nowhere));
}

void TestSdkEc::rtmanagerHonoursContextType()
{
    LiveTest::LiveSystem live;
    QString error;
    QVERIFY2(live.startNameServer(&error), qPrintable(error));
    const quint16 port = LiveTest::freePort();
    // As OpenRTM's ExtTrigger example: the type for every component comes from the configuration.
    QVERIFY2(live.startHostManager(RTMANAGER_PATH, port, "sdkec",
                                   {"exec_cxt.periodic.type=ExtTrigExecutionContext", "exec_cxt.periodic.rate=100"},
                                   &error),
             qPrintable(error));
    CORBA::ORB_var orb = m_manager->getORB();
    CORBA::Object_var object = orb->string_to_object(LiveTest::managerLocation(port).constData());
    RTM::Manager_var manager = RTM::Manager::_narrow(object);
    QVERIFY(!CORBA::is_nil(manager));

    RTC::RTObject_var ticked = manager->create_component("ConsoleIn?instance_name=Ticked");
    QVERIFY(!CORBA::is_nil(ticked));
    RTC::RTObject_var running =
        manager->create_component("ConsoleIn?instance_name=Running&exec_cxt.periodic.type=PeriodicExecutionContext");
    QVERIFY(!CORBA::is_nil(running));

    // The named one through the name server, as ConnectorComp finds ConsoleIn0.
    RTC::NamingManager naming(m_manager);
    naming.registerNameServer("corba", live.namingServer().toUtf8().constData());
    RTC::RTCList found = naming.string_to_component("sdkec.host_cxt/Ticked.rtc");
    QCOMPARE(found.length(), CORBA::ULong(1));
    QVERIFY(found[0]->_is_equivalent(ticked));

    RTC::ExecutionContextList_var owned = ticked->get_owned_contexts();
    QCOMPARE(owned->length(), CORBA::ULong(1));
    OpenRTM::ExtTrigExecutionContextService_var ec =
        OpenRTM::ExtTrigExecutionContextService::_narrow(owned[CORBA::ULong(0)]);
    QVERIFY(!CORBA::is_nil(ec));
    QCOMPARE(ec->activate_component(ticked), RTC::RTC_OK);
    QTRY_COMPARE_WITH_TIMEOUT(statusOf(ticked, "sent_count"), QString("1"), 5000);
    ec->tick();
    ec->tick();
    QTRY_COMPARE_WITH_TIMEOUT(statusOf(ticked, "sent_count"), QString("3"), 5000);

    RTC::ExecutionContextList_var periodic = running->get_owned_contexts();
    QVERIFY(CORBA::is_nil(OpenRTM::ExtTrigExecutionContextService::_narrow(periodic[CORBA::ULong(0)])));
    QCOMPARE(periodic[CORBA::ULong(0)]->activate_component(running), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(statusOf(running, "sent_count").toInt() >= 10, 5000);
    QCOMPARE(statusOf(ticked, "sent_count"), QString("3"));

    // Unknown types are refused, the manager saying which and what it knows.
    RTC::RTObject_var refused = manager->create_component("ConsoleIn?exec_cxt.periodic.type=Bogus");
    QVERIFY(CORBA::is_nil(refused));
    RTM::ManagerProfile_var profile = manager->get_profile();
    QString lastError;
    for (CORBA::ULong i = 0; i < profile->properties.length(); ++i) {
        const char *value = nullptr;
        if (std::string(profile->properties[i].name.in()) == "last_error" && (profile->properties[i].value >>= value))
            lastError = QString::fromUtf8(value);
    }
    QVERIFY2(lastError.contains("unknown execution context type 'Bogus'"), qPrintable(lastError));
    QVERIFY2(lastError.contains("ExtTrigExecutionContext"), qPrintable(lastError));
    live.stopAll();
}

void TestSdkEc::extTriggerExample()
{
    // OpenRTM-aist's ExtTrigger example, built against the SDK as it is: ConsoleIn and
    // ConsoleOut programs reading the example's rtc.conf, driven as its ConnectorComp does.
    const QString example = RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-examples/ExtTrigger");
    if (!QFileInfo::exists(example + "/rtc.conf"))
        QSKIP("the OpenRTM-aist examples corpus (shared/conformance/openrtm-examples beside the project) is absent");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QFile cmake(dir.filePath("CMakeLists.txt"));
    QVERIFY(cmake.open(QIODevice::WriteOnly | QIODevice::Text));
    cmake.write(QStringLiteral("cmake_minimum_required(VERSION 3.16)\n"
                               "project(ExtTriggerExample CXX)\n"
                               "find_package(OpenRTM REQUIRED)\n"
                               "set(example \"%1\")\n"
                               "foreach(name ConsoleIn ConsoleOut)\n"
                               "  add_executable(${name}Comp ${example}/${name}.cpp ${example}/${name}Comp.cpp)\n"
                               "  target_include_directories(${name}Comp PRIVATE ${example})\n"
                               "  target_link_libraries(${name}Comp OpenRTM::RTC)\n"
                               "endforeach()\n"
                               "add_executable(ConnectorComp ${example}/ConnectorComp.cpp)\n"
                               "target_link_libraries(ConnectorComp OpenRTM::RTC)\n")
                   .arg(example)
                   .toUtf8());
    cmake.close();
    QString log;
    QVERIFY2(SdkTest::buildProject(dir.path(), RTSTUDIO_BUILD_DIR, &log), qPrintable(log));

    LiveTest::LiveSystem live;
    QString error;
    QVERIFY2(live.startNameServer(&error), qPrintable(error));
    QFile original(example + "/rtc.conf");
    QVERIFY(original.open(QIODevice::ReadOnly | QIODevice::Text));
    QFile conf(dir.filePath("rtc.conf"));
    QVERIFY(conf.open(QIODevice::WriteOnly | QIODevice::Text));
    // The example's settings, then where this test's name server and endpoints are.
    conf.write(original.readAll());
    conf.write(QStringLiteral("\ncorba.nameservers: %1\ncorba.endpoints: 127.0.0.1:\ncorba.master_manager:\n")
                   .arg(live.namingServer())
                   .toUtf8());
    conf.close();
    const QStringList arguments{"-f", conf.fileName()};
    QProcess *in = live.startProcess(dir.filePath("build/ConsoleInComp"), arguments, "succeed.", &error);
    QVERIFY2(in, qPrintable(error));
    QProcess *out = live.startProcess(dir.filePath("build/ConsoleOutComp"), arguments, "succeed.", &error);
    QVERIFY2(out, qPrintable(error));

    RTC::NamingManager naming(m_manager);
    naming.registerNameServer("corba", live.namingServer().toUtf8().constData());
    RTC::RTCList consoleIn = naming.string_to_component("ConsoleIn0.rtc");
    RTC::RTCList consoleOut = naming.string_to_component("ConsoleOut0.rtc");
    QCOMPARE(consoleIn.length(), CORBA::ULong(1));
    QCOMPARE(consoleOut.length(), CORBA::ULong(1));
    RTC::PortServiceList_var inPorts = consoleIn[0]->get_ports();
    RTC::PortServiceList_var outPorts = consoleOut[0]->get_ports();
    QVERIFY(inPorts->length() > 0 && outPorts->length() > 0);
    RTC::ConnectorProfile profile;
    profile.connector_id = CORBA::string_dup("");
    profile.name = CORBA::string_dup("connector0");
    profile.ports.length(2);
    profile.ports[0] = RTC::PortService::_duplicate(inPorts[CORBA::ULong(0)]);
    profile.ports[1] = RTC::PortService::_duplicate(outPorts[CORBA::ULong(0)]);
    const char *const nvs[][2] = {{"dataport.interface_type", "corba_cdr"},
                                  {"dataport.dataflow_type", "push"},
                                  {"dataport.subscription_type", "flush"}};
    profile.properties.length(3);
    for (CORBA::ULong i = 0; i < 3; ++i) {
        profile.properties[i].name = CORBA::string_dup(nvs[i][0]);
        profile.properties[i].value <<= nvs[i][1];
    }
    QCOMPARE(inPorts[CORBA::ULong(0)]->connect(profile), RTC::RTC_OK);

    RTC::ExecutionContextList_var inContexts = consoleIn[0]->get_owned_contexts();
    RTC::ExecutionContextList_var outContexts = consoleOut[0]->get_owned_contexts();
    OpenRTM::ExtTrigExecutionContextService_var ec0 =
        OpenRTM::ExtTrigExecutionContextService::_narrow(inContexts[CORBA::ULong(0)]);
    OpenRTM::ExtTrigExecutionContextService_var ec1 =
        OpenRTM::ExtTrigExecutionContextService::_narrow(outContexts[CORBA::ULong(0)]);
    QVERIFY(!CORBA::is_nil(ec0) && !CORBA::is_nil(ec1));
    QCOMPARE(ec0->activate_component(consoleIn[0]), RTC::RTC_OK);
    QCOMPARE(ec1->activate_component(consoleOut[0]), RTC::RTC_OK);

    // Each cycle of ConsoleIn asks for one number, the first one run by its activation as on
    // OpenRTM-aist; each tick of ConsoleOut prints what came.
    QByteArray inText, outText;
    for (int value : {42, 7}) {
        if (value != 42)
            ec0->tick();
        QTRY_VERIFY_WITH_TIMEOUT((inText += in->readAllStandardOutput()).count("Please input number:")
                                     == (value == 42 ? 1 : 2),
                                 10000);
        in->write(QByteArray::number(value) + "\n");
        QTRY_VERIFY_WITH_TIMEOUT((inText += in->readAllStandardOutput()).contains("Sending to subscriber: "
                                                                                 + QByteArray::number(value)),
                                 10000);
        ec1->tick();
        QTRY_VERIFY_WITH_TIMEOUT((outText += out->readAllStandardOutput()).contains("Received: "
                                                                                   + QByteArray::number(value)),
                                 10000);
    }
    // No cycle ran without a tick: two prompts for two ticks.
    inText += in->readAllStandardOutput();
    QCOMPARE(inText.count("Please input number:"), 2);
    QCOMPARE(outText.count("Received:"), 2);
    live.stopAll();
}

void TestSdkEc::multilayerCompositeRunsLayers()
{
    SdkCounter *owner = create("SdkCounter?instance_name=layersOwner&exec_cxt.periodic.type=MultilayerCompositeEC"
                               "&exec_cxt.periodic.rate=200");
    SdkCounter *first = create("SdkCounter?instance_name=layerOne");
    SdkCounter *second = create("SdkCounter?instance_name=layerTwo");
    QVERIFY(owner && first && second);
    auto *ec = dynamic_cast<RTC_exp::MultilayerCompositeEC *>(owner->ownedContexts().front());
    QVERIFY(ec);
    RTC::RTObject_var firstRef = first->getObjRef();
    RTC::RTObject_var secondRef = second->getObjRef();
    ec->addTask({firstRef.in()});
    ec->addTask({secondRef.in()});
    QCOMPARE(ec->getComponentList().length(), CORBA::ULong(3));
    // Refused with a message: the runtime's engine owns the thread and the state machines.
    QCOMPARE(ec->svc(), -1);
    QVERIFY(ec->findComponent(firstRef.in()) == nullptr);

    RTC::RTObject_var ownerRef = owner->getObjRef();
    for (RTC::RTObject_ptr rtc : {ownerRef.in(), firstRef.in(), secondRef.in()})
        QCOMPARE(ec->activateComponent(rtc), RTC::RTC_OK);
    QTRY_VERIFY_WITH_TIMEOUT(second->executions.load() >= 3, 5000);
    QVERIFY(first->executions.load() >= 3);
    QVERIFY(owner->executions.load() >= 3);
    for (RTC::RTObject_ptr rtc : {secondRef.in(), firstRef.in(), ownerRef.in()})
        QCOMPARE(ec->deactivateComponent(rtc), RTC::RTC_OK);
    m_manager->deleteComponent(first);
    m_manager->deleteComponent(second);
    m_manager->deleteComponent(owner);
}

void TestSdkEc::cycleStepsAndTaskInterface()
{
    SdkCounter *counter = create("SdkCounter?instance_name=stepped&exec_cxt.periodic.type=OpenHRPExecutionContext");
    QVERIFY(counter);
    auto *base = dynamic_cast<RTC::ExecutionContextBase *>(counter->ownedContexts().front());
    QVERIFY(base);
    RTC::RTObject_var rtc = counter->getObjRef();
    QCOMPARE(base->activateComponent(rtc), RTC::RTC_OK);
    const int before = counter->executions.load();
    // The engine runs a cycle as one step: Do runs it, PreDo and PostDo refuse.
    base->invokeWorkerPreDo();
    base->invokeWorkerPostDo();
    QCOMPARE(counter->executions.load(), before);
    base->invokeWorkerDo();
    QCOMPARE(counter->executions.load(), before + 1);
    QCOMPARE(base->deactivateComponent(rtc), RTC::RTC_OK);
    m_manager->deleteComponent(counter);

    // ExtTrig's task interface belongs to the engine's thread: refused.
    RTC::ExecutionContextBase *made = RTC::ExecutionContextFactory::instance().createObject("ExtTrigExecutionContext");
    auto *extTrig = dynamic_cast<RTC::ExtTrigExecutionContext *>(made);
    QVERIFY(extTrig);
    QCOMPARE(extTrig->open(nullptr), -1);
    QCOMPARE(extTrig->svc(), -1);
    QCOMPARE(extTrig->close(0), -1);
    QCOMPARE(RTC::ExecutionContextFactory::instance().deleteObject(made), coil::FactoryReturn::OK);
}

QTEST_GUILESS_MAIN(TestSdkEc)
#include "tst_sdkec.moc"
