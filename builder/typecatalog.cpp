// SPDX-License-Identifier: MIT
#include "typecatalog.h"

#include "idltypelibrary.h"
#include "installation.h"

#include <QDir>
#include <QSettings>
#include <QThread>

#include <atomic>
#include <utility>

namespace Builder {

namespace {

const char *const SettingsKey = "builder/idlDirectories";

} // namespace

/// One background scan: the worker fills `library` unless `cancel` stopped it.
struct TypeCatalog::Scan
{
    std::atomic_bool cancel {false};
    std::unique_ptr<Codegen::IdlTypeLibrary> library;
};

TypeCatalog::TypeCatalog(const QString &bundledDirectory, QObject *parent)
    : QObject(parent)
    , m_bundledDirectory(bundledDirectory.isEmpty() ? Codegen::Installation::bundledIdlDirectory()
                                                    : bundledDirectory)
    , m_library(std::make_unique<Codegen::IdlTypeLibrary>())
    , m_dataTypes(builtInDataTypes())
{ }

TypeCatalog::~TypeCatalog()
{
    // The threads may still post to this object: let them end first.
    if (m_scan)
        m_scan->cancel = true;
    if (m_thread)
        m_cancelled << m_thread;
    for (QThread *thread : std::as_const(m_cancelled)) {
        thread->wait();
        delete thread;
    }
}

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
    startReload();
    waitForLoaded();
}

void TypeCatalog::startReload()
{
    if (m_thread)
        cancelReload();
    auto scan = std::make_shared<Scan>();
    const QStringList folders = directories();
    m_scan = scan;
    m_thread = QThread::create([this, scan, folders] {
        auto library = std::make_unique<Codegen::IdlTypeLibrary>();
        const bool completed = library->setDirectories(folders, [this, scan](int done, int total, const QString &file) {
            if (scan->cancel)
                return false;
            // Queued to this object, whose destructor waits for this thread.
            QMetaObject::invokeMethod(this, [this, scan, done, total, file] {
                if (scan == m_scan)
                    emit loadingProgress(done, total, file);
            }, Qt::QueuedConnection);
            return true;
        });
        if (completed)
            scan->library = std::move(library);
    });
    connect(m_thread, &QThread::finished, this, [this, scan] {
        if (scan == m_scan)
            finishReload();
    });
    emit loadingStarted();
    m_thread->start();
}

void TypeCatalog::cancelReload()
{
    if (!m_thread)
        return;
    m_scan->cancel = true;
    m_scan.reset();
    QThread *thread = std::exchange(m_thread, nullptr);
    m_cancelled << thread;
    connect(thread, &QThread::finished, this, [this, thread] {
        m_cancelled.removeOne(thread);
        thread->deleteLater();
    });
    emit loadingFinished(true);
}

void TypeCatalog::waitForLoaded()
{
    if (m_thread)
        finishReload();
}

void TypeCatalog::finishReload()
{
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    const std::shared_ptr<Scan> scan = std::move(m_scan);
    const bool completed = scan->library != nullptr && !scan->cancel;
    if (completed) {
        m_library = std::move(scan->library);
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
    emit loadingFinished(!completed);
}

} // namespace Builder
