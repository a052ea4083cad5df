// SPDX-License-Identifier: MIT
#include "buildsettingsdialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace Builder {

BuildSettingsDialog::BuildSettingsDialog(const QString &sdkPrefix, const QString &defaultPrefix,
                                         const QString &buildType, QWidget *parent)
    : QDialog(parent)
    , m_prefix(new QLineEdit(QDir::toNativeSeparators(sdkPrefix), this))
    , m_buildType(new QComboBox(this))
{
    setWindowTitle(tr("Build Settings"));
    auto *form = new QFormLayout(this);
    auto *prefixRow = new QHBoxLayout;
    auto *browse = new QPushButton(tr("&Browse…"), this);
    auto *reset = new QPushButton(tr("&Default"), this);
    reset->setToolTip(QDir::toNativeSeparators(defaultPrefix));
    connect(browse, &QPushButton::clicked, this, &BuildSettingsDialog::browse);
    connect(reset, &QPushButton::clicked, this,
            [this, defaultPrefix] { m_prefix->setText(QDir::toNativeSeparators(defaultPrefix)); });
    prefixRow->addWidget(m_prefix, 1);
    prefixRow->addWidget(browse);
    prefixRow->addWidget(reset);
    m_prefix->setPlaceholderText(tr("(none: CMake searches the system)"));
    m_prefix->setToolTip(tr("Passed to CMake as CMAKE_PREFIX_PATH, so that find_package(OpenRTM) "
                            "finds this SDK"));
    auto *prefixLabel = new QLabel(tr("SDK &prefix:"), this);
    prefixLabel->setBuddy(m_prefix);
    form->addRow(prefixLabel, prefixRow);
    m_buildType->addItem(tr("Release"), QStringLiteral("Release"));
    m_buildType->addItem(tr("Debug"), QStringLiteral("Debug"));
    m_buildType->setCurrentIndex(qMax(0, m_buildType->findData(buildType)));
    form->addRow(tr("Build &type:"), m_buildType);
    auto *box = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(box, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(box, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(box);
    setMinimumWidth(520);
}

QString BuildSettingsDialog::sdkPrefix() const
{
    return QDir::fromNativeSeparators(m_prefix->text().trimmed());
}

QString BuildSettingsDialog::buildType() const
{
    return m_buildType->currentData().toString();
}

void BuildSettingsDialog::browse()
{
    const QString folder
        = QFileDialog::getExistingDirectory(this, tr("SDK Prefix"), m_prefix->text());
    if (!folder.isEmpty())
        m_prefix->setText(QDir::toNativeSeparators(folder));
}

} // namespace Builder
