// SPDX-License-Identifier: MIT
#include <rtm/CORBA_RTCUtil.h>
#include <rtm/CorbaNaming.h>
#include <rtm/Manager.h>

#include <ManagerSkel.h>

#include <coil/stringutil.h>

#include <cstdlib>
#include <functional>

namespace CORBA_RTCUtil {

namespace {

// ExecutionContextHandle_t values from here on index the contexts a component participates in.
const RTC::UniqueId participatingOffset = 1000;

RTC::ExecutionContext_ptr contextAt(const RTC::ExecutionContextList &contexts, CORBA::ULong index)
{
    if (index >= contexts.length() || CORBA::is_nil(contexts[index]))
        return RTC::ExecutionContext::_nil();
    return RTC::ExecutionContext::_duplicate(contexts[index]);
}

// The names of the ports whose port.port_type is `portType` (all ports when it is empty).
coil::vstring portNames(const RTC::RTObject_ptr rtc, const std::string &portType)
{
    coil::vstring names;
    if (CORBA::is_nil(rtc))
        return names;
    RTC::PortServiceList_var ports = rtc->get_ports();
    for (CORBA::ULong i = 0; i < ports->length(); ++i) {
        RTC::PortProfile_var profile = ports[i]->get_port_profile();
        if (!portType.empty()
            && NVUtil::toString(profile->properties, "port.port_type") != portType)
            continue;
        names.emplace_back(static_cast<const char *>(profile->name));
    }
    return names;
}

coil::vstring connectorFields(const RTC::PortService_ptr port, bool ids)
{
    coil::vstring values;
    if (CORBA::is_nil(port))
        return values;
    RTC::ConnectorProfileList_var profiles = port->get_connector_profiles();
    for (CORBA::ULong i = 0; i < profiles->length(); ++i) {
        const RTC::ConnectorProfile &profile = profiles[i];
        values.emplace_back(static_cast<const char *>(ids ? profile.connector_id : profile.name));
    }
    return values;
}

RTC::ReturnCode_t onContext(const RTC::RTObject_ptr rtc, RTC::UniqueId ecId,
                            const std::function<RTC::ReturnCode_t(RTC::ExecutionContext_ptr)> &call)
{
    if (CORBA::is_nil(rtc))
        return RTC::BAD_PARAMETER;
    RTC::ExecutionContext_var ec = get_actual_ec(rtc, ecId);
    if (CORBA::is_nil(ec))
        return RTC::BAD_PARAMETER;
    return call(ec);
}

bool isInState(const RTC::RTObject_ptr rtc, RTC::UniqueId ecId, RTC::LifeCycleState wanted)
{
    RTC::LifeCycleState state = RTC::CREATED_STATE;
    return get_state(state, rtc, ecId) && state == wanted;
}

// --- get_port_by_url: finding components by RTC URI.

void appendObject(RTC::RTCList &found, CORBA::Object_ptr object)
{
    RTC::RTObject_var rtc = RTC::RTObject::_narrow(object);
    if (!CORBA::is_nil(rtc))
        CORBA_SeqUtil::push_back(found, RTC::RTObject::_duplicate(rtc));
}

// Depth-first through the contexts below `context` for objects bound as `id`.rtc.
void searchContexts(CosNaming::NamingContext_ptr context, const std::string &id,
                    RTC::RTCList &found, int depth)
{
    const int maxDepth = 16; // name trees are shallow; this only guards against cycles
    if (depth > maxDepth)
        return;
    CosNaming::BindingList_var bindings;
    CosNaming::BindingIterator_var more;
    context->list(1000, bindings.out(), more.out());
    if (!CORBA::is_nil(more))
        more->destroy();
    for (CORBA::ULong i = 0; i < bindings->length(); ++i) {
        const CosNaming::Binding &binding = bindings[i];
        if (binding.binding_name.length() != 1)
            continue;
        const CosNaming::NameComponent &last = binding.binding_name[0];
        try {
            CORBA::Object_var object = context->resolve(binding.binding_name);
            if (binding.binding_type == CosNaming::ncontext) {
                CosNaming::NamingContext_var child = CosNaming::NamingContext::_narrow(object);
                if (!CORBA::is_nil(child))
                    searchContexts(child, id, found, depth + 1);
            } else if (id == static_cast<const char *>(last.id)
                       && std::string("rtc") == static_cast<const char *>(last.kind)) {
                appendObject(found, object);
            }
        } catch (const CORBA::Exception &) {
            // A stale or unreachable entry hides nothing else.
        }
    }
}

RTC::RTCList componentsByName(const CORBA_RTCUtil::RTCURIObject &uri)
{
    RTC::RTCList found;
    RTC::Manager &manager = RTC::Manager::instance();
    coil::vstring servers;
    if (uri.getAddress() == "*")
        servers = coil::split(manager.getConfig().getProperty("corba.nameservers"), ",", true);
    else
        servers.push_back(uri.getAddress());
    const std::string path = uri.getRTCName();
    const std::string::size_type slash = path.find('/');
    const bool anyContext = slash != std::string::npos && path.substr(0, slash) == "*";
    for (const std::string &server : servers) {
        try {
            RTC::CorbaNaming naming(manager.getORB(), server.c_str());
            if (anyContext) {
                CosNaming::NamingContext_var root = naming.getRootContext();
                searchContexts(root, path.substr(slash + 1), found, 0);
            } else {
                CORBA::Object_var object = naming.resolveStr((path + ".rtc").c_str());
                appendObject(found, object);
            }
        } catch (...) {
            // An unreachable name server or a missing name: try the next server.
        }
    }
    return found;
}

RTC::RTCList componentsOfManager(const CORBA_RTCUtil::RTCURIObject &uri)
{
    RTC::RTCList found;
    RTC::Manager &manager = RTC::Manager::instance();
    const std::string path = uri.getRTCName();
    if (uri.getAddress() == "*") {
        // This process's components, by "category/instance" or "instance".
        const std::string::size_type slash = path.rfind('/');
        const std::string category = slash == std::string::npos ? "" : path.substr(0, slash);
        const std::string instance = slash == std::string::npos ? path : path.substr(slash + 1);
        for (RTC::RTObject_impl *component : manager.getComponents()) {
            if (instance != component->getInstanceName())
                continue;
            if (!category.empty() && category != "*" && category != component->getCategory())
                continue;
            CORBA_SeqUtil::push_back(found, component->getObjRef());
        }
        return found;
    }
    try {
        CORBA::Object_var object
            = manager.getORB()->string_to_object((uri.getAddress() + "/manager").c_str());
        RTM::Manager_var remote = RTM::Manager::_narrow(object);
        if (CORBA::is_nil(remote))
            return found;
        RTC::RTCList_var own = remote->get_components_by_name(path.c_str());
        CORBA_SeqUtil::push_back_list(found, own.in());
        RTM::ManagerList_var slaves = remote->get_slave_managers();
        for (CORBA::ULong i = 0; i < slaves->length(); ++i) {
            try {
                RTC::RTCList_var theirs = slaves[i]->get_components_by_name(path.c_str());
                CORBA_SeqUtil::push_back_list(found, theirs.in());
            } catch (const CORBA::SystemException &) {
                // A slave that is gone has no components to offer.
            }
        }
    } catch (const CORBA::Exception &) { }
    return found;
}

} // namespace

coil::Properties get_component_profile(const RTC::RTObject_ptr rtc)
{
    coil::Properties prop;
    if (CORBA::is_nil(rtc))
        return prop;
    RTC::ComponentProfile_var profile = rtc->get_component_profile();
    NVUtil::copyToProperties(prop, profile->properties);
    return prop;
}

bool is_existing(const RTC::RTObject_ptr rtc)
{
    if (CORBA::is_nil(rtc))
        return false;
    try {
        return !rtc->_non_existent();
    } catch (...) {
        return false;
    }
}

bool is_alive_in_default_ec(const RTC::RTObject_ptr rtc)
{
    RTC::ExecutionContext_var ec = get_actual_ec(rtc);
    return !CORBA::is_nil(ec) && rtc->is_alive(ec);
}

RTC::ExecutionContext_ptr get_actual_ec(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    if (CORBA::is_nil(rtc) || ec_id < 0)
        return RTC::ExecutionContext::_nil();
    if (ec_id < participatingOffset) {
        RTC::ExecutionContextList_var owned = rtc->get_owned_contexts();
        return contextAt(owned.in(), CORBA::ULong(ec_id));
    }
    RTC::ExecutionContextList_var participating = rtc->get_participating_contexts();
    return contextAt(participating.in(), CORBA::ULong(ec_id - participatingOffset));
}

RTC::UniqueId get_ec_id(const RTC::RTObject_ptr rtc, const RTC::ExecutionContext_ptr ec)
{
    if (CORBA::is_nil(rtc) || CORBA::is_nil(ec))
        return -1;
    RTC::ExecutionContextList_var owned = rtc->get_owned_contexts();
    for (CORBA::ULong i = 0; i < owned->length(); ++i) {
        if (!CORBA::is_nil(owned[i]) && owned[i]->_is_equivalent(ec))
            return RTC::UniqueId(i);
    }
    RTC::ExecutionContextList_var participating = rtc->get_participating_contexts();
    for (CORBA::ULong i = 0; i < participating->length(); ++i) {
        if (!CORBA::is_nil(participating[i]) && participating[i]->_is_equivalent(ec))
            return participatingOffset + RTC::UniqueId(i);
    }
    return -1;
}

RTC::ReturnCode_t activate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    return onContext(rtc, ec_id,
                     [rtc](RTC::ExecutionContext_ptr ec) { return ec->activate_component(rtc); });
}

