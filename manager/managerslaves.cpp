// SPDX-License-Identifier: MIT
// Master/slave side of the Manager: spawning slave processes, finding them by address or name,
// forwarding create requests, joining the master and dropping slaves that died.
#include "corbautil.h"
#include "managerdetail.h"

#include <omniORB4/omniORB.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <iostream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace Runtime {

namespace {

std::string normalizedHost(const std::string &host)
{
    return host == "localhost" || host == "0.0.0.0" ? std::string("127.0.0.1") : host;
}

bool unreachable(const CORBA::Exception &e)
{
    return CORBA::TRANSIENT::_downcast(&e) || CORBA::COMM_FAILURE::_downcast(&e)
           || CORBA::OBJECT_NOT_EXIST::_downcast(&e) || CORBA::TIMEOUT::_downcast(&e);
}

// "manager at HOST:PORT" or "manager NAME": the one a create request is forwarded to.
std::string targetName(const CreateRequest &request)
{
    if (request.managerAddress)
        return "manager at " + *request.managerAddress;
    return "manager " + request.managerName.value_or(std::string());
}

// Why `manager`, on another host, cannot take a request now; empty when it answers. omniORB keeps
// the connection to a manager after its process is gone, and the first call on it fails although
// a new process may listen there by now. _non_existent may be repeated on a broken connection (the
// repeat opens a new one); create_component may not, for it may have been carried out.
std::string remoteProblem(RTM::Manager_ptr manager)
{
    std::string problem;
    for (int attempt = 0; attempt < 2; ++attempt) {
        try {
            return manager->_non_existent() ? std::string("no manager there") : std::string();
        } catch (const CORBA::COMM_FAILURE &e) {
            problem = describeException(e);
        } catch (const CORBA::Exception &e) {
            return describeException(e);
        }
    }
    return problem;
}

} // namespace

bool Manager::isLocalHost(const std::string &host) const
{
    const std::string h = normalizedHost(host);
    return h == "127.0.0.1" || h == hostName() || h == m_address.substr(0, m_address.rfind(':'));
}

RTC::RTObject_ptr Manager::createRemote(const CreateRequest &request, std::string *error)
{
    const std::string forwarded = request.toStringWithoutManager();
    // One retry: a slave found dead on the first call is dropped and (if ours to start) restarted.
    for (int attempt = 0; attempt < 2; ++attempt) {
        bool remoteOnly = false;
        RTM::Manager_var target = slaveFor(request, &remoteOnly, error);
        if (CORBA::is_nil(target)) {
            if (error && error->empty())
                fail("create_component: no manager for the request", error);
            return RTC::RTObject::_nil();
        }
        if (sameObject(target, m_self))
            return createLocal(request, error);
        if (remoteOnly) {
            const std::string problem = remoteProblem(target);
            if (!problem.empty()) {
                fail("create_component: " + targetName(request) + " unreachable: " + problem,
                     error);
                return RTC::RTObject::_nil();
            }
        }
        try {
            RTC::RTObject_var created = target->create_component(forwarded.c_str());
            if (!CORBA::is_nil(created))
                return created._retn();
            RTM::ManagerProfile_var profile = target->get_profile();
            std::string reason = nvString(profile->properties, "rtstudio.create_error." + forwarded);
            if (reason.empty())
                reason = nvString(profile->properties, "last_error");
            fail("create_component on " + nvString(profile->properties, "address") + ": " + reason, error);
            return RTC::RTObject::_nil();
        } catch (const CORBA::Exception &e) {
            if (remoteOnly || !unreachable(e) || attempt == 1) {
                fail("create_component: " + targetName(request) + " unreachable: " + describeException(e),
                     error);
                return RTC::RTObject::_nil();
            }
            dropSlave(target);
        }
    }
    return RTC::RTObject::_nil();
}

RTM::Manager_ptr Manager::slaveFor(const CreateRequest &request, bool *remoteOnly, std::string *error)
{
    if (request.managerAddress) {
        std::string host;
        int port = 0;
        std::string message;
        if (!parseHostPort(*request.managerAddress, &host, &port, &message)) {
            fail("create_component: " + message, error);
            return RTM::Manager::_nil();
        }
        const std::string address = normalizedHost(host) + ':' + std::to_string(port);
        if (address == m_address)
            return RTM::Manager::_duplicate(m_self);
        std::lock_guard spawning(m_spawnMutex);
        {
            std::lock_guard lock(m_mutex);
            for (const auto &slave : m_slaves) {
                if (slave->address == address)
                    return RTM::Manager::_duplicate(slave->reference);
            }
        }
        if (isLocalHost(host))
            return spawnSlave(normalizedHost(host), port, "manager_%p", error);
        // Someone else's manager on another host: use it directly, without making it our slave.
        *remoteOnly = true;
        CORBA::Object_var object = corbalocObject(address, "manager");
        return RTM::Manager::_unchecked_narrow(object);
    }
    const std::string name = *request.managerName;
    if (name == m_instanceName)
        return RTM::Manager::_duplicate(m_self);
    // Each such request wants a process of its own: nothing to look up or share, so these slaves
    // start side by side.
    if (name == "manager_%p")
        return spawnSlave("127.0.0.1", reserveLoopbackPort(), name, error);
    std::lock_guard spawning(m_spawnMutex);
    {
        std::lock_guard lock(m_mutex);
        for (const auto &slave : m_slaves) {
            if (slave->name == name)
                return RTM::Manager::_duplicate(slave->reference);
        }
    }
    return spawnSlave("127.0.0.1", reserveLoopbackPort(), name, error);
}

