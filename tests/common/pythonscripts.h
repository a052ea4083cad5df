// SPDX-License-Identifier: MIT
#pragma once

// Python programs of a live test: python3 with the build tree's packages, an rtc.conf registering
// them in one host context of the test's name server, started and waited for until registered.

#include "hostrtctl.h"
#include "pythonenvironment.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcessEnvironment>

#include <algorithm>

namespace LiveTest {

#if defined(RTSTUDIO_CONFORMANCE_DIR) && defined(RTSTUDIO_TEST_DATA_DIR)
/// OpenRTM-aist-Python's examples in the shared corpus (absent on a clone with nothing beside it).
inline QString pythonCorpusDir()
{
    return RTSTUDIO_CONFORMANCE_DIR + QStringLiteral("/openrtm-python-examples");
}

/// A Python program of the tests' own data.
inline QString pythonTestScript(const QString &name)
{
    return (RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/python/")) + name;
}
#endif

class PythonScripts
{
public:
    /**
     * Programs run by @p python with the packages at @p packages, registered under @p host of
     * @p live; @p sanitizerPreload (space-separated, may be empty) is preloaded into python3 when
     * the extension is instrumented. rtc.conf files are written into @p workDir.
     */
    PythonScripts(LiveSystem &live, const HostRtctl &rtctl, QString host, QString python, QString packages,
                  QString sanitizerPreload, QString workDir)
        : m_live(live)
        , m_rtctl(rtctl)
        , m_host(std::move(host))
        , m_python(std::move(python))
        , m_packages(std::move(packages))
        , m_preload(std::move(sanitizerPreload))
        , m_workDir(std::move(workDir))
    {
    }

    /// pythonEnvironment() with the packages at @p packages, by default those given above.
    QProcessEnvironment environment(const QString &packages = {}) const
    {
        return pythonEnvironment(packages.isEmpty() ? m_packages : packages, m_preload);
    }

    /// Writes `<name>.conf` registering components under the host context, @p extraLines after.
    QString writeConf(const QString &name, const QStringList &extraLines) const
    {
        const QString file = QDir(m_workDir).filePath(name + QStringLiteral(".conf"));
        QFile conf(file);
        if (!conf.open(QIODevice::WriteOnly | QIODevice::Text))
            return {};
        const QStringList lines{QStringLiteral("corba.nameservers: ") + m_live.namingServer(),
                                QStringLiteral("naming.formats: %1.host_cxt/%n.rtc").arg(m_host),
                                QStringLiteral("logger.enable: NO"), NoMasterLine};
        conf.write(((lines + extraLines).join('\n') + '\n').toUtf8());
        return file;
    }

    /**
     * Starts `python3 @p script -f <conf>` and waits up to @p timeoutMs until every one of
     * @p instances is in the name server.
     */
    QProcess *start(const QString &script, const QStringList &instances, int timeoutMs,
                    const QStringList &confLines = {}) const
    {
        QString error;
        const QString conf = writeConf(QFileInfo(script).baseName(), confLines);
        const auto registered = [this, &instances] {
            const QString listed = m_rtctl.run({QStringLiteral("ls")}).out;
            return std::all_of(instances.begin(), instances.end(),
                               [&listed](const QString &instance) { return listed.contains(instance); });
        };
        QProcess *process = m_live.startRegistered(m_python, {script, QStringLiteral("-f"), conf}, registered, &error,
                                                   timeoutMs, environment());
        if (!process)
            qWarning().noquote() << error;
        return process;
    }

private:
    LiveSystem &m_live;
    const HostRtctl &m_rtctl;
    QString m_host;
    QString m_python;
    QString m_packages;
    QString m_preload;
    QString m_workDir;
};

} // namespace LiveTest