RTC::ReturnCode_t deactivate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    return onContext(rtc, ec_id,
                     [rtc](RTC::ExecutionContext_ptr ec) { return ec->deactivate_component(rtc); });
}

RTC::ReturnCode_t reset(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    return onContext(rtc, ec_id,
                     [rtc](RTC::ExecutionContext_ptr ec) { return ec->reset_component(rtc); });
}

bool get_state(RTC::LifeCycleState &state, const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    if (CORBA::is_nil(rtc))
        return false;
    RTC::ExecutionContext_var ec = get_actual_ec(rtc, ec_id);
    if (CORBA::is_nil(ec))
        return false;
    state = ec->get_component_state(rtc);
    return true;
}

bool is_in_inactive(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    return isInState(rtc, ec_id, RTC::INACTIVE_STATE);
}

bool is_in_active(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    return isInState(rtc, ec_id, RTC::ACTIVE_STATE);
}

bool is_in_error(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    return isInState(rtc, ec_id, RTC::ERROR_STATE);
}

CORBA::Double get_default_rate(const RTC::RTObject_ptr rtc)
{
    return get_current_rate(rtc, 0);
}

RTC::ReturnCode_t set_default_rate(const RTC::RTObject_ptr rtc, CORBA::Double rate)
{
    return set_current_rate(rtc, 0, rate);
}

