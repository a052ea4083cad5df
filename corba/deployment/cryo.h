// SPDX-License-Identifier: MIT
#pragma once

#include "deployreport.h"

#include <QString>
#include <QStringList>

namespace Profile {
struct RtsProfile;
}

namespace Deploy {

/// What rtcryo is told: the system's identity and where its components are.
struct CryoOptions
{
    QString name = QStringLiteral("RTSystem");
    QString version = QStringLiteral("1.0");
    QString vendor = QStringLiteral("Me");
    QString abstract;
    /// rtshell paths (servers, contexts, components) whose components form the system.
    QStringList paths;
};

/**
 * Saves the live system as an RTS profile (rtcryo): every component under `options.paths` once
 * (id, pathUri, instance name, all configuration sets including hidden ones, the active set, owned
 * execution contexts with id = handle, kind and rate, data and service ports, property `IOR`), and
 * every connector between two of them with all its properties minus IOR keys (a missing
 * `dataport.subscription_type` is simply left out). Failures of single components are recorded
 * in `report` and leave them out; unreachable paths too. Safe to call from a worker thread.
 */
Profile::RtsProfile cryoSystem(const CryoOptions &options, DeployReport *report = nullptr,
                               const DeployControl &control = {});

} // namespace Deploy
