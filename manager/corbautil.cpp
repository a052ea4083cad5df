// SPDX-License-Identifier: MIT
#include "corbautil.h"

#include "tlstransport.h"

#include <omniORB4/IIOP.h>
#include <omniORB4/omniIOR.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <random>

namespace Runtime {

void nvSet(SDOPackage::NVList &list, const std::string &name, const std::string &value)
{
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (name == static_cast<const char *>(list[i].name)) {
            list[i].value <<= value.c_str();
            return;
        }
    }
    const CORBA::ULong n = list.length();
    list.length(n + 1);
    list[n].name = name.c_str();
    list[n].value <<= value.c_str();
}

std::string nvString(const SDOPackage::NVList &list, const std::string &name)
{
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (name != static_cast<const char *>(list[i].name))
            continue;
        const char *text = nullptr;
        if (list[i].value >>= text)
            return text;
        return {};
    }
    return {};
}

bool nvContains(const SDOPackage::NVList &list, const std::string &name)
{
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        if (name == static_cast<const char *>(list[i].name))
            return true;
    }
    return false;
}

Properties nvToProperties(const SDOPackage::NVList &list)
{
    Properties result;
    for (CORBA::ULong i = 0; i < list.length(); ++i) {
        const char *text = nullptr;
        if (list[i].value >>= text)
            result.set(static_cast<const char *>(list[i].name), text);
    }
    return result;
}

SDOPackage::NVList propertiesToNv(const Properties &properties)
{
    SDOPackage::NVList list;
    list.length(CORBA::ULong(properties.entries().size()));
    CORBA::ULong i = 0;
    for (const auto &[key, value] : properties.entries()) {
        list[i].name = key.c_str();
        list[i].value <<= value.c_str();
        ++i;
    }
    return list;
}

std::string newUuid()
{
    static thread_local std::mt19937_64 engine{std::random_device{}()};
    const uint64_t high = engine();
    const uint64_t low = engine();
    char text[40];
    std::snprintf(text, sizeof text, "%08x-%04x-4%03x-%04x-%012llx", unsigned(high >> 32),
                  unsigned((high >> 16) & 0xffff), unsigned(high & 0x0fff),
                  unsigned(((low >> 48) & 0x3fff) | 0x8000), (unsigned long long)(low & 0xffffffffffffULL));
    return text;
}

void releaseServant(PortableServer::POA_ptr poa, PortableServer::ServantBase *servant)
{
    if (!servant)
        return;
    try {
        PortableServer::ObjectId_var id = poa->servant_to_id(servant);
        poa->deactivate_object(id);
    } catch (const CORBA::Exception &) {
        // Never activated or already gone: only our own reference remains to drop.
    }
    servant->_remove_ref();
}

const char *programName()
{
    // glibc keeps the short name of argv[0]; a component program's messages then carry its own name.
    return program_invocation_short_name;
}

CORBA::ORB_var theOrb()
{
    // ORB_init hands back the ORB already initialised in this process.
    int argc = 0;
    return CORBA::ORB_init(argc, nullptr);
}

std::string objectUrl(const std::string &address, const std::string &key, bool tls)
{
    static const std::pair<const char *, const char *> prefixes[] = {
        {"giop:tcp:", "corbaloc:iiop:1.2@"}, {"giop:ssl:", "corbaloc:ssliop:"}, {"giop::", "corbaloc:iiop:1.2@"},
        {"iiop://", "corbaloc:iiop:1.2@"},   {"ssliop://", "corbaloc:ssliop:"}, {"inet:", "corbaloc:iiop:1.2@"},
        {"iiop:", "corbaloc:iiop:1.2@"},     {"ssliop:", "corbaloc:ssliop:"},
    };
    if (address.rfind("corbaloc:", 0) == 0)
        return address + '/' + key;
    if (address.rfind("corbaname:", 0) == 0)
        return address + '#' + key;
    for (const auto &[prefix, url] : prefixes) {
        const size_t length = std::strlen(prefix);
        if (address.compare(0, length, prefix) == 0)
            return url + address.substr(length) + '/' + key;
    }
    // A TLS process reaches its peers over TLS only.
    return (tls ? "corbaloc:ssliop:" : "corbaloc:iiop:1.2@") + address + '/' + key;
}

CORBA::Object_ptr corbalocObject(const std::string &address, const std::string &key)
{
    return theOrb()->string_to_object(objectUrl(address, key, Tls::Transport::installed()).c_str());
}