CORBA::Double get_current_rate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id)
{
    RTC::ExecutionContext_var ec = get_actual_ec(rtc, ec_id);
    // OpenRTM-aist answers a missing context with the return code as the rate.
    if (CORBA::is_nil(ec))
        return CORBA::Double(RTC::BAD_PARAMETER);
    return ec->get_rate();
}

RTC::ReturnCode_t set_current_rate(const RTC::RTObject_ptr rtc, const RTC::UniqueId ec_id,
                                   const CORBA::Double rate)
{
    return onContext(rtc, ec_id,
                     [rate](RTC::ExecutionContext_ptr ec) { return ec->set_rate(rate); });
}

RTC::ReturnCode_t add_rtc_to_default_ec(const RTC::RTObject_ptr localcomp,
                                        const RTC::RTObject_ptr othercomp)
{
    if (CORBA::is_nil(othercomp))
        return RTC::BAD_PARAMETER;
    return onContext(localcomp, 0, [othercomp](RTC::ExecutionContext_ptr ec) {
        return ec->add_component(othercomp);
    });
}

RTC::ReturnCode_t remove_rtc_to_default_ec(const RTC::RTObject_ptr localcomp,
                                           const RTC::RTObject_ptr othercomp)
{
    if (CORBA::is_nil(othercomp))
        return RTC::BAD_PARAMETER;
    return onContext(localcomp, 0, [othercomp](RTC::ExecutionContext_ptr ec) {
        return ec->remove_component(othercomp);
    });
}

