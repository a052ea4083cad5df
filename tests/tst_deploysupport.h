// SPDX-License-Identifier: MIT
#pragma once

// Shared by the live deployment tests (tst_deploy, tst_deployslaves): test systems and report
// queries.

#include "componentmapper.h"
#include "livesystem.h"
#include "profileio.h"
#include "restorer.h"
#include "rtsprofile.h"

#include <QString>
#include <QStringList>
#include <QtGlobal>

namespace DeployTest {

/// The system in `file`; a test file that does not load ends the test run.
inline Profile::RtsProfile loadSystem(const QString &file)
{
    Profile::Diagnostics diagnostics;
    const auto loaded = Profile::loadProfileFile(file, &diagnostics);
    if (!loaded || !loaded->rts)
        qFatal("cannot read %s", qPrintable(file));
    return *loaded->rts;
}

/// `name` in the deployment tests' data folder.
inline QString dataFile(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/deploy/")) + name;
}

/// Subjects of the steps `action` that were done, in report order.
inline QStringList doneSubjects(const Deploy::DeployReport &report, const QString &action)
{
    QStringList subjects;
    for (const Deploy::DeployStep &step : report.steps) {
        if (step.action == action && step.status == Deploy::StepStatus::Done)
            subjects.append(step.subject);
    }
    return subjects;
}

/// The step `action` on `subject`, null when the report has none.
inline const Deploy::DeployStep *findStep(const Deploy::DeployReport &report, const QString &action,
                                          const QString &subject)
{
    for (const Deploy::DeployStep &step : report.steps) {
        if (step.action == action && step.subject == subject)
            return &step;
    }
    return nullptr;
}

/**
 * Starts omniNames and a master rtmanager (RTMANAGER_PATH) on free loopback ports in `live`, its
 * components named by `namingFormat` and itself by `managerFormat`, contexts at 200 Hz. The
 * manager's port goes to `managerPort`; false with `error` set when either did not start.
 */
inline bool startManager(LiveTest::LiveSystem &live, const QString &namingFormat,
                         const QString &managerFormat, quint16 *managerPort, QString *error)
{
    if (!live.startNameServer(error))
        return false;
    *managerPort = LiveTest::freePort();
    const QStringList options {
        "corba.nameservers=" + live.namingServer(), "naming.formats=" + namingFormat,
        "manager.naming_formats=" + managerFormat, "exec_cxt.periodic.rate=200"};
    return live.startManager(RTMANAGER_PATH, *managerPort, options, error)
        != nullptr;
}

/// Instance names of the live components below `namingServer`, sorted.
inline QStringList liveInstances(const QString &namingServer)
{
    QStringList names
        = Deploy::ComponentMapper::liveComponents({"/" + namingServer}, nullptr).keys();
    names.sort();
    return names;
}

/// The message of the step `action` on `subject`, or says that the report has no such step.
inline QString stepMessage(const Deploy::DeployReport &report, const QString &action,
                           const QString &subject)
{
    const Deploy::DeployStep *step = findStep(report, action, subject);
    return step ? step->message : QStringLiteral("(no step %1 %2)").arg(action, subject);
}

} // namespace DeployTest
