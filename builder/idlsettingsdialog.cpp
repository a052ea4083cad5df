// SPDX-License-Identifier: MIT
#include "idlsettingsdialog.h"

#include "typecatalog.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace Builder {

IdlSettingsDialog::IdlSettingsDialog(TypeCatalog *catalog, QWidget *parent)
    : QDialog(parent)
    , m_catalog(catalog)
    , m_list(new QListWidget(this))
{
    setWindowTitle(tr("IDL Folders"));
    m_list->addItems(TypeCatalog::userDirectories());
    auto *bundled = new QLabel(
        tr("Bundled OpenRTM IDL: %1").arg(catalog->bundledDirectory().toHtmlEscaped()), this);
    bundled->setWordWrap(true);
    auto *add = new QPushButton(tr("&Add..."), this);
    auto *remove = new QPushButton(tr("&Remove"), this);
    connect(add, &QPushButton::clicked, this, [this] {
        const QString directory = QFileDialog::getExistingDirectory(this, tr("IDL Folder"));
        if (!directory.isEmpty())
            addDirectory(directory);
    });
    connect(remove, &QPushButton::clicked, this, &IdlSettingsDialog::removeSelected);
    auto *buttons = new QVBoxLayout;
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    auto *row = new QHBoxLayout;
    row->addWidget(m_list, 1);
    row->addLayout(buttons);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(box, &QDialogButtonBox::accepted, this, &IdlSettingsDialog::accept);
    connect(box, &QDialogButtonBox::rejected, this, &IdlSettingsDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(bundled);
    layout->addWidget(new QLabel(tr("Your IDL folders (searched after the bundled one):"), this));
    layout->addLayout(row);
    layout->addWidget(box);
}

QStringList IdlSettingsDialog::directories() const
{
    QStringList result;
    for (int i = 0; i < m_list->count(); ++i)
        result << m_list->item(i)->text();
    return result;
}

void IdlSettingsDialog::addDirectory(const QString &directory)
{
    if (!directories().contains(directory))
        m_list->addItem(directory);
}

void IdlSettingsDialog::removeSelected()
{
    delete m_list->currentItem();
}

void IdlSettingsDialog::accept()
{
    TypeCatalog::setUserDirectories(directories());
    m_catalog->reload();
    QDialog::accept();
}

QWidget *createTypeCatalogButtons(TypeCatalog *catalog, QWidget *parent)
{
    auto *row = new QWidget(parent);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *folders = new QPushButton(IdlSettingsDialog::tr("IDL Folders..."), row);
    auto *reload = new QPushButton(IdlSettingsDialog::tr("Reload Types"), row);
    reload->setToolTip(IdlSettingsDialog::tr("Parse the IDL folders again"));
    QObject::connect(folders, &QPushButton::clicked, row, [catalog, row] {
        IdlSettingsDialog dialog(catalog, row);
        dialog.exec();
    });
    QObject::connect(reload, &QPushButton::clicked, catalog, &TypeCatalog::reload);
    layout->addStretch(1);
    layout->addWidget(folders);
    layout->addWidget(reload);
    return row;
}

} // namespace Builder