RTC::RTCList get_participants_rtc(const RTC::RTObject_ptr rtc)
{
    RTC::ExecutionContext_var ec = get_actual_ec(rtc);
    if (CORBA::is_nil(ec))
        return RTC::RTCList();
    try {
        RTC::ExecutionContextService_var service = RTC::ExecutionContextService::_narrow(ec);
        if (CORBA::is_nil(service))
            return RTC::RTCList();
        RTC::ExecutionContextProfile_var profile = service->get_profile();
        return profile->participants;
    } catch (const CORBA::Exception &) {
        return RTC::RTCList();
    }
}

coil::vstring get_port_names(const RTC::RTObject_ptr rtc)
{
    return portNames(rtc, {});
}

coil::vstring get_inport_names(const RTC::RTObject_ptr rtc)
{
    return portNames(rtc, "DataInPort");
}

coil::vstring get_outport_names(const RTC::RTObject_ptr rtc)
{
    return portNames(rtc, "DataOutPort");
}

coil::vstring get_svcport_names(const RTC::RTObject_ptr rtc)
{
    return portNames(rtc, "CorbaPort");
}

coil::vstring get_connector_names(const RTC::PortService_ptr port)
{
    return connectorFields(port, false);
}

coil::vstring get_connector_names(const RTC::RTObject_ptr rtc, const std::string &port_name)
{
    RTC::PortService_var port = get_port_by_name(rtc, port_name);
    return connectorFields(port, false);
}

coil::vstring get_connector_ids(const RTC::PortService_ptr port)
{
    return connectorFields(port, true);
}

coil::vstring get_connector_ids(const RTC::RTObject_ptr rtc, const std::string &port_name)
{
    RTC::PortService_var port = get_port_by_name(rtc, port_name);
    return connectorFields(port, true);
}

RTC::ConnectorProfile *create_connector(const std::string &name, const coil::Properties &prop_arg,
                                        const RTC::PortService_ptr port0,
                                        const RTC::PortService_ptr port1)
{
    RTC::ConnectorProfile_var profile = new RTC::ConnectorProfile;
    profile->name = CORBA::string_dup(name.c_str());
    profile->connector_id = CORBA::string_dup("");
    const bool both = !CORBA::is_nil(port1);
    profile->ports.length(both ? 2 : 1);
    profile->ports[0] = RTC::PortService::_duplicate(port0);
    if (both)
        profile->ports[1] = RTC::PortService::_duplicate(port1);
    coil::Properties prop(prop_arg);
    if (prop.getProperty("dataport.dataflow_type").empty())
        prop.setProperty("dataport.dataflow_type", "push");
    if (prop.getProperty("dataport.interface_type").empty())
        prop.setProperty("dataport.interface_type", "corba_cdr");
    NVUtil::copyFromProperties(profile->properties, prop);
    return profile._retn();
}

bool already_connected(const RTC::PortService_ptr localport, const RTC::PortService_ptr otherport)
{
    if (CORBA::is_nil(localport) || CORBA::is_nil(otherport)
        || localport->_is_equivalent(otherport))
        return false;
    RTC::ConnectorProfileList_var profiles = localport->get_connector_profiles();
    for (CORBA::ULong i = 0; i < profiles->length(); ++i) {
        const RTC::PortServiceList &ports = profiles[i].ports;
        for (CORBA::ULong j = 0; j < ports.length(); ++j) {
            if (!CORBA::is_nil(ports[j]) && ports[j]->_is_equivalent(otherport))
                return true;
        }
    }
    return false;
}

RTC::ReturnCode_t connect(const std::string &name, const coil::Properties &prop,
                          const RTC::PortService_ptr port0, const RTC::PortService_ptr port1)
{
    if (CORBA::is_nil(port0))
        return RTC::BAD_PARAMETER;
    if (!CORBA::is_nil(port1) && port0->_is_equivalent(port1))
        return RTC::BAD_PARAMETER;
    RTC::ConnectorProfile_var profile = create_connector(name, prop, port0, port1);
    return port0->connect(profile.inout());
}

RTC::ReturnCode_t disconnect(const RTC::ConnectorProfile connector_prof)
{
    if (connector_prof.ports.length() == 0)
        return RTC::BAD_PARAMETER;
    return disconnect_connector_id(
        connector_prof.ports[0],
        std::string(static_cast<const char *>(connector_prof.connector_id)));
}