int Manager::reserveLoopbackPort()
{
    // Two slaves starting at once must not be given one port: the kernel may hand out a port
    // again as soon as the probe's socket is closed.
    std::lock_guard lock(m_mutex);
    for (;;) {
        const int port = freeLoopbackPort();
        if (port == 0
            || m_startingSlaves.emplace("127.0.0.1:" + std::to_string(port), StartingSlave {})
                   .second)
            return port;
    }
}

RTM::Manager_ptr Manager::spawnSlave(const std::string &host, int port, const std::string &name, std::string *error)
{
    const std::string address = host + ':' + std::to_string(port);
    const auto release = [this, &address] {
        std::lock_guard lock(m_mutex);
        m_startingSlaves.erase(address);
    };
    if (!m_isMaster) {
        release();
        fail("create_component: only a master manager starts slaves", error);
        return RTM::Manager::_nil();
    }
    size_t running = 0;
    {
        std::lock_guard lock(m_mutex);
        // This one may be among those starting already (its port reserved).
        running = m_slaves.size() + m_startingSlaves.size() - m_startingSlaves.count(address);
    }
    if (double(running) >= configNumber("manager.slaves.max", DefaultSlaveLimit)) {
        release();
        fail("create_component: this master runs " + std::to_string(running)
                 + " slaves, as many as manager.slaves.max allows",
             error);
        return RTM::Manager::_nil();
    }
    const pid_t pid = startSlaveProcess(address, name, m_address);
    if (pid > 0) {
        std::lock_guard lock(m_mutex);
        m_startingSlaves[address] = {pid, expandedInstanceName(name, pid)};
    }
    RTM::Manager_var slave = pid < 0 ? RTM::Manager::_nil() : waitForSlave(pid, address);
    release();
    if (pid < 0)
        fail("create_component: cannot start a slave manager", error);
    else if (CORBA::is_nil(slave))
        fail("create_component: slave manager at " + address + " did not start", error);
    return slave._retn();
}

void Manager::startForkServer()
{
    if (!m_forkServer.start())
        std::cerr << programName() << ": no fork server, slaves are started one exec each" << std::endl;
}

pid_t Manager::startSlaveProcess(const std::string &address, const std::string &name, const std::string &master)
{
    // What makes it a slave comes first, where ps shows it.
    std::vector<std::string> args = {"rtmanager", "-o", "manager.instance_name=" + name, "-o",
                                     "corba.endpoints=" + address, "-o", "manager.is_master=NO", "-o",
                                     "corba.master_manager=" + master};
    const Properties config = configuration();
    for (const auto &[key, value] : config.entries()) {
        // A slave makes only what it is asked for: the master's precreated components stay single.
        if (key == "manager.is_master" || key == "corba.endpoints" || key == "corba.master_manager"
            || key == "manager.instance_name" || key == "manager.spawned_by"
            || key == "manager.components.precreate")
            continue;
        args.insert(args.end(), {"-o", key + '=' + value});
    }
    // The slave watches its parent to go down with its master: the fork server, or this process.
    if (m_forkServer.running()) {
        std::vector<std::string> served = args;
        served.insert(served.end(), {"-o", "manager.spawned_by=" + std::to_string(m_forkServer.pid())});
        const pid_t pid = m_forkServer.launch(served);
        if (pid > 0)
            return pid;
    }
    args.insert(args.end(), {"-o", "manager.spawned_by=" + std::to_string(getpid())});
    std::vector<char *> argv;
    for (std::string &arg : args)
        argv.push_back(arg.data());
    argv.push_back(nullptr);
    const std::string program = ownExecutable();
    const pid_t pid = fork();
    if (pid == 0) {
        execv(program.c_str(), argv.data());
        _exit(127);
    }
    return pid;
}

