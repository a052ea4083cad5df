// SPDX-License-Identifier: MIT
#include "namingregistrar.h"

#include "corbautil.h"

#include <omniORB4/Naming.hh>

#include <unistd.h>

namespace Runtime {

namespace {

CosNaming::Name toName(const std::string &path)
{
    const std::vector<std::string> parts = split(path, '/');
    CosNaming::Name name;
    name.length(CORBA::ULong(parts.size()));
    for (CORBA::ULong i = 0; i < name.length(); ++i) {
        const size_t dot = parts[i].rfind('.');
        name[i].id = (dot == std::string::npos ? parts[i] : parts[i].substr(0, dot)).c_str();
        name[i].kind = (dot == std::string::npos ? std::string() : parts[i].substr(dot + 1)).c_str();
    }
    return name;
}

CosNaming::NamingContext_ptr rootContext(const std::string &server)
{
    const std::string address = server.find(':') == std::string::npos ? server + ":2809" : server;
    CORBA::Object_var object = theOrb()->string_to_object(("corbaloc:iiop:" + address + "/NameService").c_str());
    return CosNaming::NamingContext::_narrow(object);
}

void bindPath(CosNaming::NamingContext_ptr root, const CosNaming::Name &name, CORBA::Object_ptr object)
{
    CosNaming::NamingContext_var context = CosNaming::NamingContext::_duplicate(root);
    for (CORBA::ULong i = 0; i + 1 < name.length(); ++i) {
        CosNaming::Name step;
        step.length(1);
        step[0] = name[i];
        try {
            CORBA::Object_var next = context->resolve(step);
            context = CosNaming::NamingContext::_narrow(next);
        } catch (const CosNaming::NamingContext::NotFound &) {
            context = context->bind_new_context(step);
        }
    }
    CosNaming::Name last;
    last.length(1);
    last[0] = name[name.length() - 1];
    context->rebind(last, object);
}

} // namespace

std::string hostName()
{
    char buffer[256] = {};
    if (gethostname(buffer, sizeof buffer - 1) != 0)
        return "localhost";
    return buffer;
}

NamingRegistrar::NamingRegistrar(const std::vector<std::string> &servers)
    : m_servers(servers)
{
}

bool NamingRegistrar::bind(const std::string &path, CORBA::Object_ptr object, std::vector<std::string> *errors)
{
    const CosNaming::Name name = toName(path);
    if (name.length() == 0)
        return false;
    bool ok = true;
    for (const std::string &server : m_servers) {
        try {
            CosNaming::NamingContext_var root = rootContext(server);
            if (CORBA::is_nil(root))
                throw CORBA::OBJECT_NOT_EXIST();
            bindPath(root, name, object);
        } catch (const CORBA::Exception &e) {
            ok = false;
            if (errors)
                errors->push_back("name server " + server + ": cannot bind " + path + ": " + describeException(e));
        }
    }
    return ok;
}

void NamingRegistrar::unbind(const std::string &path)
{
    const CosNaming::Name name = toName(path);
    for (const std::string &server : m_servers) {
        try {
            CosNaming::NamingContext_var root = rootContext(server);
            if (!CORBA::is_nil(root))
                root->unbind(name);
        } catch (const CORBA::Exception &) {
            // Already gone, or the server is down: nothing left to clean.
        }
    }
}

std::vector<std::string> NamingRegistrar::expand(const std::string &formats, const Properties &values)
{
    std::vector<std::string> paths;
    for (const std::string &format : split(formats, ',')) {
        std::string path;
        for (size_t i = 0; i < format.size(); ++i) {
            if (format[i] != '%' || i + 1 == format.size()) {
                path += format[i];
                continue;
            }
            const char code = format[++i];
            switch (code) {
            case 'h': path += values.value("host", hostName()); break;
            case 'n': path += values.value("instance_name"); break;
            case 'p': path += std::to_string(getpid()); break;
            case 'M': path += values.value("manager_name"); break;
            case 'c': path += values.value("category"); break;
            case 't': path += values.value("type_name"); break;
            case 'v': path += values.value("vendor"); break;
            case '%': path += '%'; break;
            default: path += '%'; path += code; break;
            }
        }
        paths.push_back(path);
    }
    return paths;
}

} // namespace Runtime