RTC::ReturnCode_t disconnect_connector_name(const RTC::PortService_ptr port_ref,
                                            const std::string &conn_name)
{
    if (CORBA::is_nil(port_ref))
        return RTC::BAD_PARAMETER;
    RTC::ConnectorProfileList_var profiles = port_ref->get_connector_profiles();
    for (CORBA::ULong i = 0; i < profiles->length(); ++i) {
        if (conn_name == static_cast<const char *>(profiles[i].name))
            return disconnect(profiles[i]);
    }
    return RTC::BAD_PARAMETER;
}

RTC::ReturnCode_t disconnect_connector_name(const std::string &port_name,
                                            const std::string &conn_name)
{
    RTC::PortService_var port = get_port_by_url(port_name);
    return disconnect_connector_name(port.in(), conn_name);
}

RTC::ReturnCode_t disconnect_connector_id(const RTC::PortService_ptr port_ref,
                                          const std::string &conn_id)
{
    if (CORBA::is_nil(port_ref))
        return RTC::BAD_PARAMETER;
    return port_ref->disconnect(conn_id.c_str());
}

RTC::ReturnCode_t disconnect_connector_id(const std::string &port_name, const std::string &conn_id)
{
    RTC::PortService_var port = get_port_by_url(port_name);
    return disconnect_connector_id(port.in(), conn_id);
}

RTC::ReturnCode_t disconnect_all(const RTC::PortService_ptr port_ref)
{
    if (CORBA::is_nil(port_ref))
        return RTC::BAD_PARAMETER;
    return port_ref->disconnect_all();
}

RTC::ReturnCode_t disconnect_all(const std::string &port_name)
{
    RTC::PortService_var port = get_port_by_url(port_name);
    return disconnect_all(port.in());
}

