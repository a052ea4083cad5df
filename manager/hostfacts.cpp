// SPDX-License-Identifier: MIT
#include "hostfacts.h"

#include <sys/utsname.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace Runtime {

namespace {

/// The value of @p key in an os-release file's `KEY=value` lines, quotes removed.
std::string osReleaseValue(const std::string &text, const std::string &key)
{
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = text.find('\n', at);
        const std::string line
            = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
        if (line.compare(0, key.size() + 1, key + "=") == 0) {
            std::string value = line.substr(key.size() + 1);
            if (value.size() >= 2 && (value.front() == '"' || value.front() == '\''))
                value = value.substr(1, value.size() - 2);
            return value;
        }
        if (end == std::string::npos)
            break;
        at = end + 1;
    }
    return {};
}

std::string readFile(const char *path)
{
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string distribution()
{
    std::string text = readFile("/etc/os-release");
    if (text.empty())
        text = readFile("/usr/lib/os-release");
    const std::string id = osReleaseValue(text, "ID");
    const std::string version = osReleaseValue(text, "VERSION_ID");
    return version.empty() ? id : id + ' ' + version;
}

/// MemTotal of /proc/meminfo in KiB; empty when it cannot be read.
std::string memoryKiB()
{
    const std::string text = readFile("/proc/meminfo");
    const std::size_t at = text.find("MemTotal:");
    if (at == std::string::npos)
        return {};
    const long long kib = std::strtoll(text.c_str() + at + 9, nullptr, 10);
    return kib > 0 ? std::to_string(kib) : std::string();
}

void setIfKnown(Properties &p, const std::string &key, const std::string &value)
{
    if (!value.empty())
        p.set(key, value);
}

} // namespace

Properties osFacts()
{
    Properties p;
    utsname info {};
    if (uname(&info) == 0) {
        p.set("os.name", info.sysname);
        p.set("os.release", info.release);
        p.set("os.version", info.version);
        p.set("os.arch", info.machine);
        p.set("os.hostname", info.nodename);
    }
    return p;
}

Properties hostFacts()
{
    Properties p = osFacts();
    setIfKnown(p, "os.distribution", distribution());
    const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    if (cpus > 0)
        p.set("rtstudio.cpu_count", std::to_string(cpus));
    setIfKnown(p, "rtstudio.memory_kib", memoryKiB());
    double load[1] = {0};
    if (getloadavg(load, 1) == 1) {
        char text[32];
        std::snprintf(text, sizeof text, "%.2f", load[0]);
        p.set("rtstudio.load_average", text);
    }
#ifdef RTSTUDIO_SDK_ABI
    p.set("rtstudio.sdk_abi", RTSTUDIO_SDK_ABI);
#endif
    return p;
}

} // namespace Runtime