// A port nobody listens on right now, for a slave we start ourselves.
int freeLoopbackPort()
{
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    int port = 0;
    if (fd >= 0 && bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0
        && getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length) == 0)
        port = ntohs(address.sin_port);
    if (fd >= 0)
        close(fd);
    return port;
}

std::string localSocketFolder(bool removeStale)
{
    // A socket's path must fit sockaddr_un (108 bytes) with omniORB's 20-character file name.
    // $XDG_RUNTIME_DIR is the user's place for sockets (a tmpfs on desktops, where making and
    // removing them costs no disk inode), then $TMPDIR, then /tmp.
    std::string base = "/tmp";
    for (const char *variable : {"XDG_RUNTIME_DIR", "TMPDIR"}) {
        const char *value = std::getenv(variable);
        if (value && *value == '/' && std::strlen(value) <= 64) {
            base = value;
            break;
        }
    }
    std::string folder = base + "/rtstudio-orb-" + std::to_string(getuid());
    struct stat info {};
    if (mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST)
        return {};
    // Someone else's folder, or not a folder: do not put sockets there.
    if (lstat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != getuid())
        return {};
    if (!removeStale)
        return folder;
    // omniORB names a socket "<pid>-<time>" and removes it when its ORB is destroyed; a process that
    // was killed leaves its socket behind.
    if (DIR *dir = opendir(folder.c_str())) {
        while (const dirent *entry = readdir(dir)) {
            char *end = nullptr;
            const long pid = std::strtol(entry->d_name, &end, 10);
            if (end == entry->d_name || *end != '-' || pid <= 0)
                continue;
            const std::string path = folder + '/' + entry->d_name;
            if (kill(pid_t(pid), 0) != 0 && errno == ESRCH && lstat(path.c_str(), &info) == 0
                && S_ISSOCK(info.st_mode))
                unlink(path.c_str());
        }
        closedir(dir);
    }
    return folder;
}

namespace {

/// The object key and TCP addresses of a reference's IIOP profiles.
struct IiopAddresses
{
    std::string key;
    std::vector<std::pair<std::string, int>> addresses;
};

IiopAddresses iiopAddresses(CORBA::Object_ptr object)
{
    IiopAddresses result;
    omniIOR_var ior = object->_PR_getobj()->_getIOR();
    const IOP::TaggedProfileList &profiles = ior->iopProfiles();
    for (CORBA::ULong i = 0; i < profiles.length(); ++i) {
        if (profiles[i].tag != IOP::TAG_INTERNET_IOP)
            continue;
        IIOP::ProfileBody body;
        IIOP::unmarshalProfile(profiles[i], body);
        result.key.assign(reinterpret_cast<const char *>(body.object_key.get_buffer()), body.object_key.length());
        result.addresses.emplace_back(static_cast<const char *>(body.address.host), int(body.address.port));
    }
    return result;
}

} // namespace

bool sameObject(CORBA::Object_ptr a, CORBA::Object_ptr b)
{
    if (CORBA::is_nil(a) || CORBA::is_nil(b))
        return CORBA::is_nil(a) && CORBA::is_nil(b);
    if (a->_is_equivalent(b))
        return true;
    try {
        const IiopAddresses first = iiopAddresses(a);
        const IiopAddresses second = iiopAddresses(b);
        if (first.key.empty() || first.key != second.key)
            return false;
        return std::any_of(first.addresses.begin(), first.addresses.end(), [&second](const auto &address) {
            return std::find(second.addresses.begin(), second.addresses.end(), address) != second.addresses.end();
        });
    } catch (const CORBA::Exception &) {
        return false;
    }
}

std::vector<std::string> tcpAddresses(CORBA::Object_ptr object)
{
    std::vector<std::string> result;
    if (CORBA::is_nil(object))
        return result;
    try {
        for (const auto &[host, port] : iiopAddresses(object).addresses)
            result.push_back(host + ':' + std::to_string(port));
    } catch (const CORBA::Exception &) {
    }
    return result;
}

std::string describeException(const CORBA::Exception &e)
{
    std::string text = e._name();
    if (const auto *system = CORBA::SystemException::_downcast(&e)) {
        const char *minor = system->NP_minorString();
        if (minor)
            text += std::string(" (") + minor + ')';
    }
    return text;
}

} // namespace Runtime
