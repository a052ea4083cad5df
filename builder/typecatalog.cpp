// SPDX-License-Identifier: MIT
#include "typecatalog.h"

#include "idltypelibrary.h"
#include "installation.h"

#include <QDir>
#include <QSettings>

namespace Builder {

namespace {

const char *const SettingsKey = "builder/idlDirectories";

} // namespace

TypeCatalog::TypeCatalog(const QString &bundledDirectory, QObject *parent)
    : QObject(parent)
    , m_bundledDirectory(bundledDirectory.isEmpty() ? Codegen::Installation::bundledIdlDirectory()
                                                    : bundledDirectory)
    , m_library(std::make_unique<Codegen::IdlTypeLibrary>())
    , m_dataTypes(builtInDataTypes())
{ }

TypeCatalog::~TypeCatalog() = default;

QString TypeCatalog::fileOf(const QString &scopedName) const
{
    return m_library->fileOf(scopedName);
}

QStringList TypeCatalog::directories() const
{
    QStringList result;
    if (QDir(m_bundledDirectory).exists())
        result << m_bundledDirectory;
    for (const QString &directory : userDirectories()) {
        if (!result.contains(directory))
            result << directory;
    }
    return result;
}

QStringList TypeCatalog::userDirectories()
{
    return QSettings().value(QLatin1String(SettingsKey)).toStringList();
}

void TypeCatalog::setUserDirectories(const QStringList &directories)
{
    QSettings().setValue(QLatin1String(SettingsKey), directories);
}

QStringList TypeCatalog::builtInDataTypes()
{
    QStringList types;
    for (const char *name : {"Boolean", "Octet", "Char", "Short", "UShort", "Long", "ULong",
                             "Float", "Double", "String", "WString"}) {
        types << QStringLiteral("RTC::Timed%1").arg(QLatin1String(name))
              << QStringLiteral("RTC::Timed%1Seq").arg(QLatin1String(name));
    }
    types.sort();
    return types;
}

void TypeCatalog::reload()
{
    m_library->setDirectories(directories());
    m_dataTypes.clear();
    for (const Codegen::IdlDataType &type : m_library->dataTypes())
        m_dataTypes << type.scopedName;
    m_interfaceTypes.clear();
    for (const Codegen::IdlInterface &interface : m_library->interfaces())
        m_interfaceTypes << interface.scopedName;
    if (m_dataTypes.isEmpty())
        m_dataTypes = builtInDataTypes();
    emit typesChanged();
}

} // namespace Builder