RTM::Manager_ptr Manager::waitForSlave(pid_t pid, const std::string &address)
{
    const auto deadline = std::chrono::steady_clock::now()
                          + std::chrono::milliseconds(long(configNumber("manager.slave_start_timeout", 10000)));
    std::unique_lock lock(m_mutex);
    while (!m_stopping) {
        RTM::Manager_var found;
        for (const auto &slave : m_slaves) {
            if (slave->address == address || slave->pid == pid)
                found = RTM::Manager::_duplicate(slave->reference);
        }
        if (!CORBA::is_nil(found))
            return found._retn();
        // Woken by add_slave_manager; the short bound notices a child that died on start.
        if (m_slavesChanged.wait_for(lock, std::chrono::milliseconds(100)) == std::cv_status::timeout) {
            if (kill(pid, 0) != 0 || waitpid(pid, nullptr, WNOHANG) == pid
                || std::chrono::steady_clock::now() > deadline)
                return RTM::Manager::_nil();
        }
    }
    return RTM::Manager::_nil();
}

bool Manager::addSlave(RTM::Manager_ptr manager)
{
    if (CORBA::is_nil(manager))
        return false;
    auto slave = std::make_unique<Slave>();
    slave->reference = RTM::Manager::_duplicate(manager);
    // Calls to a slave (create, aggregation, watchdog) never wait longer than this.
    omniORB::setClientCallTimeout(slave->reference,
                                  CORBA::ULong(configNumber("manager.slave_call_timeout", 2000)));
    // A slave this master started is known by the address it was given; others are asked.
    {
        std::lock_guard lock(m_mutex);
        for (const std::string &address : tcpAddresses(manager)) {
            const auto starting = m_startingSlaves.find(address);
            if (starting == m_startingSlaves.end() || starting->second.pid == 0)
                continue;
            slave->name = starting->second.name;
            slave->address = address;
            slave->pid = starting->second.pid;
            break;
        }
    }
    try {
        if (slave->pid == 0) {
            RTM::ManagerProfile_var profile = slave->reference->get_profile();
            slave->name = nvString(profile->properties, "instance_name");
            slave->address = nvString(profile->properties, "address");
            slave->pid = pid_t(std::stol("0" + nvString(profile->properties, "pid")));
        }
    } catch (const CORBA::Exception &) {
        return false;
    }
    std::lock_guard lock(m_mutex);
    for (const auto &existing : m_slaves) {
        if (existing->address == slave->address)
            return true;
    }
    m_slaves.push_back(std::move(slave));
    m_slavesChanged.notify_all();
    return true;
}

bool Manager::removeSlave(RTM::Manager_ptr manager)
{
    if (CORBA::is_nil(manager))
        return false;
    dropSlave(manager);
    return true;
}

void Manager::dropSlave(RTM::Manager_ptr manager)
{
    std::lock_guard lock(m_mutex);
    m_slaves.erase(std::remove_if(m_slaves.begin(), m_slaves.end(),
                                  [manager](const auto &slave) {
                                      try {
                                          return sameObject(slave->reference, manager);
                                      } catch (const CORBA::Exception &) {
                                          return false;
                                      }
                                  }),
                   m_slaves.end());
    m_slavesChanged.notify_all();
}

RTM::ManagerList Manager::slaves()
{
    std::lock_guard lock(m_mutex);
    RTM::ManagerList list;
    list.length(CORBA::ULong(m_slaves.size()));
    for (CORBA::ULong i = 0; i < list.length(); ++i)
        list[i] = RTM::Manager::_duplicate(m_slaves[i]->reference);
    return list;
}

RTM::ManagerList Manager::masters()
{
    std::lock_guard lock(m_mutex);
    return m_masters;
}

bool Manager::addMaster(RTM::Manager_ptr manager)
{
    if (CORBA::is_nil(manager))
        return false;
    std::lock_guard lock(m_mutex);
    const CORBA::ULong n = m_masters.length();
    m_masters.length(n + 1);
    m_masters[n] = RTM::Manager::_duplicate(manager);
    return true;
}

bool Manager::removeMaster(RTM::Manager_ptr manager)
{
    std::lock_guard lock(m_mutex);
    RTM::ManagerList kept;
    for (CORBA::ULong i = 0; i < m_masters.length(); ++i) {
        if (sameObject(m_masters[i], manager))
            continue;
        const CORBA::ULong n = kept.length();
        kept.length(n + 1);
        kept[n] = m_masters[i];
    }
    const bool removed = kept.length() != m_masters.length();
    m_masters = kept;
    return removed;
}

