// SPDX-License-Identifier: MIT
#pragma once

#include <QList>
#include <QMap>
#include <QPair>
#include <QString>
#include <QStringList>

#include <optional>

namespace Planner {

/// Key/value pairs as a manager's profile or configuration gives them (the NVList of the wire).
using FactProperties = QList<QPair<QString, QString>>;

/**
 * What one node (an RTC manager) offers a plan. Every fact is optional: a fact the node did not
 * give (OpenRTM-aist's managers give only some) is unknown, and an unknown fact never meets a
 * requirement.
 */
struct NodeFacts
{
    QString name; ///< how plans name the node: the manager address given to the planner
    std::optional<QString> os; ///< `os.name` (uname: Linux)
    std::optional<QString> osRelease; ///< `os.release` (kernel release)
    std::optional<QString> distribution; ///< `os.distribution` (os-release: `debian 13`)
    std::optional<QString> architecture; ///< `os.arch` (uname: x86_64, aarch64)
    std::optional<QString> hostname; ///< `os.hostname`
    std::optional<int> cpuCount; ///< `rtstudio.cpu_count`
    std::optional<qint64> memoryKiB; ///< `rtstudio.memory_kib`
    std::optional<double> loadAverage; ///< `rtstudio.load_average` (one minute)
    std::optional<QString> sdkAbi; ///< `rtstudio.sdk_abi` (SONAME of the component SDK)
    std::optional<QStringList> languages; ///< `supported_languages` (OpenRTM-aist's key)
    std::optional<QStringList>
        loadableTypes; ///< component types it can create (get_loadable_modules)
    std::optional<QStringList> packages; ///< installed component packages (`rtstudio.packages`)
    QMap<QString, QString> userFacts; ///< the manager's `node.*` configuration, without `node.`

    /// The devices the node's operator listed (`node.devices: lidar0,camera0`).
    QStringList devices() const;
    /// CPUs free for new components: the CPU count less the load average; nothing when unknown.
    std::optional<double> freeCpus() const;

    /**
     * The facts in a manager's @p profile (get_profile) and @p configuration (get_configuration;
     * OpenRTM-aist keeps `os.*` there), with the implementation ids of @p loadableModules
     * (get_loadable_modules, nothing when the call failed).
     */
    static NodeFacts fromManager(const QString &name, const FactProperties &profile,
                                 const FactProperties &configuration,
                                 const std::optional<QList<FactProperties>> &loadableModules);
    /// The facts of `key: value` pairs in the keys a manager publishes (also the facts file's).
    static NodeFacts fromProperties(const QString &name, const FactProperties &properties);
};

/// A comma- or space-separated list (`lidar0, camera0`) as its items.
QStringList splitFactList(const QString &text);

/// Architecture names as uname, Debian and RTC profiles spell them, folded onto one (amd64 →
/// x86_64).
QString canonicalArchitecture(const QString &name);

} // namespace Planner
