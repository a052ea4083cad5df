// SPDX-License-Identifier: MIT
#include "namingregistrar.h"

#include "corbautil.h"

#include <omniORB4/Naming.hh>

#include <cstdlib>

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
    CORBA::Object_var object = corbalocObject(address, "NameService");
    // Unchecked: the first real call tells whether a name server answers, without an extra round trip.
    return CosNaming::NamingContext::_unchecked_narrow(object);
}

/// Makes the contexts of every element of @p name but the last where missing; returns the last one.
CosNaming::NamingContext_ptr makeContexts(CosNaming::NamingContext_ptr root, const CosNaming::Name &name)
{
    CosNaming::NamingContext_var context = CosNaming::NamingContext::_duplicate(root);
    for (CORBA::ULong i = 0; i + 1 < name.length(); ++i) {
        CosNaming::Name step;
        step.length(1);
        step[0] = name[i];
        try {
            context = context->bind_new_context(step);
        } catch (const CosNaming::NamingContext::AlreadyBound &) {
            // There already, or made by another registration just now.
            CORBA::Object_var next = context->resolve(step);
            context = CosNaming::NamingContext::_unchecked_narrow(next);
        }
    }
    return context._retn();
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
    if (toName(path).length() == 0)
        return false;
    bool ok = true;
    for (const std::string &server : m_servers)
        ok = bindOn(server, path, object, errors) && ok;
    return ok;
}

bool NamingRegistrar::bindOn(const std::string &server, const std::string &path, CORBA::Object_ptr object,
                             std::vector<std::string> *errors)
{
    const CosNaming::Name name = toName(path);
    if (name.length() == 0)
        return false;
    CosNaming::Name last;
    last.length(1);
    last[0] = name[name.length() - 1];
    try {
        CosNaming::NamingContext_var root = rootContext(server);
        try {
            // The whole path in one call: the server walks the contexts.
            root->rebind(name, object);
        } catch (const CosNaming::NamingContext::NotFound &) {
            CosNaming::NamingContext_var holder = makeContexts(root, name);
            holder->rebind(last, object);
        }
        return true;
    } catch (const CORBA::Exception &e) {
        if (errors)
            errors->push_back("name server " + server + ": cannot bind " + path + ": " + describeException(e));
        return false;
    }
}

NamingRegistrar::Lookup NamingRegistrar::lookUp(const std::string &server, const std::string &path)
{
    try {
        CosNaming::NamingContext_var root = rootContext(server);
        CORBA::Object_var bound = root->resolve(toName(path));
        return Lookup::Bound;
    } catch (const CosNaming::NamingContext::NotFound &) {
        return Lookup::Missing;
    } catch (const CORBA::UserException &) {
        return Lookup::Missing;
    } catch (const CORBA::Exception &) {
        return Lookup::Unreachable;
    }
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

namespace {

/// The value of a one-letter format code, or the code itself when it is not one.
std::string formatCode(char code, const Properties &values)
{
    switch (code) {
    case 'h': return values.value("host", hostName());
    case 'n': return values.value("instance_name");
    case 'N': {
        const std::string name = values.value("instance_name");
        const size_t prefix = values.value("implementation_id").size();
        return name.size() >= prefix ? name.substr(prefix) : std::string();
    }
    case 'i': return values.value("implementation_id");
    case 't':
    case 'm': return values.value("type_name");
    case 'c': return values.value("category");
    case 'v': return values.value("version");
    case 'V': return values.value("vendor");
    case 'p': return std::to_string(getpid());
    case 'M': return values.value("manager_name");
    case '%': return "%";
    default: return std::string("%") + code;
    }
}

std::string expandOne(const std::string &format, const Properties &values)
{
    std::string result;
    for (size_t i = 0; i < format.size(); ++i) {
        const size_t close = format.compare(i, 2, "${") == 0 ? format.find('}', i + 2) : std::string::npos;
        if (close != std::string::npos) {
            const char *value = std::getenv(format.substr(i + 2, close - i - 2).c_str());
            result += value ? value : "";
            i = close;
        } else if (format[i] == '%' && i + 1 < format.size()) {
            result += formatCode(format[++i], values);
        } else {
            result += format[i];
        }
    }
    return result;
}

} // namespace

std::vector<std::string> NamingRegistrar::expand(const std::string &formats, const Properties &values)
{
    std::vector<std::string> paths;
    for (const std::string &format : split(formats, ','))
        paths.push_back(expandOne(format, values));
    return paths;
}

} // namespace Runtime
