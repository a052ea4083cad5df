// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "rtcprofile.h"

#include <QAbstractItemModel>
#include <QHash>

namespace SystemEditor {

/**
 * The offline editor's repository: RTC profiles loaded from files and folders, shown as a tree
 * category → component, dragged onto the editor as `application/x-rtstudio-rtc-profile` mime
 * data carrying the profile's file path.
 *
 * Folders are searched recursively for `*.xml`, `*.yaml` and `*.yml` files holding RTC profiles
 * (other profiles and other XML are skipped). A file that claims to be an RTC profile but cannot
 * be read is kept as an error — listed under the "Unreadable files" branch with its
 * diagnostics as tool tip, and in errors() — so that the user sees why a component is missing.
 *
 * A component repository (`rtctl repo init`: a Debian repository of component packages), as a
 * folder or by URL (http, https, file), lists the newest version of each of its packages, with
 * the RTC profile read from the package (kept in the cache folder, cacheFolder()); its rows name
 * the package and version. Repositories are read in a background thread (packages are downloaded
 * and unpacked the first time); their rows appear when repositoryRead() says so.
 */
class RtcRepository : public QAbstractItemModel
{
    Q_OBJECT

public:
    static inline const QString MimeType = QStringLiteral("application/x-rtstudio-rtc-profile");

    enum Role {
        FilePathRole = Qt::UserRole + 1, ///< component and error rows: the file
        ComponentIdRole, ///< component rows: `RTC:vendor:category:name:version`
        IsCategoryRole, ///< true on category rows
        ErrorRole ///< error rows: the diagnostics, one per line
    };

    /// One profile that was read.
    struct Entry
    {
        QString filePath;
        Profile::RtcProfile profile;
        QString package; ///< from a component repository: the package that ships it
        QString packageVersion;
        QString repository; ///< that repository's folder or URL
    };
    /// One file that could not be read.
    struct FileError
    {
        QString filePath;
        Profile::Diagnostics diagnostics;
    };

    explicit RtcRepository(QObject *parent = nullptr);

    /// Adds a file, a folder (searched recursively) or a component repository's URL and reads it.
    /// False when a file or folder does not exist.
    bool addSource(const QString &path);
    /// Forgets a source and what came from it.
    void removeSource(const QString &path);
    QStringList sources() const { return m_sources; }
    /// Reads every source again (files changed on disk, new files in folders); component
    /// repositories in the background.
    void reload();
    /// True while a component repository is being read.
    bool isReading() const { return m_reading > 0; }
    /**
     * Removes the package of the component row @p index from its repository folder (as `rtctl
     * repo remove REPO NAME=VERSION`: the index written and signed again), off the GUI thread;
     * packageRemoved() says how it went and the repository is read again. False when the row
     * comes from no repository folder.
     */
    bool removePackage(const QModelIndex &index);
    void clear();

    QList<Entry> entries() const { return m_entries; }
    QList<FileError> errors() const { return m_errors; }
    /// The profile read from `filePath`, or null.
    const Profile::RtcProfile *profileForFile(const QString &filePath) const;
    /// The entry at a component row, or null for other rows.
    const Entry *entry(const QModelIndex &index) const;

    /// Where profiles read from component repositories' packages are kept.
    static QString cacheFolder();

    /// The text shown for errors' branch.
    static QString errorCategoryName();

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QStringList mimeTypes() const override;
    QMimeData *mimeData(const QModelIndexList &indexes) const override;

signals:
    /// The list of unreadable files changed.
    void errorsChanged();
    /// The component repository @p source was read (its rows and errors are in the model).
    void repositoryRead(const QString &source);
    /// removePackage() ended: @p error is empty when the package was removed.
    void packageRemoved(const QString &package, const QString &error);

private:
    struct Category
    {
        QString name;
        QList<int> rows; ///< indices into m_entries, or into m_errors for the errors branch
        bool errors = false;
    };

    /// What one source gave.
    struct SourceRead
    {
        QList<Entry> entries;
        QList<FileError> errors;
    };

    static bool isComponentRepository(const QString &source);
    static SourceRead readSource(const QString &path);
    static void readFile(const QString &path, bool explicitlyAdded, SourceRead *read);
    static SourceRead readComponentRepository(const QString &source);
    void readInBackground(const QString &source);
    /// Shows what the sources gave, in the sources' order.
    void publish();
    void rebuildCategories();

    QStringList m_sources;
    QHash<QString, SourceRead> m_reads;
    quint64 m_generation = 0; ///< a background read of an older reload() is dropped
    int m_reading = 0;
    QList<Entry> m_entries;
    QList<FileError> m_errors;
    QList<Category> m_categories;
};

} // namespace SystemEditor
