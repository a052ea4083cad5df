// SPDX-License-Identifier: MIT
#include "rtcrepository.h"

#include "profileio.h"
#include "remoteindex.h"
#include "repository.h"
#include "repositoryfetcher.h"

#include <QCryptographicHash>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QMap>
#include <QMimeData>
#include <QStandardPaths>
#include <QUrl>
#include <QtConcurrent>

namespace SystemEditor {

using namespace Profile;

namespace {

/// Category rows have internal id 0; component rows carry their category row + 1.
constexpr quintptr CategoryId = 0;

bool isProfileFileName(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("xml") || suffix == QLatin1String("yaml")
        || suffix == QLatin1String("yml");
}

/// How long one file of a repository reached over the network may take.
constexpr int fetchTimeoutMs = 30000;

bool isUrl(const QString &source)
{
    const QString scheme = QUrl(source).scheme();
    return scheme == QLatin1String("http") || scheme == QLatin1String("https")
        || scheme == QLatin1String("file");
}

QString diagnosticsText(const Diagnostics &diagnostics)
{
    QStringList lines;
    for (const Diagnostic &d : diagnostics)
        lines << d.toString();
    return lines.join(QLatin1Char('\n'));
}

} // namespace

RtcRepository::RtcRepository(QObject *parent)
    : QAbstractItemModel(parent)
{ }

bool RtcRepository::addSource(const QString &path)
{
    const QFileInfo info(path);
    if (!isUrl(path) && !info.exists())
        return false;
    const QString absolute = isUrl(path) ? path : info.absoluteFilePath();
    if (m_sources.contains(absolute))
        return true;
    m_sources << absolute;
    reload();
    return true;
}

void RtcRepository::removeSource(const QString &path)
{
    if (m_sources.removeAll(isUrl(path) ? path : QFileInfo(path).absoluteFilePath()) > 0) {
        m_reads.remove(path);
        reload();
    }
}

void RtcRepository::clear()
{
    m_sources.clear();
    reload();
}

void RtcRepository::reload()
{
    ++m_generation;
    m_reading = 0;
    QHash<QString, SourceRead> reads;
    for (const QString &source : std::as_const(m_sources)) {
        if (isComponentRepository(source)) {
            // What was read before stays shown until the new read arrives.
            if (m_reads.contains(source))
                reads.insert(source, m_reads.value(source));
            readInBackground(source);
        } else {
            reads.insert(source, readSource(source));
        }
    }
    m_reads = reads;
    publish();
}

void RtcRepository::publish()
{
    const QList<FileError> oldErrors = m_errors;
    beginResetModel();
    m_entries.clear();
    m_errors.clear();
    for (const QString &source : std::as_const(m_sources)) {
        const SourceRead read = m_reads.value(source);
        m_entries << read.entries;
        m_errors << read.errors;
    }
    rebuildCategories();
    endResetModel();
    const auto paths = [](const QList<FileError> &errors) {
        QStringList result;
        for (const FileError &e : errors)
            result << e.filePath + diagnosticsText(e.diagnostics);
        return result;
    };
    if (paths(oldErrors) != paths(m_errors))
        emit errorsChanged();
}

void RtcRepository::readInBackground(const QString &source)
{
    ++m_reading;
    const quint64 generation = m_generation;
    auto *watcher = new QFutureWatcher<SourceRead>(this);
    connect(watcher, &QFutureWatcher<SourceRead>::finished, this, [this, watcher, source, generation] {
        watcher->deleteLater();
        if (generation != m_generation || !m_sources.contains(source))
            return;
        --m_reading;
        m_reads.insert(source, watcher->result());
        publish();
        emit repositoryRead(source);
    });
    watcher->setFuture(QtConcurrent::run(&RtcRepository::readComponentRepository, source));
}

bool RtcRepository::removePackage(const QModelIndex &index)
{
    const Entry *row = entry(index);
    if (!row || row->package.isEmpty() || isUrl(row->repository))
        return false;
    const QString root = row->repository;
    const QString package = row->package;
    const QString version = row->packageVersion;
    auto *watcher = new QFutureWatcher<QString>(this);
    connect(watcher, &QFutureWatcher<QString>::finished, this, [this, watcher, package, version] {
        watcher->deleteLater();
        reload();
        emit packageRemoved(QStringLiteral("%1 %2").arg(package, version), watcher->result());
    });
    watcher->setFuture(QtConcurrent::run([root, package, version] {
        Packages::Repository repository(root);
        QString error;
        if (repository.open(&error))
            repository.remove(package, version, &error);
        return error;
    }));
    return true;
}

bool RtcRepository::isComponentRepository(const QString &source)
{
    return isUrl(source) || QFileInfo::exists(QDir(source).filePath(QStringLiteral("conf/repository")));
}

RtcRepository::SourceRead RtcRepository::readSource(const QString &path)
{
    SourceRead read;
    if (QFileInfo(path).isFile()) {
        readFile(path, true, &read);
        return read;
    }
    QStringList files;
    QDirIterator it(path, QDir::Files | QDir::Readable, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        if (isProfileFileName(file))
            files << file;
    }
    files.sort(); // a stable order, independent of the file system
    for (const QString &file : std::as_const(files))
        readFile(file, false, &read);
    return read;
}

void RtcRepository::readFile(const QString &path, bool explicitlyAdded, SourceRead *read)
{
    QFile file(path);
    QByteArray head;
    if (file.open(QIODevice::ReadOnly))
        head = file.read(64 * 1024);
    // In a folder only files that say they are RTC profiles count; an added file must be one.
    if (!explicitlyAdded && detectProfileKind(head) != ProfileKind::Rtc)
        return;
    Diagnostics diagnostics;
    const std::optional<LoadedProfile> loaded = loadProfileFile(path, &diagnostics);
    if (loaded && loaded->rtc) {
        read->entries << Entry {path, *loaded->rtc, {}, {}, {}};
        return;
    }
    if (loaded && !loaded->rtc)
        diagnostics << Diagnostic::error(path, 0, 0, tr("The file is no RTC profile."));
    read->errors << FileError {path, diagnostics};
}

QString RtcRepository::cacheFolder()
{
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation)
        + QStringLiteral("/component-repositories");
}

