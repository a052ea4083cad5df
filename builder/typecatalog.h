// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QStringList>

#include <memory>

class QThread;

namespace Codegen {
class IdlTypeLibrary;
}

namespace Builder {

/**
 * The data types and service interfaces the editor offers, parsed from IDL folders: the bundled
 * OpenRTM IDL set plus the user's folders (kept in QSettings under `builder/idlDirectories`).
 * Until the first load, and when no IDL can be read, a small built-in list of OpenRTM data types
 * is offered so the choices are never empty.
 *
 * Folders are read on a worker thread (startReload()), file by file with loadingProgress(), and a
 * scan can be cancelled at any time; the types read before stay until a scan completes.
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

    bool isLoading() const { return m_thread != nullptr; }
    /// Blocks until a scan under way has ended and its types are in place.
    void waitForLoaded();

public slots:
    /// Parses the IDL folders again, waits for the result and announces typesChanged().
    void reload();
    /// Starts reading the IDL folders in the background (a scan under way is cancelled first).
    void startReload();
    /**
     * Drops a scan under way at once: the types stay as they were and loadingFinished(true) is
     * announced now; its thread stops after the file it is reading.
     */
    void cancelReload();

signals:
    void typesChanged();
    void loadingStarted();
    /// @p done of @p total files read; @p file is the one being read now.
    void loadingProgress(int done, int total, const QString &file);
    void loadingFinished(bool cancelled);

private:
    struct Scan;

    void finishReload();

    QString m_bundledDirectory;
    std::unique_ptr<Codegen::IdlTypeLibrary> m_library;
    QThread *m_thread = nullptr;
    std::shared_ptr<Scan> m_scan;
    QList<QThread *> m_cancelled; ///< threads of cancelled scans still reading their last file
    QStringList m_dataTypes;
    QStringList m_interfaceTypes;
};

} // namespace Builder
