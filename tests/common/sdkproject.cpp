// SPDX-License-Identifier: MIT
#include "sdkproject.h"

#include <QFile>
#include <QProcess>
#include <QStandardPaths>

namespace SdkTest {

bool runTool(const QString &program, const QStringList &arguments, const QString &cwd, int timeoutMs, QString *log)
{
    QProcess process;
    process.setWorkingDirectory(cwd);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    const bool finished = process.waitForFinished(timeoutMs);
    *log = QString::fromLocal8Bit(process.readAll());
    if (!finished) {
        process.kill();
        process.waitForFinished(5000);
        *log += QStringLiteral("\n(%1 timed out)").arg(program);
        return false;
    }
    return process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
}

bool buildProject(const QString &dir, const QString &sdkPrefix, QString *log)
{
    const QString cmake = QStandardPaths::findExecutable(QStringLiteral("cmake"));
    QStringList configure{"-S", dir, "-B", dir + "/build", "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                          "-DCMAKE_PREFIX_PATH=" + sdkPrefix};
    const QString ccache = QStandardPaths::findExecutable(QStringLiteral("ccache"));
    if (!ccache.isEmpty())
        configure << "-DCMAKE_CXX_COMPILER_LAUNCHER=" + ccache;
    return runTool(cmake, configure, dir, 120000, log)
           && runTool(cmake, {"--build", dir + "/build", "-j2"}, dir, 600000, log);
}

bool applyEdit(const QString &root, const UserEdit &edit, QString *error)
{
    QFile file(root + '/' + QString::fromUtf8(edit.file));
    if (!file.open(QIODevice::ReadOnly)) {
        *error = "cannot read " + file.fileName();
        return false;
    }
    QByteArray text = file.readAll();
    file.close();
    if (!text.contains(edit.before)) {
        *error = QStringLiteral("%1 has no '%2'").arg(QString::fromUtf8(edit.file), QString::fromUtf8(edit.before));
        return false;
    }
    text.replace(edit.before, edit.after);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) || file.write(text) != text.size()) {
        *error = "cannot write " + file.fileName();
        return false;
    }
    return true;
}

} // namespace SdkTest
