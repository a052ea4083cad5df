// SPDX-License-Identifier: MIT
#include "idlsearchpath.h"

#include <QDir>
#include <QFileInfo>

using namespace Profile;

namespace Codegen {

QStringList idlSearchDirs(const RtcProfile &profile, const QString &profileDir,
                          const QStringList &leading, const QStringList &trailing)
{
    QStringList dirs = leading;
    const bool saved = !profileDir.isEmpty();
    const QDir base(saved ? profileDir : QDir::currentPath());
    if (saved)
        dirs << base.path() << base.filePath(QStringLiteral("idl"));
    auto addFileDir = [&](const std::optional<QString> &idlFile) {
        if (!idlFile || idlFile->isEmpty())
            return;
        // Relative names only mean something next to a saved profile.
        if (!saved && QFileInfo(*idlFile).isRelative())
            return;
        const QFileInfo info(base, *idlFile);
        if (info.exists())
            dirs << info.absolutePath();
    };
    for (const RtcDataPort &port : profile.dataPorts)
        addFileDir(port.idlFile);
    for (const RtcServicePort &port : profile.servicePorts) {
        for (const RtcServiceInterface &iface : port.interfaces)
            addFileDir(iface.idlFile);
    }
    dirs << trailing;
    QStringList unique;
    for (const QString &dir : std::as_const(dirs)) {
        const QString clean = QDir::cleanPath(QDir(dir).absolutePath());
        if (QFileInfo(clean).isDir() && !unique.contains(clean))
            unique << clean;
    }
    return unique;
}

} // namespace Codegen
