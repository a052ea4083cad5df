// SPDX-License-Identifier: MIT
#include "idltypelibrary.h"

#include "idlparser.h"

#include <QDir>

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
    for (const QString &directory : std::as_const(m_directories)) {
        const QDir dir(directory);
        const QStringList names = dir.entryList({QStringLiteral("*.idl")}, QDir::Files, QDir::Name);
        for (const QString &name : names)
            parser.parseFile(dir.filePath(name));
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
