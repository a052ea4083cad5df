// SPDX-License-Identifier: MIT
#include "coderestoredialog.h"

#include "backups.h"

#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace Builder {

CodeRestoreDialog::CodeRestoreDialog(const QString &projectDir, const QStringList &stamps,
                                     QWidget *parent)
    : QDialog(parent)
    , m_projectDir(projectDir)
    , m_sets(new QListWidget(this))
    , m_files(new QListWidget(this))
{
    setWindowTitle(tr("Code Restore"));
    auto *layout = new QVBoxLayout(this);
    auto *label = new QLabel(tr("Backups in %1. Restoring a set swaps its files with the current "
                                "ones, so the current files become a backup in turn.")
                                 .arg(QDir::toNativeSeparators(projectDir)),
                             this);
    label->setWordWrap(true);
    layout->addWidget(label);
    for (const QString &stamp : stamps) {
        const QDateTime when = QDateTime::fromString(stamp, QStringLiteral("yyyyMMddHHmmss"));
        auto *item = new QListWidgetItem(
            when.isValid() ? when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) : stamp);
        item->setData(Qt::UserRole, stamp);
        m_sets->addItem(item);
    }
    layout->addWidget(m_sets, 1);
    layout->addWidget(new QLabel(tr("Files of the selected backup:"), this));
    layout->addWidget(m_files, 1);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton *restore = box->addButton(tr("&Restore"), QDialogButtonBox::AcceptRole);
    connect(box, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(box);
    connect(m_sets, &QListWidget::currentRowChanged, this, [this, restore] {
        restore->setEnabled(!selectedStamp().isEmpty());
        showFiles();
    });
    m_sets->setCurrentRow(stamps.isEmpty() ? -1 : 0);
    restore->setEnabled(!selectedStamp().isEmpty());
    resize(520, 420);
}

QString CodeRestoreDialog::selectedStamp() const
{
    const QListWidgetItem *item = m_sets->currentItem();
    return item ? item->data(Qt::UserRole).toString() : QString();
}

QStringList CodeRestoreDialog::listedFiles() const
{
    QStringList files;
    for (int i = 0; i < m_files->count(); ++i)
        files << m_files->item(i)->text();
    return files;
}

void CodeRestoreDialog::showFiles()
{
    m_files->clear();
    const QString stamp = selectedStamp();
    if (stamp.isEmpty())
        return;
    const QDir dir(m_projectDir);
    for (const QString &backup : Codegen::Backups::filesOfSet(m_projectDir, stamp))
        m_files->addItem(dir.relativeFilePath(backup.left(backup.size() - stamp.size())));
}

} // namespace Builder
