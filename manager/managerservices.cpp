// SPDX-License-Identifier: MIT
// The Manager's answers that reach beyond its own components: what its slaves host, restarting
// and forking manager processes, and its well-known objects for get_service().
#include "corbautil.h"
#include "managerdetail.h"

#include <mutex>
#include <thread>

namespace Runtime {

namespace {

// Asks every slave at once so that the whole answer takes one slave timeout at most, however many
// slaves are stopped or dead; their calls are bounded by the per-reference timeout set in addSlave.
template<typename Sequence, typename Query>
Sequence gather(const RTM::ManagerList &slaves, Query query)
{
    Sequence merged;
    std::mutex mutex;
    std::vector<std::thread> threads;
    for (CORBA::ULong i = 0; i < slaves.length(); ++i) {
        RTM::Manager_ptr slave = slaves[i];
        threads.emplace_back([&merged, &mutex, &query, slave] {
            try {
                const auto part = query(slave);
                std::lock_guard lock(mutex);
                appendSequence(merged, part.in());
            } catch (const CORBA::Exception &) {
                // A slave that is gone or does not answer in time is left out; the watchdog drops
                // it.
            }
        });
    }
    for (std::thread &thread : threads)
        thread.join();
    return merged;
}

} // namespace

RTC::RTCList Manager::slaveComponents()
{
    return gather<RTC::RTCList>(
        slaves(), [](RTM::Manager_ptr slave) { return RTC::RTCList_var(slave->get_components()); });
}

RTC::ComponentProfileList Manager::slaveComponentProfiles()
{
    return gather<RTC::ComponentProfileList>(slaves(), [](RTM::Manager_ptr slave) {
        return RTC::ComponentProfileList_var(slave->get_component_profiles());
    });
}

void Manager::restart()
{
    {
        std::lock_guard lock(m_mutex);
        if (m_stopping)
            return;
        m_restart = true;
    }
    shutdown();
}

bool Manager::forkSlave(std::string *error)
{
    // A master's new slave registers with it; a slave's new sibling registers with the same master.
    const std::string master = m_isMaster ? m_address : m_config.value("corba.master_manager");
    if (master.empty())
        return fail("fork: this manager has no master to register a new slave with", error);
    const std::string address = "127.0.0.1:" + std::to_string(freeLoopbackPort());
    const pid_t pid = startSlaveProcess(address, "manager_%p", master);
    if (pid < 0)
        return fail("fork: cannot start a new manager process", error);
    if (m_isMaster && CORBA::is_nil(RTM::Manager_var(waitForSlave(pid, address))))
        return fail("fork: the new manager at " + address + " did not start", error);
    return true;
}

CORBA::Object_ptr Manager::activate(PortableServer::ServantBase *servant)
{
    if (CORBA::is_nil(m_poa))
        return CORBA::Object::_nil();
    PortableServer::ObjectId_var id = m_poa->activate_object(servant);
    return m_poa->id_to_reference(id);
}

void Manager::setPackageInstaller(CORBA::Object_ptr installer)
{
    std::lock_guard lock(m_mutex);
    m_packageInstaller = CORBA::Object::_duplicate(installer);
}

CORBA::Object_ptr Manager::packageInstaller()
{
    std::lock_guard lock(m_mutex);
    return CORBA::Object::_duplicate(m_packageInstaller);
}

CORBA::Object_ptr Manager::service(const std::string &name)
{
    if (name == "manager")
        return CORBA::Object::_duplicate(m_self);
    if (name == "master") {
        if (m_isMaster)
            return CORBA::Object::_duplicate(m_self);
        RTM::ManagerList all = masters();
        return all.length() ? CORBA::Object::_duplicate(all[0]) : CORBA::Object::_nil();
    }
    if (name == "NameService" && m_config.isYes("naming.enable", true)) {
        const std::vector<std::string> servers
            = split(m_config.value("corba.nameservers", "localhost"), ',');
        if (servers.empty())
            return CORBA::Object::_nil();
        const std::string server = trimmed(servers.front());
        const std::string address
            = server.find(':') == std::string::npos ? server + ":2809" : server;
        return corbalocObject(address, "NameService");
    }
    return CORBA::Object::_nil();
}

} // namespace Runtime