RTC::PortService_ptr get_port_by_url(const std::string &port_name)
{
    // "<component URI>.<port>": the port's own name is "<instance>.<port>", the last path element.
    const std::string::size_type dot = port_name.rfind('.');
    const std::string::size_type slash = port_name.rfind('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return RTC::PortService::_nil();
    const std::string component = port_name.substr(0, dot);
    const std::string portOwnName
        = slash == std::string::npos ? port_name : port_name.substr(slash + 1);
    RTC::RTCList found;
    const RTCURIObject byName(component, true, false);
    const RTCURIObject byManager(component, false, true);
    if (byName.isRTCNameURI())
        found = componentsByName(byName);
    else if (byManager.isRTCLocURI())
        found = componentsOfManager(byManager);
    for (CORBA::ULong i = 0; i < found.length(); ++i) {
        try {
            RTC::PortService_ptr port = get_port_by_name(found[i], portOwnName);
            if (!CORBA::is_nil(port))
                return port;
        } catch (const CORBA::SystemException &) {
            // A component that is gone has no ports; look at the next one.
        }
    }
    return RTC::PortService::_nil();
}

RTC::ReturnCode_t disconnect_name(const RTC::PortService_ptr localport,
                                  const std::string &othername)
{
    if (CORBA::is_nil(localport))
        return RTC::BAD_PARAMETER;
    RTC::PortProfile_var own = localport->get_port_profile();
    if (othername == static_cast<const char *>(own->name))
        return RTC::BAD_PARAMETER;
    RTC::ConnectorProfileList_var profiles = localport->get_connector_profiles();
    for (CORBA::ULong i = 0; i < profiles->length(); ++i) {
        const RTC::PortServiceList &ports = profiles[i].ports;
        for (CORBA::ULong j = 0; j < ports.length(); ++j) {
            if (CORBA::is_nil(ports[j]))
                continue;
            RTC::PortProfile_var other = ports[j]->get_port_profile();
            if (othername == static_cast<const char *>(other->name))
                return disconnect(profiles[i]);
        }
    }
    return RTC::BAD_PARAMETER;
}

RTC::ReturnCode_t connect_multi(const std::string &name, const coil::Properties &prop,
                                const RTC::PortService_ptr port, RTC::PortServiceList &target_ports)
{
    RTC::ReturnCode_t result = RTC::RTC_OK;
    for (CORBA::ULong i = 0; i < target_ports.length(); ++i) {
        const RTC::PortService_ptr target = target_ports[i];
        if (target->_is_equivalent(port) || already_connected(port, target))
            continue;
        if (connect(name, prop, port, target) != RTC::RTC_OK)
            result = RTC::RTC_ERROR;
    }
    return result;
}

bool find_port::operator()(const RTC::PortService_ptr p)
{
    RTC::PortProfile_var profile = p->get_port_profile();
    return m_name == static_cast<const char *>(profile->name);
}

RTC::PortService_ptr get_port_by_name(const RTC::RTObject_ptr rtc, const std::string &name)
{
    if (CORBA::is_nil(rtc))
        return RTC::PortService::_nil();
    RTC::PortServiceList_var ports = rtc->get_ports();
    find_port isNamed(name);
    const CORBA::Long index = CORBA_SeqUtil::find(ports.in(), isNamed);
    if (index < 0)
        return RTC::PortService::_nil();
    return RTC::PortService::_duplicate(ports[CORBA::ULong(index)]);
}

RTC::ReturnCode_t connect_by_name(const std::string &name, const coil::Properties &prop,
                                  const RTC::RTObject_ptr rtc0, const std::string &portName0,
                                  const RTC::RTObject_ptr rtc1, const std::string &portName1)
{
    if (CORBA::is_nil(rtc0) || CORBA::is_nil(rtc1))
        return RTC::BAD_PARAMETER;
    RTC::PortService_var port0 = get_port_by_name(rtc0, portName0);
    if (CORBA::is_nil(port0))
        return RTC::BAD_PARAMETER;
    RTC::PortService_var port1 = get_port_by_name(rtc1, portName1);
    if (CORBA::is_nil(port1))
        return RTC::BAD_PARAMETER;
    return connect(name, prop, port0, port1);
}

coil::Properties get_configuration(const RTC::RTObject_ptr rtc, const std::string &conf_name)
{
    SDOPackage::Configuration_var conf = rtc->get_configuration();
    SDOPackage::ConfigurationSet_var set = conf->get_configuration_set(conf_name.c_str());
    return NVUtil::toProperties(set->configuration_data);
}

std::string get_parameter_by_key(const RTC::RTObject_ptr rtc, const std::string &confset_name,
                                 const std::string &value_name)
{
    return get_configuration(rtc, confset_name).getProperty(value_name);
}

std::string get_active_configuration_name(const RTC::RTObject_ptr rtc)
{
    SDOPackage::Configuration_var conf = rtc->get_configuration();
    SDOPackage::ConfigurationSet_var set = conf->get_active_configuration_set();
    return std::string(static_cast<const char *>(set->id));
}

coil::Properties get_active_configuration(const RTC::RTObject_ptr rtc)
{
    SDOPackage::Configuration_var conf = rtc->get_configuration();
    SDOPackage::ConfigurationSet_var set = conf->get_active_configuration_set();
    return NVUtil::toProperties(set->configuration_data);
}

bool set_configuration(const RTC::RTObject_ptr rtc, const std::string &confset_name,
                       const std::string &value_name, const std::string &value)
{
    SDOPackage::Configuration_var conf = rtc->get_configuration();
    SDOPackage::ConfigurationSet_var set = conf->get_configuration_set(confset_name.c_str());
    set_configuration_parameter(conf, set.inout(), value_name, value);
    conf->activate_configuration_set(confset_name.c_str());
    return true;
}

bool set_active_configuration(const RTC::RTObject_ptr rtc, const std::string &value_name,
                              const std::string &value)
{
    SDOPackage::Configuration_var conf = rtc->get_configuration();
    SDOPackage::ConfigurationSet_var set = conf->get_active_configuration_set();
    set_configuration_parameter(conf, set.inout(), value_name, value);
    conf->activate_configuration_set(set->id);
    return true;
}

bool set_configuration_parameter(SDOPackage::Configuration_ptr conf,
                                 SDOPackage::ConfigurationSet &confset,
                                 const std::string &value_name, const std::string &value)
{
    coil::Properties prop = NVUtil::toProperties(confset.configuration_data);
    prop.setProperty(value_name, value);
    NVUtil::copyFromProperties(confset.configuration_data, prop);
    conf->set_configuration_set_values(confset);
    return true;
}

} // namespace CORBA_RTCUtil
