// SPDX-License-Identifier: MIT
#include "nativerepository.h"

#include "rtctlrunner.h"

#include <QDir>
#include <QFile>
#include <QProcess>

namespace TestSupport {

namespace {

bool runTool(const QString &program, const QStringList &arguments, QString *output)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    const bool done = process.waitForFinished(60000);
    *output = QString::fromUtf8(process.readAll());
    return done && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
}

/// The package tree with the architecture filled in.
bool copyTree(const QString &tree, const QString &arch, QString *error)
{
    if (!runTool(QStringLiteral("cp"),
                 {QStringLiteral("-r"), RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/packages/debtree"),
                  tree},
                 error))
        return false;
    QFile control(tree + QStringLiteral("/DEBIAN/control"));
    if (!control.open(QIODevice::ReadOnly))
        return false;
    const QByteArray text = control.readAll().replace("@ARCH@", arch.toLatin1());
    control.close();
    return control.open(QIODevice::WriteOnly | QIODevice::Truncate)
        && control.write(text) == text.size();
}

} // namespace

QString makeNativeRepository(const QString &dir, QString *arch, QString *error)
{
    if (!runTool(QStringLiteral("dpkg"), {QStringLiteral("--print-architecture")}, error))
        return {};
    *arch = error->trimmed();
    const QDir folder(dir);
    const QString tree = folder.filePath(QStringLiteral("tree"));
    const QString deb = folder.filePath(QStringLiteral("native.deb"));
    const QString repo = folder.filePath(QStringLiteral("repo"));
    if (!copyTree(tree, *arch, error)
        || !runTool(QStringLiteral("dpkg-deb"),
                    {QStringLiteral("--root-owner-group"), QStringLiteral("--build"), tree, deb},
                    error))
        return {};
    for (const QStringList &arguments :
         {QStringList {QStringLiteral("repo"), QStringLiteral("init"), repo},
          QStringList {QStringLiteral("repo"), QStringLiteral("publish"), repo, deb}}) {
        const RtctlResult result = runRtctl(arguments);
        if (result.code != 0) {
            *error = result.err;
            return {};
        }
    }
    error->clear();
    return repo;
}

} // namespace TestSupport
