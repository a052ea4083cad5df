// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QStringList>

#include <memory>

namespace Codegen {
class IdlTypeLibrary;
}

namespace Builder {

/**
 * The data types and service interfaces the editor offers, parsed from IDL folders: the bundled
 * OpenRTM IDL set plus the user's folders (kept in QSettings under `builder/idlDirectories`).
 * Until the first load, and when no IDL can be read, a small built-in list of OpenRTM data types
 * is offered so the choices are never empty.
 */
class TypeCatalog : public QObject
{
    Q_OBJECT

public:
    /// `bundledDirectory` empty: the IDL folder built into the application.
    explicit TypeCatalog(const QString &bundledDirectory = QString(), QObject *parent = nullptr);
    ~TypeCatalog() override;

    /// Data port types (scoped names such as `RTC::TimedLong`).
    QStringList dataTypes() const { return m_dataTypes; }
    /// Service interface types (scoped names such as `SimpleService::MyService`).
    QStringList interfaceTypes() const { return m_interfaceTypes; }
    /// The IDL file that declares a type; empty when unknown.
    QString fileOf(const QString &scopedName) const;

    /// The folders read: the bundled one first, then the user's.
    QStringList directories() const;
    QString bundledDirectory() const { return m_bundledDirectory; }
    /// The user's IDL folders from the settings.
    static QStringList userDirectories();
    static void setUserDirectories(const QStringList &directories);

    /// The small list used when no IDL is available.
    static QStringList builtInDataTypes();

public slots:
    /// Parses the IDL folders again and announces typesChanged().
    void reload();

signals:
    void typesChanged();

private:
    QString m_bundledDirectory;
    std::unique_ptr<Codegen::IdlTypeLibrary> m_library;
    QStringList m_dataTypes;
    QStringList m_interfaceTypes;
};

} // namespace Builder
