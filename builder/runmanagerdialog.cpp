// SPDX-License-Identifier: MIT
#include "runmanagerdialog.h"

#include "modulerun.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace Builder {

RunManagerDialog::RunManagerDialog(const QStringList &addresses, const QString &modulePath,
                                   QWidget *parent)
    : QDialog(parent)
    , m_address(new QComboBox(this))
{
    setWindowTitle(tr("Run in Manager"));
    setObjectName(QStringLiteral("runManagerDialog"));
    m_address->setObjectName(QStringLiteral("managerAddressBox"));
    m_address->setEditable(true);
    m_address->addItems(addresses);
    m_address->setToolTip(tr("host:port of a running manager (rtmanager or rtcd), port 2810 "
                             "when left out"));
    auto *module = new QLabel(QDir::toNativeSeparators(modulePath), this);
    module->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_runButton = buttons->addButton(tr("&Run"), QDialogButtonBox::AcceptRole);
    m_runButton->setObjectName(QStringLiteral("runButton"));
    m_runButton->setDefault(true);
    connect(buttons, &QDialogButtonBox::accepted, this, &RunManagerDialog::run);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // An address that cannot be one is not offered to the manager.
    connect(m_address, &QComboBox::currentTextChanged, this, [this](const QString &text) {
        m_runButton->setEnabled(!ModuleRun::managerLocation(text).isEmpty());
    });

    auto *form = new QFormLayout;
    form->addRow(tr("&Manager:"), m_address);
    form->addRow(tr("Module:"), module);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    m_runButton->setEnabled(!ModuleRun::managerLocation(address()).isEmpty());
}

QString RunManagerDialog::address() const
{
    return m_address->currentText().trimmed();
}

void RunManagerDialog::setAddress(const QString &address)
{
    m_address->setCurrentText(address);
}

void RunManagerDialog::run()
{
    emit runRequested(address());
    accept();
}

} // namespace Builder