void Manager::joinMaster()
{
    const std::string master = m_config.value("corba.master_manager");
    if (master.empty())
        return;
    RTM::Manager_var manager;
    try {
        CORBA::Object_var object = corbalocObject(master, "manager");
        // Unchecked: the first real call tells whether it is there, without an extra round trip.
        manager = RTM::Manager::_unchecked_narrow(object);
    } catch (const CORBA::Exception &e) {
        std::cerr << programName() << ": cannot join master " << master << ": " << describeException(e) << std::endl;
        return;
    }
    // A slave we were started for is awaited by its master, which may be busy (many slaves joining
    // at once, slow callbacks under load): keep asking while it lives, within the start timeout.
    const pid_t parent = pid_t(configNumber("manager.spawned_by", 0));
    const auto deadline = std::chrono::steady_clock::now()
                          + std::chrono::milliseconds(long(configNumber("manager.slave_start_timeout", 10000)));
    // The master counts this slave as started once it has registered it, before its answer is
    // back here, and may call create_component at once: list it as the master before asking.
    addMaster(manager);
    std::string problem;
    bool absent = false;
    for (;;) {
        bool retry = false;
        problem = requestJoin(manager, &retry, &absent);
        if (problem.empty())
            return;
        const bool parentAlive = parent > 0 && getppid() == parent;
        if (!(retry || parentAlive) || std::chrono::steady_clock::now() > deadline)
            break;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    removeMaster(manager);
    // A master that went down meanwhile took this slave's parent with it: it goes too, quietly.
    if (parent > 0 && getppid() != parent)
        return;
    // A program started on its own where no master runs is a standalone one, as in OpenRTM-aist.
    if (parent <= 0 && absent)
        return;
    std::cerr << programName() << ": cannot join master " << master << ": " << problem << std::endl;
}

std::string Manager::requestJoin(RTM::Manager_ptr master, bool *retry, bool *absent)
{
    try {
        if (master->add_slave_manager(m_self) == RTC::RTC_OK)
            return {};
        // The master could not call this manager back in time; it may manage on a second try.
        *retry = true;
        return "the master could not reach this manager back";
    } catch (const CORBA::Exception &e) {
        // Nobody listening means no master; a timeout or a broken connection means a busy one.
        *retry = CORBA::TIMEOUT::_downcast(&e) || CORBA::COMM_FAILURE::_downcast(&e);
        *absent = CORBA::TRANSIENT::_downcast(&e) != nullptr;
        return describeException(e);
    }
}

void Manager::leaveMaster()
{
    RTM::ManagerList all = masters();
    for (CORBA::ULong i = 0; i < all.length(); ++i) {
        try {
            all[i]->remove_slave_manager(m_self);
        } catch (const CORBA::Exception &) {
            // The master is gone already.
        }
    }
}

void Manager::watchSlaves()
{
    const auto period = std::chrono::milliseconds(std::max(10L, long(configNumber("manager.slave_check_interval", 500))));
    std::unique_lock lock(m_mutex);
    auto next = std::chrono::steady_clock::now() + period;
    while (!m_stopping) {
        // The condition also announces each slave that joins: checking only once a period keeps
        // slaves started side by side from being asked once per join, each ask a further
        // connection and server thread in a slave that is still starting.
        if (m_slavesChanged.wait_until(lock, next) != std::cv_status::timeout)
            continue;
        next = std::chrono::steady_clock::now() + period;
        std::vector<RTM::Manager_var> refs;
        for (const auto &slave : m_slaves)
            refs.push_back(RTM::Manager::_duplicate(slave->reference));
        lock.unlock();
        while (waitpid(-1, nullptr, WNOHANG) > 0) {
        }
        for (RTM::Manager_var &ref : refs) {
            bool dead = false;
            try {
                dead = ref->_non_existent();
            } catch (const CORBA::Exception &) {
                dead = true;
            }
            if (dead)
                dropSlave(ref);
        }
        lock.lock();
    }
}

} // namespace Runtime

namespace Runtime {

void Manager::watchAsSlave(pid_t parent)
{
    // A slave we spawned goes down with its master (reparenting shows the master is gone), so no
    // process outlives a killed master. (PR_SET_PDEATHSIG would follow the forking ORB thread.)
    // With manager.shutdown_auto, a manager left without components goes after
    // manager.auto_shutdown_duration seconds, as OpenRTM's slaves do.
    const bool autoShutdown = m_config.isYes("manager.shutdown_auto");
    const double idleLimit = configNumber("manager.auto_shutdown_duration", 10.0);
    auto idleSince = std::chrono::steady_clock::now();
    std::unique_lock lock(m_mutex);
    while (!m_stopping) {
        m_slavesChanged.wait_for(lock, std::chrono::milliseconds(100));
        if (m_stopping)
            return;
        if (!m_components.empty())
            idleSince = std::chrono::steady_clock::now();
        const bool orphaned = parent > 0 && getppid() != parent;
        const bool idle = autoShutdown
                          && std::chrono::steady_clock::now() - idleSince > std::chrono::duration<double>(idleLimit);
        if (orphaned || idle) {
            lock.unlock();
            shutdown();
            return;
        }
    }
}

} // namespace Runtime