// Runs in a worker thread: no member is touched.
RtcRepository::SourceRead RtcRepository::readComponentRepository(const QString &source)
{
    // One cache folder per repository, so that two repositories with alike packages do not mix.
    const QString cache = cacheFolder() + QLatin1Char('/')
        + QString::fromLatin1(QCryptographicHash::hash(source.toUtf8(), QCryptographicHash::Sha1).toHex().left(16));
    QStringList problems;
    QString error;
    const auto profiles = isUrl(source)
        ? Packages::readRemoteRepositoryProfiles(source, Packages::RepositoryFetcher(QString(), fetchTimeoutMs),
                                                 cache, &problems, &error)
        : Packages::readRepositoryProfiles(source, cache, &problems, &error);
    SourceRead read;
    if (!profiles) {
        read.errors << FileError{source, {Diagnostic::error(source, 0, 0, error)}};
        return read;
    }
    for (const QString &problem : std::as_const(problems))
        read.errors << FileError{source, {Diagnostic::error(source, 0, 0, problem)}};
    for (const Packages::PackagedProfile &packaged : *profiles) {
        Diagnostics diagnostics;
        const std::optional<LoadedProfile> loaded = loadProfileFile(packaged.profileFile, &diagnostics);
        if (!loaded || !loaded->rtc) {
            diagnostics.prepend(Diagnostic::error(source, 0, 0,
                                                  tr("The RTC profile of package %1 %2 cannot be read.")
                                                      .arg(packaged.entry.package(), packaged.entry.version())));
            read.errors << FileError{packaged.profileFile, diagnostics};
            continue;
        }
        read.entries << Entry{packaged.profileFile, *loaded->rtc, packaged.entry.package(),
                              packaged.entry.version(), source};
    }
    return read;
}

void RtcRepository::rebuildCategories()
{
    QMap<QString, Category> byName;
    for (int i = 0; i < m_entries.size(); ++i) {
        QString name = m_entries.at(i).profile.basicInfo.category;
        if (name.isEmpty())
            name = tr("(no category)");
        Category &category = byName[name];
        category.name = name;
        category.rows << i;
    }
    m_categories = byName.values();
    if (!m_errors.isEmpty()) {
        Category errors;
        errors.name = errorCategoryName();
        errors.errors = true;
        for (int i = 0; i < m_errors.size(); ++i)
            errors.rows << i;
        m_categories << errors;
    }
}

