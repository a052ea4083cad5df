// SPDX-License-Identifier: MIT
#pragma once

// A small tmpfs mounted for the length of a test, to make a full disk or a read-only file system
// that even root cannot write to. Mounting needs root (CI runs as root); tests skip with the
// reason elsewhere (TESTDISK_MOUNT_OR_SKIP).

#include <QFile>
#include <QProcess>
#include <QTest>
#include <QString>
#include <QStringList>

/// Mounts @p disk (a TmpfsMount) on @p dir or skips the test function with the reason.
#define TESTDISK_MOUNT_OR_SKIP(disk, dir)                                                                    \
    do {                                                                                                     \
        QString why_;                                                                                        \
        if (!(disk).mount((dir), 256, &why_))                                                                \
            QSKIP(qPrintable("skipped: cannot mount a small file system here (" + why_ + ")"));             \
    } while (false)

namespace TestDisk {

class TmpfsMount
{
public:
    TmpfsMount() = default;
    TmpfsMount(const TmpfsMount &) = delete;
    TmpfsMount &operator=(const TmpfsMount &) = delete;
    ~TmpfsMount()
    {
        if (!m_dir.isEmpty())
            run({QStringLiteral("umount"), QStringLiteral("-l"), m_dir});
    }

    /// Mounts a tmpfs of @p kib KiB on the existing folder @p dir; false with the reason in @p why.
    bool mount(const QString &dir, int kib, QString *why)
    {
        if (!run({QStringLiteral("mount"), QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                  QStringLiteral("size=%1k").arg(kib), QStringLiteral("tmpfs"), dir},
                 why))
            return false;
        m_dir = dir;
        return true;
    }

    /// Makes the mounted file system read-only; false with the reason in @p why.
    bool makeReadOnly(QString *why)
    {
        return run({QStringLiteral("mount"), QStringLiteral("-o"), QStringLiteral("remount,ro"), m_dir}, why);
    }

    /// Fills the file system (@p readOnly false) or makes it read-only; false with the reason in
    /// @p why.
    bool spoil(bool readOnly, QString *why)
    {
        if (readOnly)
            return makeReadOnly(why);
        fill();
        return true;
    }

    /// Writes a file that takes the space left; what is left is less than a page.
    void fill() const
    {
        QFile filler(m_dir + QStringLiteral("/filler"));
        if (!filler.open(QIODevice::WriteOnly))
            return;
        const QByteArray page(4096, 'x');
        while (filler.write(page) == page.size() && filler.flush()) { }
        const QByteArray byte(1, 'x');
        while (filler.write(byte) == 1 && filler.flush()) { }
    }

private:
    static bool run(const QStringList &command, QString *why = nullptr)
    {
        QProcess process;
        process.setProcessChannelMode(QProcess::MergedChannels);
        process.start(command.first(), command.mid(1));
        const bool ok = process.waitForFinished(10000) && process.exitStatus() == QProcess::NormalExit
            && process.exitCode() == 0;
        if (!ok && why)
            *why = QStringLiteral("%1: %2").arg(command.join(QLatin1Char(' ')),
                                                QString::fromLocal8Bit(process.readAll()).trimmed()
                                                    + process.errorString());
        return ok;
    }

    QString m_dir;
};

/// The data rows of a test run once on a full disk and once on a read-only file system (column
/// `readOnly`, for TmpfsMount::spoil()).
inline void addSpoiledDiskRows()
{
    QTest::addColumn<bool>("readOnly");
    QTest::newRow("full disk") << false;
    QTest::newRow("read-only file system") << true;
}

} // namespace TestDisk
