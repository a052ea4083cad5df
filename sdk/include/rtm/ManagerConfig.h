// SPDX-License-Identifier: MIT
// A manager's configuration from the command line and rtc.conf.
#ifndef RTC_MANAGERCONFIG_H
#define RTC_MANAGERCONFIG_H

#include <coil/Properties.h>

#include <string>

namespace RTC
{
/**
 * Reads a manager's configuration as RTC::Manager::init() does: the defaults, the rtc.conf
 * found (`-f FILE`, else $RTC_MANAGER_CONFIG and the usual places) and the command line
 * (`-o key:value`, `-p PORT`, `-d`, …), later ones winning.
 */
class ManagerConfig
{
public:
    /// Where rtc.conf is looked for when no `-f` names it, in order (null-terminated).
    static const char *const config_file_path[];
    /// The environment variable naming the configuration file (RTC_MANAGER_CONFIG).
    static const char *config_file_env;

    ManagerConfig();
    ManagerConfig(int argc, char **argv);
    virtual ~ManagerConfig();

    /**
     * Reads the command line. One that cannot be used (an unknown option, a missing `-f` file)
     * throws std::invalid_argument with the reason, as OpenRTM-aist stops there.
     */
    void init(int argc, char **argv);
    /// Puts the whole configuration (defaults, file, command line, os.* facts) into @p prop.
    void configure(coil::Properties &prop);
    coil::Properties getConfig() const;

protected:
    void parseArgs(int argc, char **argv);
    bool findConfigFile();
    static void setSystemInformation(coil::Properties &prop);
    static bool fileExist(const std::string &filename);

    coil::Properties m_argprop;
    std::string m_configFile;
    bool m_isMaster{false};
};
} // namespace RTC

#endif // RTC_MANAGERCONFIG_H
