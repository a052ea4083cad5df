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

void IdlTypeLibrary::setDirectories(const QStringList &directories)
{
    m_directories = directories;
    reload();
}

void IdlTypeLibrary::reload()
{
    // A fresh parser forgets the files read before, so edited files are read again.
    IdlParser parser;
    parser.setSearchDirectories(m_directories);
    // Projects often carry copies of standard IDL (BasicDataType.idl in idl/); like an include search,
    // the first folder that has a file name wins, so the copy does not redefine every type.
    QSet<QString> namesRead;
    for (const QString &directory : std::as_const(m_directories)) {
        const QDir dir(directory);
        const QStringList names = dir.entryList({QStringLiteral("*.idl")}, QDir::Files, QDir::Name);
        for (const QString &name : names) {
            if (namesRead.contains(name))
                continue;
            parser.parseFile(dir.filePath(name));
            for (const QString &file : parser.model().files)
                namesRead.insert(QFileInfo(file).fileName());
        }
    }
    m_model = parser.model();
    m_diagnostics = parser.diagnostics();
}

QString IdlTypeLibrary::fileOf(const QString &scopedName) const
{
    const auto declaration = m_model.find(scopedName);
    return declaration ? declaration->source.file : QString();
}

} // namespace Codegen
