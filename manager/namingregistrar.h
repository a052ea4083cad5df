// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <omniORB4/CORBA.h>
#include <omniORB4/Naming.hh>

#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace Runtime {

/**
 * Binds objects in CORBA naming services under OpenRTM-style paths (`host.host_cxt/Name0.rtc`),
 * creating the contexts on the way, and unbinds them again. Servers are `host[:port]` (2809 by
 * default). A server that cannot be reached is reported, never waited on beyond the ORB's timeouts.
 * The contexts a name goes into are remembered, so the next component of the same host costs one
 * call (rebind); a context that is gone (a restarted name server) is looked up again.
 */
class NamingRegistrar
{
public:
    explicit NamingRegistrar(const std::vector<std::string> &servers);

    /// Binds @p object at @p path on every server; errors name the server and the problem.
    bool bind(const std::string &path, CORBA::Object_ptr object, std::vector<std::string> *errors);
    /// Unbinds @p path everywhere (missing names are fine).
    void unbind(const std::string &path);

    /**
     * Expands an OpenRTM format (naming formats, `logger.file_name`): %h host, %n instance name,
     * %N its number (the instance name less the implementation id), %i implementation id,
     * %t and %m type name, %c category, %v version, %V vendor, %p pid, %M manager name, %% a
     * percent sign, `${NAME}` the environment variable NAME. Several formats are comma-separated;
     * spaces around each are dropped.
     */
    static std::vector<std::string> expand(const std::string &formats, const Properties &values);

private:
    /// The context on @p server that holds the last element of @p name, made when missing.
    CosNaming::NamingContext_ptr context(const std::string &server, const CosNaming::Name &name,
                                         bool fresh);

    std::vector<std::string> m_servers;
    std::mutex m_mutex;
    std::map<std::string, CosNaming::NamingContext_var> m_contexts; ///< by server and context path
};

/// This machine's host name.
std::string hostName();

} // namespace Runtime
