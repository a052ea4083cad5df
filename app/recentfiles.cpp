// SPDX-License-Identifier: MIT
#include "recentfiles.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace Studio {

namespace {

QString normalised(const QString &path)
{
    return QDir::cleanPath(QFileInfo(path).absoluteFilePath());
}

} // namespace

RecentFiles::RecentFiles(const QString &settingsKey, QObject *parent)
    : QObject(parent)
    , m_key(settingsKey)
{ }

QStringList RecentFiles::files() const
{
    const QStringList all = stored();
    QStringList existing;
    for (const QString &path : all) {
        if (QFileInfo(path).isFile())
            existing << path;
    }
    // Pruning writes through a const reader, so that a stale entry disappears everywhere at once.
    if (existing != all)
        const_cast<RecentFiles *>(this)->store(existing);
    return existing;
}

void RecentFiles::add(const QString &path)
{
    const QString absolute = normalised(path);
    QStringList list = stored();
    list.removeAll(absolute);
    list.prepend(absolute);
    store(list);
}

void RecentFiles::remove(const QString &path)
{
    QStringList list = stored();
    if (list.removeAll(normalised(path)) > 0)
        store(list);
}

void RecentFiles::clear()
{
    store({});
}

void RecentFiles::setMaximum(int maximum)
{
    m_maximum = qMax(1, maximum);
    store(stored());
}

QStringList RecentFiles::stored() const
{
    return QSettings().value(m_key).toStringList();
}

void RecentFiles::store(const QStringList &files)
{
    const QStringList limited = files.mid(0, m_maximum);
    QSettings settings;
    if (settings.value(m_key).toStringList() == limited && settings.contains(m_key))
        return;
    settings.setValue(m_key, limited);
    emit changed();
}

} // namespace Studio
