// SPDX-License-Identifier: MIT
#pragma once

#include "properties.h"

#include <omniORB4/CORBA.h>
#include <omniORB4/Naming.hh>

#include <string>
#include <vector>

namespace Runtime {

/**
 * Binds objects in CORBA naming services under OpenRTM-style paths (`host.host_cxt/Name0.rtc`),
 * creating the contexts on the way, and unbinds them again. Servers are `host[:port]` (2809 by
 * default). A server that cannot be reached is reported, never waited on beyond the ORB's timeouts.
 * A name costs one call (a rebind of the whole path) when its contexts exist, and makes the missing
 * ones otherwise.
 */
class NamingRegistrar
{
public:
    explicit NamingRegistrar(const std::vector<std::string> &servers);

    /// Binds @p object at @p path on every server; errors name the server and the problem.
    bool bind(const std::string &path, CORBA::Object_ptr object, std::vector<std::string> *errors);
    /// Binds @p object at @p path on @p server only.
    bool bindOn(const std::string &server, const std::string &path, CORBA::Object_ptr object,
                std::vector<std::string> *errors);

    enum class Lookup { Bound, Missing, Unreachable };
    /// Whether @p server has a name @p path (bound to any object: one another process bound there
    /// under the same name is not taken back).
    Lookup lookUp(const std::string &server, const std::string &path);
    const std::vector<std::string> &servers() const { return m_servers; }
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
    std::vector<std::string> m_servers;
};

/// This machine's host name.
std::string hostName();

} // namespace Runtime
