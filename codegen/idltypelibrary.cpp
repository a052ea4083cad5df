// SPDX-License-Identifier: MIT
#include "idltypelibrary.h"

#include "idlparser.h"

#include <QDir>
#include <QFileInfo>
#include <QSet>

namespace Codegen {

IdlTypeLibrary::IdlTypeLibrary(const QStringList &directories)
{
    setDirectories(directories);
}

bool IdlTypeLibrary::setDirectories(const QStringList &directories, const Progress &progress)
{
    m_directories = directories;
    return reload(progress);
}

bool IdlTypeLibrary::reload(const Progress &progress)
{
    // Projects often carry copies of standard IDL (BasicDataType.idl in idl/); like an include search,
    // the first folder that has a file name wins, so the copy does not redefine every type.
    QStringList paths;
    QSet<QString> names;
    for (const QString &directory : std::as_const(m_directories)) {
        const QDir dir(directory);
        for (const QString &name : dir.entryList({QStringLiteral("*.idl")}, QDir::Files, QDir::Name)) {
            if (!names.contains(name)) {
                names.insert(name);
                paths << dir.filePath(name);
            }
        }
    }
    // A fresh parser forgets the files read before, so edited files are read again.
    IdlParser parser;
    parser.setSearchDirectories(m_directories);
    QSet<QString> namesRead;
    for (int i = 0; i < paths.size(); ++i) {
        if (progress && !progress(i, int(paths.size()), paths.at(i)))
            return false;
        const QString name = QFileInfo(paths.at(i)).fileName();
        if (namesRead.contains(name)) // read already, through an include
            continue;
        parser.parseFile(paths.at(i));
        for (const QString &file : parser.model().files)
            namesRead.insert(QFileInfo(file).fileName());
    }
    m_model = parser.model();
    m_diagnostics = parser.diagnostics();
    return true;
}

QString IdlTypeLibrary::fileOf(const QString &scopedName) const
{
    const auto declaration = m_model.find(scopedName);
    return declaration ? declaration->source.file : QString();
}

} // namespace Codegen
