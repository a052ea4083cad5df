// SPDX-License-Identifier: MIT
#pragma once

#include "nodefacts.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

namespace Planner {

/**
 * Node facts from a file, for planning without live managers (tests, offline planning): JSON or
 * YAML, a list of nodes (or a map with the list under `nodes`), one map per node with its `name`
 * and the keys a manager publishes (`os.arch: aarch64`, `node.devices: lidar0`, …); nested maps
 * join their keys with dots (`node: {role: onboard}`), lists are lists (`rtstudio.loadable_types`).
 * Nothing, with "FILE:LINE: reason" in @p error, when the file cannot be read or an entry is bad.
 */
std::optional<QList<NodeFacts>> readNodeFactsFile(const QString &path, QString *error);
/// The same for the text @p data, named @p fileName in messages.
std::optional<QList<NodeFacts>> readNodeFactsData(const QByteArray &data, const QString &fileName,
                                                  QString *error);

} // namespace Planner
