// SPDX-License-Identifier: MIT
#include "repository.h"

#include "debnames.h"
#include "gpgsigner.h"
#include "packagetool.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSaveFile>
#include <QSet>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>

namespace Packages {

namespace {

const QString ConfigFile = QStringLiteral("conf/repository");

bool writeFile(const QString &path, const QByteArray &data, QString *error)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.commit()) {
        *error = QStringLiteral("%1: cannot write: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

/// Puts @p staging in the place of @p target in one step (the old one ends at @p staging).
bool exchange(const QString &staging, const QString &target, QString *error)
{
    const QByteArray from = QFile::encodeName(staging);
    const QByteArray to = QFile::encodeName(target);
    if (!QFileInfo::exists(target)) {
        if (std::rename(from.constData(), to.constData()) == 0)
            return true;
    } else if (renameat2(AT_FDCWD, from.constData(), AT_FDCWD, to.constData(), RENAME_EXCHANGE)
               == 0) {
        return true;
    } else if (errno == EINVAL || errno == ENOSYS) {
        // A file system without exchange: two renames, with a moment between them.
        const QByteArray old = to + ".old";
        QDir(QFile::decodeName(old)).removeRecursively();
        if (std::rename(to.constData(), old.constData()) == 0
            && std::rename(from.constData(), to.constData()) == 0) {
            QDir(QFile::decodeName(old)).removeRecursively();
            return true;
        }
    }
    *error = QStringLiteral("%1: cannot replace the index: %2")
                 .arg(target, QString::fromLocal8Bit(std::strerror(errno)));
    return false;
}

} // namespace

Repository::Repository(QString root)
    : m_root(QDir(root).absolutePath())
{ }

void Repository::overrideSigning(const QString &keyId, const QString &gnupgHome)
{
    if (!keyId.isEmpty())
        m_config.signWith = keyId;
    if (!gnupgHome.isEmpty())
        m_config.gnupgHome = gnupgHome;
}

QString Repository::suiteFolder() const
{
    return m_root + QStringLiteral("/dists/") + m_config.suite;
}

bool Repository::writeConfig(QString *error) const
{
    DebControl conf;
    conf.set(QStringLiteral("Suite"), m_config.suite);
    conf.set(QStringLiteral("Component"), m_config.component);
    conf.set(QStringLiteral("Architectures"), m_config.architectures.join(QLatin1Char(' ')));
    conf.set(QStringLiteral("Origin"), m_config.origin);
    conf.set(QStringLiteral("Label"), m_config.label);
    if (!m_config.signWith.isEmpty())
        conf.set(QStringLiteral("Sign-With"), m_config.signWith);
    if (!m_config.gnupgHome.isEmpty())
        conf.set(QStringLiteral("GnuPG-Home"), m_config.gnupgHome);
    return writeFile(m_root + QLatin1Char('/') + ConfigFile, conf.toText(), error);
}

bool Repository::open(QString *error)
{
    QFile file(m_root + QLatin1Char('/') + ConfigFile);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: not a repository (no %2; create one with 'rtctl repo init')")
                     .arg(m_root, ConfigFile);
        return false;
    }
    QString reason;
    const std::optional<DebControl> conf = DebControl::parse(file.readAll(), &reason);
    if (!conf || conf->value(QStringLiteral("Suite")).isEmpty()) {
        *error = QStringLiteral("%1: unreadable: %2")
                     .arg(file.fileName(), reason.isEmpty() ? QStringLiteral("no Suite") : reason);
        return false;
    }
    m_config.suite = conf->value(QStringLiteral("Suite"));
    m_config.component = conf->value(QStringLiteral("Component"));
    m_config.architectures
        = conf->value(QStringLiteral("Architectures")).split(QLatin1Char(' '), Qt::SkipEmptyParts);
    m_config.origin = conf->value(QStringLiteral("Origin"));
    m_config.label = conf->value(QStringLiteral("Label"));
    m_config.signWith = conf->value(QStringLiteral("Sign-With"));
    m_config.gnupgHome = conf->value(QStringLiteral("GnuPG-Home"));
    return true;
}

bool Repository::init(RepositoryConfig config, const QString &newKeyUserId, QString *error)
{
    if (QFileInfo::exists(m_root + QLatin1Char('/') + ConfigFile)) {
        *error = QStringLiteral("%1: already a repository").arg(m_root);
        return false;
    }
    if (!isValidPackageName(config.suite) || !isValidPackageName(config.component)) {
        *error = QStringLiteral("invalid suite or component name '%1/%2'")
                     .arg(config.suite, config.component);
        return false;
    }
    if (config.architectures.isEmpty()) {
        const ToolResult arch
            = runTool(QStringLiteral("dpkg"), {QStringLiteral("--print-architecture")});
        if (!arch.ok()) {
            *error = arch.failure(QStringLiteral("dpkg --print-architecture"));
            return false;
        }
        config.architectures << QString::fromLatin1(arch.out).trimmed();
    }
    if (!newKeyUserId.isEmpty()) {
        const std::optional<QString> key
            = GpgSigner::createKey(config.gnupgHome, newKeyUserId, error);
        if (!key)
            return false;
        config.signWith = *key;
    }
    m_config = config;
    if (!m_config.signWith.isEmpty()) {
        // The key must sign before anything is written.
        const std::optional<QString> fingerprint
            = GpgSigner(m_config.signWith, m_config.gnupgHome).fingerprint(error);
        if (!fingerprint)
            return false;
    }
    if (!QDir().mkpath(m_root + QStringLiteral("/pool/") + m_config.component)) {
        *error = QStringLiteral("%1: cannot create the pool").arg(m_root);
        return false;
    }
    return exportKey(error) && writeIndex({}, error) && writeConfig(error);
}

bool Repository::exportKey(QString *error) const
{
    if (m_config.signWith.isEmpty())
        return true;
    const GpgSigner signer(m_config.signWith, m_config.gnupgHome);
    for (const bool armored : {true, false}) {
        const std::optional<QByteArray> key = signer.exportPublicKey(armored, error);
        if (!key)
            return false;
        const QString name
            = armored ? QStringLiteral("/archive-key.asc") : QStringLiteral("/archive-key.gpg");
        if (!writeFile(m_root + name, *key, error))
            return false;
    }
    return true;
}

std::optional<QList<IndexEntry>> Repository::packages(QString *error) const
{
    QList<IndexEntry> entries;
    QSet<QString> seen;
    for (const QString &architecture : m_config.architectures) {
        const QString path = QStringLiteral("%1/%2/binary-%3/Packages")
                                 .arg(suiteFolder(), m_config.component, architecture);
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            continue; // an architecture added by a publish that did not finish
        QString reason;
        const std::optional<QList<DebControl>> paragraphs
            = DebControl::parseAll(file.readAll(), &reason);
        if (!paragraphs) {
            *error = QStringLiteral("%1: %2").arg(path, reason);
            return std::nullopt;
        }
        for (const DebControl &paragraph : *paragraphs) {
            IndexEntry entry {paragraph};
            if (!seen.contains(entry.filename())) {
                seen.insert(entry.filename());
                entries << entry;
            }
        }
    }
    std::sort(entries.begin(), entries.end(), [](const IndexEntry &a, const IndexEntry &b) {
        if (a.package() != b.package())
            return a.package() < b.package();
        if (const int c = compareVersions(a.version(), b.version()))
            return c < 0;
        return a.architecture() < b.architecture();
    });
    return entries;
}

bool Repository::writeIndex(const QList<IndexEntry> &entries, QString *error)
{
    ReleaseInfo info;
    info.origin = m_config.origin;
    info.label = m_config.label;
    info.suite = m_config.suite;
    info.component = m_config.component;
    info.architectures = m_config.architectures;
    info.description = QStringLiteral("RT-Component packages");
    const std::optional<QList<IndexFile>> files = packagesFiles(entries, info, error);
    if (!files)
        return false;
    const QByteArray release = releaseText(info, *files);
    const QString staging
        = m_root + QStringLiteral("/dists/.") + m_config.suite + QStringLiteral(".new");
    QDir(staging).removeRecursively();
    auto fail = [&staging]() {
        QDir(staging).removeRecursively();
        return false;
    };
    for (const IndexFile &file : *files) {
        if (!writeFile(staging + QLatin1Char('/') + file.path, file.data, error))
            return fail();
    }
    if (!writeFile(staging + QStringLiteral("/Release"), release, error))
        return fail();
    if (!m_config.signWith.isEmpty()) {
        const GpgSigner signer(m_config.signWith, m_config.gnupgHome);
        const std::optional<QByteArray> inRelease = signer.clearSign(release, error);
        if (!inRelease || !writeFile(staging + QStringLiteral("/InRelease"), *inRelease, error))
            return fail();
        const std::optional<QByteArray> detached = signer.detachSign(release, error);
        if (!detached || !writeFile(staging + QStringLiteral("/Release.gpg"), *detached, error))
            return fail();
    }
    if (!exchange(staging, suiteFolder(), error))
        return fail();
    QDir(staging).removeRecursively(); // the previous index, after the exchange
    return true;
}

bool Repository::reindex(QString *error)
{
    QLockFile lockFile(m_root + QStringLiteral("/conf/lock"));
    const std::optional<QList<IndexEntry>> entries
        = lock(&lockFile, error) ? packages(error) : std::nullopt;
    return entries && writeIndex(*entries, error);
}

/// A package to publish and the file it comes from.
struct Incoming
{
    IndexEntry entry;
    QString source;
};

namespace {

/// The pool files one publish wrote or kept aside, to keep or to undo.
struct PoolChange
{
    QStringList written;
    QStringList keptAside; ///< renamed to <path>.replaced

