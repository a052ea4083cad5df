// SPDX-License-Identifier: MIT
// The name services a manager binds its components under, and the ways of reaching them.
#ifndef RTC_NAMINGMANAGER_H
#define RTC_NAMINGMANAGER_H

#include <rtm/RTC.h>

#include <coil/Task.h>
#include <mutex>
#include <rtm/RTObject.h>
#include <rtm/SystemLogger.h>
#include <rtm/ManagerServant.h>

#include <string>
#include <vector>

namespace Runtime
{
class NamingRegistrar;
}

namespace RTC
{
class Manager;

/// One way of publishing names (a CORBA naming service, the manager itself).
class NamingBase
{
public:
    NamingBase() = default;
    virtual ~NamingBase() = default;
    virtual void bindObject(const char *name, const PortBase *port) = 0;
    virtual void bindObject(const char *name, const RTObject_impl *rtobj) = 0;
    virtual void bindObject(const char *name, const RTM::ManagerServant *mgr) = 0;
    virtual void unbindObject(const char *name) = 0;
    virtual bool isAlive() = 0;
    /// The components bound under @p name (a naming path such as `host.host_cxt/Name0.rtc`).
    virtual RTC::RTCList string_to_component(std::string name) = 0;
};

/// A registered name service: its method (`corba`, `manager`), its address and the object.
class NamingService
{
public:
    NamingService(const char *meth, const char *name, NamingBase *naming)
        : method(meth)
        , nsname(name)
        , ns(naming)
    {
    }
    ~NamingService() { delete ns; }
    std::string method;
    std::string nsname;
    NamingBase *ns;
};

/**
 * Names in a CORBA naming service at `host[:port]` (2809 by default); contexts on the way are
 * made as needed.
 */
class NamingOnCorba : public virtual NamingBase
{
public:
    NamingOnCorba(CORBA::ORB_ptr orb, const char *names);
    ~NamingOnCorba() override;
    void bindObject(const char *name, const RTObject_impl *rtobj) override;
    void bindObject(const char *name, const PortBase *port) override;
    void bindObject(const char *name, const RTM::ManagerServant *mgr) override;
    void unbindObject(const char *name) override;
    bool isAlive() override;
    RTC::RTCList string_to_component(std::string name) override;

private:
    void bind(const char *name, CORBA::Object_ptr object);

    Logger rtclog;
    CORBA::ORB_var m_orb;
    std::string m_endpoint;
    ::Runtime::NamingRegistrar *m_registrar;
};

/**
 * Names through the manager itself: the manager answers for its components by their instance
 * names (get_components_by_name), so binding is implicit and unbinding has nothing to undo.
 */
class NamingOnManager : public virtual NamingBase
{
public:
    NamingOnManager(CORBA::ORB_ptr orb, Manager *mgr);
    ~NamingOnManager() override = default;
    void bindObject(const char *name, const RTObject_impl *rtobj) override;
    void bindObject(const char *name, const PortBase *port) override;
    void bindObject(const char *name, const RTM::ManagerServant *mgr) override;
    void unbindObject(const char *name) override;
    bool isAlive() override;
    RTC::RTCList string_to_component(std::string name) override;
    /// The manager at @p name (`host:port`); nil when none answers.
    RTM::Manager_ptr getManager(const std::string &name);

private:
    Logger rtclog;
    CORBA::ORB_ptr m_orb;
    Manager *m_mgr;
};

/**
 * The name services of a manager (`naming.type`, `corba.nameservers`): binds objects in all of
 * them, remembers what it bound so that update() can bind it again in a server that came back,
 * and unbinds it all on shutdown.
 */
class NamingManager
{
public:
    explicit NamingManager(Manager *manager);
    virtual ~NamingManager();

    /// Adds a name service: @p method `corba` (@p name_server `host[:port]`) or `manager`.
    void registerNameServer(const char *method, const char *name_server);
    void bindObject(const char *name, const PortBase *port);
    void bindObject(const char *name, const RTObject_impl *rtobj);
    void bindObject(const char *name, const RTM::ManagerServant *mgr);
    /// Binds everything bound so far again (a name server restarted meanwhile).
    void update();
    void unbindObject(const char *name);
    void unbindAll();
    /// The components bound through this manager, in order.
    std::vector<RTObject_impl *> getObjects();
    std::vector<NamingService *> &getNameServices() { return m_names; }
    /// The components @p name stands for in the registered name services.
    RTCList string_to_component(const std::string &name);

protected:
    NamingBase *createNamingObj(const char *method, const char *name_server);
    void bindCompsTo(NamingBase *ns);
    void registerCompName(const char *name, const RTObject_impl *rtobj);
    void registerPortName(const char *name, const PortBase *port);
    void registerMgrName(const char *name, const RTM::ManagerServant *mgr);
    void unregisterCompName(const char *name);
    void unregisterPortName(const char *name);
    void unregisterMgrName(const char *name);

    std::vector<NamingService *> m_names;
    std::mutex m_namesMutex;
    struct Comps
    {
        Comps(const char *n, const RTObject_impl *obj)
            : name(n)
            , rtobj(obj)
        {
        }
        std::string name;
        const RTObject_impl *rtobj;
    };
    struct Port
    {
        Port(const char *n, const PortBase *p)
            : name(n)
            , port(p)
        {
        }
        std::string name;
        const PortBase *port;
    };
    struct Mgr
    {
        Mgr(const char *n, const RTM::ManagerServant *obj)
            : name(n)
            , mgr(obj)
        {
        }
        std::string name;
        const RTM::ManagerServant *mgr;
    };
    std::vector<Comps *> m_compNames;
    std::mutex m_compNamesMutex;
    std::vector<Port *> m_portNames;
    std::mutex m_portNamesMutex;
    std::vector<Mgr *> m_mgrNames;
    std::mutex m_mgrNamesMutex;
    Manager *m_manager;
    Logger rtclog;
};
} // namespace RTC

#endif // RTC_NAMINGMANAGER_H
