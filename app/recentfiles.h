// SPDX-License-Identifier: MIT
#pragma once

#include <QObject>
#include <QStringList>

namespace Studio {

/**
 * The most recently opened or saved profile files, newest first, kept in QSettings.
 *
 * Files that no longer exist are pruned whenever the list is read, so the menu never offers
 * a file that cannot be opened.
 */
class RecentFiles : public QObject
{
    Q_OBJECT

public:
    static constexpr int DefaultMaximum = 10;

    /// Keeps the list in the default QSettings under `settingsKey`.
    explicit RecentFiles(const QString &settingsKey = QStringLiteral("recentFiles"),
                         QObject *parent = nullptr);

    /// The existing files, newest first (missing ones are removed from the settings too).
    QStringList files() const;
    /// Puts `path` (made absolute) at the top; drops the oldest beyond maximum().
    void add(const QString &path);
    void remove(const QString &path);
    void clear();

    int maximum() const { return m_maximum; }
    void setMaximum(int maximum);

signals:
    void changed();

private:
    QStringList stored() const;
    void store(const QStringList &files);

    QString m_key;
    int m_maximum = DefaultMaximum;
};

} // namespace Studio