    void rollback() const
    {
        for (const QString &path : written)
            QFile::remove(path);
        for (const QString &path : keptAside)
            QFile::rename(path + QStringLiteral(".replaced"), path);
    }
    void commit() const
    {
        for (const QString &path : keptAside)
            QFile::remove(path + QStringLiteral(".replaced"));
    }
};

/// Copies @p source to @p target through a partial file, the file it replaces kept aside in @p
/// change.
bool copyIntoPool(const QString &source, const QString &target, PoolChange *change, QString *error)
{
    QDir().mkpath(QFileInfo(target).absolutePath());
    if (QFileInfo::exists(target)) {
        QFile::remove(target + QStringLiteral(".replaced"));
        if (!QFile::rename(target, target + QStringLiteral(".replaced"))) {
            *error = QStringLiteral("%1: cannot replace").arg(target);
            return false;
        }
        change->keptAside << target;
    }
    const QString partial = target + QStringLiteral(".partial");
    QFile::remove(partial);
    if (!QFile::copy(source, partial) || !QFile::rename(partial, target)) {
        QFile::remove(partial);
        *error = QStringLiteral("%1: cannot copy into the pool (%2)").arg(source, target);
        return false;
    }
    change->written << target;
    return true;
}

} // namespace

bool Repository::lock(QLockFile *lockFile, QString *error) const
{
    // Another rtctl publishing into the same folder waits its turn.
    if (lockFile->tryLock(30000))
        return true;
    *error = QStringLiteral("%1: in use by another process (%2)").arg(m_root, lockFile->fileName());
    return false;
}

std::optional<QList<IndexEntry>> Repository::readIncoming(const QStringList &debFiles,
                                                          const QList<IndexEntry> &existing,
                                                          bool replace, QList<Incoming> *incoming,
                                                          QString *error)
{
    QSet<QString> keys;
    for (const QString &deb : debFiles) {
        std::optional<IndexEntry> entry = readDebEntry(deb, QString(), error);
        if (!entry)
            return std::nullopt;
        entry->control.set(QStringLiteral("Filename"), poolPath(m_config.component, *entry));
        if (!isValidPackageName(entry->package()) || !isValidVersion(entry->version())) {
            *error
                = QStringLiteral("%1: invalid package name or version '%2'").arg(deb, entry->key());
            return std::nullopt;
        }
        if (keys.contains(entry->key())) {
            *error = QStringLiteral("%1: %2 is given twice").arg(deb, entry->key());
            return std::nullopt;
        }
        const bool present
            = std::any_of(existing.cbegin(), existing.cend(),
                          [&entry](const IndexEntry &e) { return e.key() == entry->key(); });
        if (present && !replace) {
            *error = QStringLiteral("%1: %2 is already in the repository (--replace to replace it)")
                         .arg(deb, entry->key());
            return std::nullopt;
        }
        const QString architecture = entry->architecture();
        if (architecture != QLatin1String("all") && !m_config.architectures.contains(architecture))
            m_config.architectures << architecture;
        keys.insert(entry->key());
        *incoming << Incoming {*entry, deb};
    }
    // What stays: every entry not replaced.
    QList<IndexEntry> kept;
    for (const IndexEntry &entry : existing) {
        if (!keys.contains(entry.key()))
            kept << entry;
    }
    return kept;
}

std::optional<QList<IndexEntry>> Repository::publish(const QStringList &debFiles, bool replace,
                                                     QString *error)
{
    QLockFile lockFile(m_root + QStringLiteral("/conf/lock"));
    const std::optional<QList<IndexEntry>> existing
        = lock(&lockFile, error) ? packages(error) : std::nullopt;
    if (!existing)
        return std::nullopt;
    const RepositoryConfig before = m_config;
    QList<Incoming> incoming;
    std::optional<QList<IndexEntry>> entries
        = readIncoming(debFiles, *existing, replace, &incoming, error);
    if (!entries) {
        m_config = before;
        return std::nullopt;
    }
    // Into the pool first (replaced files kept aside), then the index; undone when the index fails.
    PoolChange change;
    QList<IndexEntry> added;
    bool ok = true;
    for (const Incoming &in : incoming) {
        ok = ok
            && copyIntoPool(in.source, m_root + QLatin1Char('/') + in.entry.filename(), &change,
                            error);
        added << in.entry;
    }
    *entries << added;
    ok = ok && writeIndex(*entries, error)
        && (m_config.architectures == before.architectures || writeConfig(error));
    if (!ok) {
        change.rollback();
        m_config = before;
        return std::nullopt;
    }
    change.commit();
    return added;
}

std::optional<QList<IndexEntry>> Repository::remove(const QString &package, const QString &version,
                                                    QString *error)
{
    QLockFile lockFile(m_root + QStringLiteral("/conf/lock"));
    const std::optional<QList<IndexEntry>> existing
        = lock(&lockFile, error) ? packages(error) : std::nullopt;
    if (!existing)
        return std::nullopt;
    QList<IndexEntry> kept;
    QList<IndexEntry> removed;
    for (const IndexEntry &entry : *existing) {
        const bool match
            = entry.package() == package && (version.isEmpty() || entry.version() == version);
        (match ? removed : kept) << entry;
    }
    if (removed.isEmpty()) {
        *error
            = QStringLiteral("%1: no package %2%3")
                  .arg(m_root, package, version.isEmpty() ? QString() : QLatin1Char('=') + version);
        return std::nullopt;
    }
    // The index first: it never names a file that is gone.
    if (!writeIndex(kept, error))
        return std::nullopt;
    for (const IndexEntry &entry : removed) {
        const QString path = m_root + QLatin1Char('/') + entry.filename();
        QFile::remove(path);
        QDir pool(m_root + QStringLiteral("/pool"));
        QString folder = QFileInfo(path).absolutePath();
        while (folder.startsWith(pool.absolutePath() + QLatin1Char('/')) && QDir(folder).isEmpty()
               && QDir().rmdir(folder))
            folder = QFileInfo(folder).absolutePath();
    }
    return removed;
}

} // namespace Packages