const RtcProfile *RtcRepository::profileForFile(const QString &filePath) const
{
    const QString absolute = QFileInfo(filePath).absoluteFilePath();
    for (const Entry &entry : m_entries) {
        if (QFileInfo(entry.filePath).absoluteFilePath() == absolute)
            return &entry.profile;
    }
    return nullptr;
}

const RtcRepository::Entry *RtcRepository::entry(const QModelIndex &index) const
{
    if (!index.isValid() || index.internalId() == CategoryId)
        return nullptr;
    const Category &category = m_categories.at(int(index.internalId() - 1));
    if (category.errors)
        return nullptr;
    return &m_entries.at(category.rows.at(index.row()));
}

QString RtcRepository::errorCategoryName()
{
    return tr("Unreadable files");
}

QModelIndex RtcRepository::index(int row, int column, const QModelIndex &parent) const
{
    if (!hasIndex(row, column, parent))
        return {};
    if (!parent.isValid())
        return createIndex(row, column, CategoryId);
    return createIndex(row, column, quintptr(parent.row() + 1));
}

QModelIndex RtcRepository::parent(const QModelIndex &child) const
{
    if (!child.isValid() || child.internalId() == CategoryId)
        return {};
    return createIndex(int(child.internalId() - 1), 0, CategoryId);
}

int RtcRepository::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return int(m_categories.size());
    if (parent.column() != 0 || parent.internalId() != CategoryId)
        return 0;
    return int(m_categories.at(parent.row()).rows.size());
}

int RtcRepository::columnCount(const QModelIndex &) const
{
    return 1;
}

QVariant RtcRepository::data(const QModelIndex &index, int role) const
{
    if (!index.isValid())
        return {};
    if (index.internalId() == CategoryId) {
        const Category &category = m_categories.at(index.row());
        if (role == Qt::DisplayRole)
            return category.name;
        if (role == IsCategoryRole)
            return true;
        return {};
    }
    const Category &category = m_categories.at(int(index.internalId() - 1));
    const int row = category.rows.at(index.row());
    if (category.errors) {
        const FileError &error = m_errors.at(row);
        switch (role) {
        case Qt::DisplayRole:
            return QFileInfo(error.filePath).fileName();
        case Qt::ToolTipRole:
        case ErrorRole:
            return diagnosticsText(error.diagnostics);
        case FilePathRole:
            return error.filePath;
        case IsCategoryRole:
            return false;
        default:
            return {};
        }
    }
    const Entry &entry = m_entries.at(row);
    switch (role) {
    case Qt::DisplayRole:
        return entry.profile.basicInfo.name;
    case Qt::ToolTipRole:
        return entry.package.isEmpty()
            ? tr("%1\n%2").arg(entry.profile.id, entry.filePath)
            : tr("%1\npackage %2 %3 in %4").arg(entry.profile.id, entry.package, entry.packageVersion,
                                               entry.repository);
    case FilePathRole:
        return entry.filePath;
    case ComponentIdRole:
        return entry.profile.id;
    case IsCategoryRole:
        return false;
    default:
        return {};
    }
}

QVariant RtcRepository::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (section == 0 && orientation == Qt::Horizontal && role == Qt::DisplayRole)
        return tr("Component");
    return {};
}

Qt::ItemFlags RtcRepository::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags result = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (entry(index))
        result |= Qt::ItemIsDragEnabled;
    return result;
}

QStringList RtcRepository::mimeTypes() const
{
    return {MimeType};
}

QMimeData *RtcRepository::mimeData(const QModelIndexList &indexes) const
{
    QStringList paths;
    for (const QModelIndex &index : indexes) {
        if (const Entry *e = entry(index))
            paths << e->filePath;
    }
    if (paths.isEmpty())
        return nullptr;
    auto *mime = new QMimeData;
    // One path per line, so that dragging several components drops all of them.
    mime->setData(MimeType, paths.join(QLatin1Char('\n')).toUtf8());
    return mime;
}

} // namespace SystemEditor
