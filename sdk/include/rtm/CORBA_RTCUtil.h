// SPDX-License-Identifier: MIT
// Operations on remote components through their object references: profiles, execution contexts and
// life-cycle states, rates, ports and connections, configuration sets; plus the parsing of CORBA and
// RTC URIs. Names and semantics are OpenRTM-aist's; every function acts on the remote objects.
#ifndef CORBA_RTCUTIL_H
#define CORBA_RTCUTIL_H

#include <rtm/CORBA_SeqUtil.h>
#include <rtm/NVUtil.h>
#include <rtm/RTC.h>
#include <rtm/RTObject.h>

#include <string>
#include <utility>

namespace CORBA_RTCUtil
{
/// The component profile's properties (instance_name, type_name, vendor, …); empty for nil.
coil::Properties get_component_profile(const RTC::RTObject_ptr rtc);
/// Whether the object still exists (false when unreachable).
bool is_existing(const RTC::RTObject_ptr rtc);
/// Whether the component is alive in its default (first owned) execution context.
bool is_alive_in_default_ec(const RTC::RTObject_ptr rtc);
/**
 * The execution context `ec_id` of the component: below 1000 the index into its owned contexts,
 * from 1000 on (1000 + index) into the contexts it participates in. Nil when there is none.
 */
RTC::ExecutionContext_ptr get_actual_ec(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
/// The inverse of get_actual_ec(): the id of `ec` for the component, or -1.
RTC::UniqueId get_ec_id(const RTC::RTObject_ptr rtc, const RTC::ExecutionContext_ptr ec);
/// activate/deactivate/reset_component on context `ec_id`; BAD_PARAMETER when there is none.
RTC::ReturnCode_t activate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
RTC::ReturnCode_t deactivate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
RTC::ReturnCode_t reset(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
/// The component's state in context `ec_id` into `state`; false when there is no such context.
bool get_state(RTC::LifeCycleState &state, const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
bool is_in_inactive(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
bool is_in_active(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
bool is_in_error(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id = 0);
/// The rate of the default context; RTC::BAD_PARAMETER (as a number) when there is none.
CORBA::Double get_default_rate(const RTC::RTObject_ptr rtc);
RTC::ReturnCode_t set_default_rate(const RTC::RTObject_ptr rtc, CORBA::Double rate);
/// The rate of context `ec_id`; RTC::BAD_PARAMETER (as a number) when there is none.
CORBA::Double get_current_rate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id);
RTC::ReturnCode_t set_current_rate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id,
                                   const CORBA::Double rate);
/// Makes `othercomp` a participant of `localcomp`'s default context.
RTC::ReturnCode_t add_rtc_to_default_ec(const RTC::RTObject_ptr localcomp,
                                        const RTC::RTObject_ptr othercomp);
/// Removes `othercomp` from `localcomp`'s default context.
RTC::ReturnCode_t remove_rtc_to_default_ec(const RTC::RTObject_ptr localcomp,
                                           const RTC::RTObject_ptr othercomp);
/// The participants of the default context (from its ExecutionContextService profile).
RTC::RTCList get_participants_rtc(const RTC::RTObject_ptr rtc);

/// The names of all ports ("Comp0.in"), of data in-ports, data out-ports and service ports.
coil::vstring get_port_names(const RTC::RTObject_ptr rtc);
coil::vstring get_inport_names(const RTC::RTObject_ptr rtc);
coil::vstring get_outport_names(const RTC::RTObject_ptr rtc);
coil::vstring get_svcport_names(const RTC::RTObject_ptr rtc);
/// The names of the port's connectors.
coil::vstring get_connector_names(const RTC::PortService_ptr port);
coil::vstring get_connector_names(const RTC::RTObject_ptr rtc, const std::string &port_name);
/// The ids of the port's connectors.
coil::vstring get_connector_ids(const RTC::PortService_ptr port);
coil::vstring get_connector_ids(const RTC::RTObject_ptr rtc, const std::string &port_name);

/**
 * A connector profile named `name` between `port0` and `port1` (only `port0` when `port1` is
 * nil), with `prop_arg` as properties; dataport.dataflow_type defaults to "push" and
 * dataport.interface_type to "corba_cdr". The caller owns the result.
 */
RTC::ConnectorProfile *create_connector(const std::string &name, const coil::Properties &prop_arg,
                                        const RTC::PortService_ptr port0,
                                        const RTC::PortService_ptr port1);
/// Whether one of `localport`'s connectors includes `otherport` (never for the port itself).
bool already_connected(const RTC::PortService_ptr localport, const RTC::PortService_ptr otherport);
/// Connects the two ports with create_connector()'s profile; BAD_PARAMETER for nil or equal ports.
RTC::ReturnCode_t connect(const std::string &name, const coil::Properties &prop,
                          const RTC::PortService_ptr port0, const RTC::PortService_ptr port1);
/// Disconnects the connector through its first port.
RTC::ReturnCode_t disconnect(const RTC::ConnectorProfile connector_prof);
/// Disconnects the port's connector called `conn_name`; BAD_PARAMETER when there is none.
RTC::ReturnCode_t disconnect_connector_name(const RTC::PortService_ptr port_ref,
                                            const std::string &conn_name);
/// The same for the port get_port_by_url() finds.
RTC::ReturnCode_t disconnect_connector_name(const std::string &port_name, const std::string &conn_name);
/// Disconnects the port's connector with id `conn_id`.
RTC::ReturnCode_t disconnect_connector_id(const RTC::PortService_ptr port_ref, const std::string &conn_id);
RTC::ReturnCode_t disconnect_connector_id(const std::string &port_name, const std::string &conn_id);
/// Disconnects all of the port's connectors.
RTC::ReturnCode_t disconnect_all(const RTC::PortService_ptr port_ref);
RTC::ReturnCode_t disconnect_all(const std::string &port_name);
/**
 * The port named by `port_name`: a component URI followed by "." and the port's own name, e.g.
 * "rtcname://localhost:2809/host.host_cxt/Comp0.in" (through a name service; "*" as the address
 * means the manager's corba.nameservers, "*" as the context searches all contexts) or
 * "rtcloc://localhost:2810/example/Comp0.in" (through the manager there; "*": this process).
 * Nil when it is not found.
 */
RTC::PortService_ptr get_port_by_url(const std::string &port_name);
/// Disconnects `localport`'s connectors to the port called `othername`.
RTC::ReturnCode_t disconnect_name(const RTC::PortService_ptr localport, const std::string &othername);
/// Connects `port` to each of `target_ports` it is not connected to yet; RTC_ERROR if one fails.
RTC::ReturnCode_t connect_multi(const std::string &name, const coil::Properties &prop,
                                const RTC::PortService_ptr port, RTC::PortServiceList &target_ports);

/// A predicate for port references: whether the port's name is `name`.
struct find_port
{
    const std::string m_name;
    find_port(std::string name)
        : m_name(std::move(name))
    {
    }
    bool operator()(const RTC::PortService_ptr p);
};

/// The component's port called `name` ("Comp0.in"), or nil.
RTC::PortService_ptr get_port_by_name(const RTC::RTObject_ptr rtc, const std::string &name);
/// connect() between the ports found by name on two components.
RTC::ReturnCode_t connect_by_name(const std::string &name, const coil::Properties &prop,
                                  const RTC::RTObject_ptr rtc0, const std::string &portName0,
                                  const RTC::RTObject_ptr rtc1, const std::string &portName1);

/// The configuration set `conf_name` as properties.
coil::Properties get_configuration(const RTC::RTObject_ptr rtc, const std::string &conf_name);
/// One parameter of a configuration set.
std::string get_parameter_by_key(const RTC::RTObject_ptr rtc, const std::string &confset_name,
                                 const std::string &value_name);
/// The id of the active configuration set.
std::string get_active_configuration_name(const RTC::RTObject_ptr rtc);
/// The active configuration set as properties.
coil::Properties get_active_configuration(const RTC::RTObject_ptr rtc);
/// Sets one parameter of set `confset_name` and activates that set.
bool set_configuration(const RTC::RTObject_ptr rtc, const std::string &confset_name,
                       const std::string &value_name, const std::string &value);
/// Sets one parameter of the active set and activates it again, so that the component applies it.
bool set_active_configuration(const RTC::RTObject_ptr rtc, const std::string &value_name,
                              const std::string &value);
/// Sets one parameter in `confset` and sends the set to `conf`.
bool set_configuration_parameter(SDOPackage::Configuration_ptr conf,
                                 SDOPackage::ConfigurationSet &confset,
                                 const std::string &value_name, const std::string &value);

/**
 * An endpoint or object address turned into a URL the ORB resolves: "giop:tcp:host:port",
 * "iiop://host:port", "inet:host:port", "iiop:host:port" and a bare "host:port" become
 * "corbaloc:iiop:host:port/<objkey>"; corbaloc URLs get "/<objkey>", corbaname URLs "#<objkey>".
 */
class CorbaURI
{
public:
    CorbaURI(std::string uri, const std::string &objkey = "");
    ~CorbaURI();
    /// The URL.
    std::string toString() const;
    /// "corbaloc" or "corbaname" (the URL's scheme).
    std::string getProtocol() const;
    /// The host of the first address, when there is one.
    std::string getHost() const;
    /// The port of the first address (2809 when the address gives none), 0 without an address.
    unsigned short getPort() const;
    /// Whether the input was a bare "host:port".
    bool isAddressOnly() const;

private:
    std::string m_protocol;
    std::string m_host;
    unsigned short m_port;
    std::string m_path;
    std::string m_fragment;
    std::string m_uri;
    bool m_addressonly;
};

/**
 * An RTC URI: "rtcname[.protocol]://host:port/context/Comp0" (a name-service path) or
 * "rtcloc[.protocol]://host:port/category/Comp0" (a manager's component). The address becomes
 * "corbaloc:<protocol>:host:port" ("*" stays "*"; http/https/ws/wss become "<protocol>://host:port"
 * with '#' before the name).
 */
class RTCURIObject
{
public:
    /// `isrtcname`/`isrtcloc` accept only that kind: any other leaves the object empty.
    RTCURIObject(const std::string &uri, bool isrtcname = false, bool isrtcloc = false);
    ~RTCURIObject();
    /// The path after the address ("context/Comp0").
    std::string getRTCName() const;
    /// The address as a URL prefix, or "*".
    std::string getAddress() const;
    bool isRTCNameURI() const;
    bool isRTCLocURI() const;

private:
    std::string m_rtcpath;
    std::string m_address;
    bool m_is_rtcname;
    bool m_is_rtcloc;
};
} // namespace CORBA_RTCUtil

#endif // CORBA_RTCUTIL_H
