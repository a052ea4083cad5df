// SPDX-License-Identifier: MIT
#include "idlsettingsdialog.h"

#include "typecatalog.h"

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
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
    m_catalog->startReload();
    QDialog::accept();
}

namespace {

/// How long a scan runs before its progress is shown (short scans do not flicker).
constexpr int ScanProgressDelayMs = 250;

/// A bar, the file being read and Cancel, shown while the catalog reads its folders.
QWidget *createScanProgress(TypeCatalog *catalog, QWidget *parent)
{
    auto *strip = new QWidget(parent);
    strip->setObjectName(QStringLiteral("idlScan"));
    auto *layout = new QHBoxLayout(strip);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *label = new QLabel(strip);
    label->setObjectName(QStringLiteral("idlScanLabel"));
    auto *bar = new QProgressBar(strip);
    bar->setObjectName(QStringLiteral("idlScanProgress"));
    bar->setRange(0, 0);
    bar->setMaximumWidth(160);
    auto *cancel = new QPushButton(IdlSettingsDialog::tr("Cancel"), strip);
    cancel->setObjectName(QStringLiteral("idlScanCancel"));
    cancel->setToolTip(IdlSettingsDialog::tr("Stop reading the IDL folders and keep the types read before"));
    layout->addWidget(label, 1);
    layout->addWidget(bar);
    layout->addWidget(cancel);
    strip->setVisible(false);

    auto *delay = new QTimer(strip);
    delay->setSingleShot(true);
    delay->setInterval(ScanProgressDelayMs);
    QObject::connect(delay, &QTimer::timeout, strip, [strip, catalog] { strip->setVisible(catalog->isLoading()); });
    QObject::connect(catalog, &TypeCatalog::loadingStarted, strip, [label, bar, delay] {
        label->setText(IdlSettingsDialog::tr("Reading the IDL folders…"));
        bar->setRange(0, 0);
        delay->start();
    });
    QObject::connect(catalog, &TypeCatalog::loadingProgress, strip,
                     [label, bar](int done, int total, const QString &file) {
                         bar->setRange(0, total);
                         bar->setValue(done);
                         label->setText(IdlSettingsDialog::tr("Reading %1 (%2 of %3)")
                                            .arg(QFileInfo(file).fileName())
                                            .arg(done + 1)
                                            .arg(total));
                     });
    QObject::connect(catalog, &TypeCatalog::loadingFinished, strip, [strip, delay] {
        delay->stop();
        strip->setVisible(false);
    });
    QObject::connect(cancel, &QPushButton::clicked, catalog, &TypeCatalog::cancelReload);
    if (catalog->isLoading())
        delay->start();
    return strip;
}

} // namespace

QWidget *createTypeCatalogButtons(TypeCatalog *catalog, QWidget *parent)
{
    auto *row = new QWidget(parent);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *folders = new QPushButton(IdlSettingsDialog::tr("IDL Folders..."), row);
    auto *reload = new QPushButton(IdlSettingsDialog::tr("Reload Types"), row);
    reload->setObjectName(QStringLiteral("reloadTypes"));
    reload->setToolTip(IdlSettingsDialog::tr("Parse the IDL folders again"));
    QObject::connect(folders, &QPushButton::clicked, row, [catalog, row] {
        IdlSettingsDialog dialog(catalog, row);
        dialog.exec();
    });
    QObject::connect(reload, &QPushButton::clicked, catalog, &TypeCatalog::startReload);
    layout->addWidget(createScanProgress(catalog, row), 1);
    layout->addWidget(folders);
    layout->addWidget(reload);
    return row;
}

} // namespace Builder
