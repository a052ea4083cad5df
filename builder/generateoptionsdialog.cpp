// SPDX-License-Identifier: MIT
#include "generateoptionsdialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace Builder {

GenerateOptionsDialog::GenerateOptionsDialog(const GenerateOptions &current, QWidget *parent)
    : QDialog(parent)
    , m_folder(new QLineEdit(QDir::toNativeSeparators(current.outputFolder), this))
    , m_backups(new QSpinBox(this))
    , m_testComponent(new QCheckBox(tr("Also generate a &test component"), this))
{
    setWindowTitle(tr("Generate"));
    auto *form = new QFormLayout(this);
    auto *folderRow = new QHBoxLayout;
    auto *browse = new QPushButton(tr("&Browse…"), this);
    connect(browse, &QPushButton::clicked, this, &GenerateOptionsDialog::browse);
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    // A row holding a layout gets no buddy by itself, which would show the '&'.
    auto *folderLabel = new QLabel(tr("&Output folder:"), this);
    folderLabel->setBuddy(m_folder);
    form->addRow(folderLabel, folderRow);
    m_backups->setRange(0, 99);
    m_backups->setValue(current.backupsKept);
    m_backups->setToolTip(tr("Merged and overwritten files are backed up as "
                             "<file>YYYYMMDDHHMMSS; older backups beyond this number are "
                             "deleted."));
    form->addRow(tr("&Backups kept per file:"), m_backups);
    m_testComponent->setChecked(current.testComponent);
    m_testComponent->setToolTip(tr("Writes test/: a project of the component <N>Test (in C++, or in "
                                   "Python when Python is the only language), whose ports mirror this "
                                   "component's, to exercise it by connecting the two."));
    form->addRow(QString(), m_testComponent);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton *ok = box->addButton(tr("&Generate"), QDialogButtonBox::AcceptRole);
    connect(box, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_folder, &QLineEdit::textChanged, ok,
            [ok](const QString &text) { ok->setEnabled(!text.trimmed().isEmpty()); });
    ok->setEnabled(!current.outputFolder.isEmpty());
    form->addRow(box);
    setMinimumWidth(520);
}

GenerateOptions GenerateOptionsDialog::options() const
{
    return {QDir::fromNativeSeparators(m_folder->text().trimmed()), m_backups->value(),
            m_testComponent->isChecked()};
}

void GenerateOptionsDialog::browse()
{
    const QString folder
        = QFileDialog::getExistingDirectory(this, tr("Output Folder"), m_folder->text());
    if (!folder.isEmpty())
        m_folder->setText(QDir::toNativeSeparators(folder));
}

} // namespace Builder
