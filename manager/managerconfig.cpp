// SPDX-License-Identifier: MIT
#include "managerconfig.h"

#include "hostfacts.h"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

namespace Runtime {

Properties managerDefaults()
{
    Properties p;
    p.set("corba.nameservers", "localhost");
    p.set("corba.master_manager", "localhost:2810");
    p.set("naming.enable", "YES");
    p.set("naming.formats", "%h.host_cxt/%n.rtc");
    p.set("manager.naming_formats", "%h.host_cxt/%n.mgr");
    p.set("manager.is_master", "NO");
    p.set("manager.corba_servant", "YES");
    p.set("manager.name", "manager");
    p.set("manager.instance_name", "manager");
    p.set("manager.modules.load_path", ".");
    p.set("exec_cxt.periodic.type", "PeriodicExecutionContext");
    p.set("exec_cxt.periodic.rate", "1000");
    p.set("exec_cxt.transition_timeout", "0.5");
    // What OpenRTM-aist's managers say too: the languages hosted, and the host's os.* facts.
    p.set("manager.supported_languages", "C++");
    p.merge(osFacts());
    return p;
}

namespace {

bool isReadable(const std::string &path)
{
    std::ifstream in(path);
    return bool(in);
}

} // namespace

std::string findConfigFile()
{
    std::vector<std::string> candidates;
    if (const char *named = std::getenv("RTC_MANAGER_CONFIG"); named && *named)
        candidates.push_back(named);
    for (const char *path : {"./rtc.conf", "/etc/rtc.conf", "/etc/rtc/rtc.conf", "/usr/local/etc/rtc.conf",
                             "/usr/local/etc/rtc/rtc.conf"})
        candidates.push_back(path);
    for (const std::string &path : candidates) {
        if (isReadable(path))
            return path;
    }
    return {};
}

bool readConfigFile(const std::string &file, Properties *config)
{
    std::ifstream in(file);
    if (!in)
        return false;
    std::stringstream text;
    text << in.rdbuf();
    std::vector<std::string> errors;
    config->merge(Properties::parseConf(text.str(), &errors));
    for (const std::string &error : errors)
        std::cerr << file << ':' << error << std::endl;
    return true;
}

bool parseManagerArguments(int argc, char **argv, Properties *config, std::string *error)
{
    Properties overrides;
    std::string file;
    bool ignoreMissingFile = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "-f" && hasValue) {
            file = argv[++i];
        } else if (arg == "-i") {
            ignoreMissingFile = true;
        } else if (arg == "-o" && hasValue) {
            const std::string pair = argv[++i];
            const size_t separator = pair.find_first_of("=:");
            if (separator == std::string::npos || separator == 0) {
                *error = "-o expects key:value, got '" + pair + "'";
                return false;
            }
            overrides.set(trimmed(pair.substr(0, separator)), trimmed(pair.substr(separator + 1)));
        } else if (arg == "-p" && hasValue) {
            overrides.set("corba.endpoints", std::string(":") + argv[++i]);
        } else if (arg == "-d") {
            overrides.set("manager.is_master", "YES");
        } else if (arg == "-a") {
            overrides.set("manager.corba_servant", "NO");
        } else if (arg.compare(0, 4, "-ORB") == 0 && hasValue) {
            ++i;
        } else {
            *error = "unknown argument '" + arg + "'";
            return false;
        }
    }
    *config = managerDefaults();
    const bool explicitFile = !file.empty();
    if (!explicitFile)
        file = findConfigFile();
    if (!file.empty() && !readConfigFile(file, config) && explicitFile && !ignoreMissingFile) {
        *error = "cannot read configuration file '" + file + "'";
        return false;
    }
    config->merge(overrides);
    return true;
}

} // namespace Runtime
