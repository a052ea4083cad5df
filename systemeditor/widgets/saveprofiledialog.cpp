// SPDX-License-Identifier: MIT
#include "saveprofiledialog.h"

#include "systemcommands.h"
#include "systemmodel.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace SystemEditor {

SaveProfileDialog::SaveProfileDialog(const SystemProfileInfo &info, const QStringList &components,
                                     QWidget *parent)
    : QDialog(parent)
    , m_original(info)
    , m_vendor(addLine(QStringLiteral("vendorEdit"), info.vendor))
    , m_name(addLine(QStringLiteral("systemNameEdit"), info.systemName))
    , m_version(addLine(QStringLiteral("versionEdit"), info.version))
    , m_abstract(new QPlainTextEdit(info.abstract.value_or(QString()), this))
    , m_required(new QListWidget(this))
    , m_problems(new QLabel(this))
    , m_buttons(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this))
{
    setWindowTitle(tr("System Profile Information"));
    m_abstract->setObjectName(QStringLiteral("abstractEdit"));
    m_abstract->setTabChangesFocus(true);
    m_required->setObjectName(QStringLiteral("requiredList"));
    for (const QString &component : components) {
        auto *item = new QListWidgetItem(component, m_required);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        item->setCheckState(info.requiredComponents.contains(component) ? Qt::Checked
                                                                          : Qt::Unchecked);
    }
    m_problems->setObjectName(QStringLiteral("problemsLabel"));
    m_problems->setWordWrap(true);
    m_problems->setStyleSheet(QStringLiteral("color: #b00020"));

    auto *form = new QFormLayout;
    form->addRow(tr("&Vendor:"), m_vendor);
    form->addRow(tr("System &name:"), m_name);
    form->addRow(tr("V&ersion:"), m_version);
    form->addRow(tr("&Abstract:"), m_abstract);
    form->addRow(tr("&Required components:"), m_required);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problems);
    layout->addWidget(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    for (QLineEdit *edit : {m_vendor, m_name, m_version})
        connect(edit, &QLineEdit::textChanged, this, &SaveProfileDialog::updateProblems);
    updateProblems();
}

QLineEdit *SaveProfileDialog::addLine(const QString &objectName, const QString &text)
{
    auto *edit = new QLineEdit(text, this);
    edit->setObjectName(objectName);
    return edit;
}

SystemProfileInfo SaveProfileDialog::info() const
{
    SystemProfileInfo result = m_original;
    result.vendor = m_vendor->text();
    result.systemName = m_name->text();
    result.version = m_version->text();
    const QString abstract = m_abstract->toPlainText();
    // An absent abstract stays absent unless text was typed, so an unedited file saves as read.
    result.abstract = abstract.isEmpty() && !m_original.abstract ? std::nullopt
                                                                  : std::optional(abstract);
    result.requiredComponents.clear();
    for (int row = 0; row < m_required->count(); ++row) {
        const QListWidgetItem *item = m_required->item(row);
        if (item->checkState() == Qt::Checked)
            result.requiredComponents.insert(item->text());
    }
    return result;
}

bool SaveProfileDialog::setRequired(const QString &instanceName, bool required)
{
    const QList<QListWidgetItem *> items = m_required->findItems(instanceName, Qt::MatchExactly);
    if (items.isEmpty())
        return false;
    items.first()->setCheckState(required ? Qt::Checked : Qt::Unchecked);
    return true;
}

QUndoCommand *SaveProfileDialog::applyCommand(SystemModel *model, const SystemProfileInfo &info)
{
    // An unchanged answer leaves even a malformed id from the file as it was read.
    if (info == model->systemInfo())
        return nullptr;
    return new SetSystemInfoCommand(model, info, -1, tr("Edit system profile information"));
}

void SaveProfileDialog::updateProblems()
{
    const QStringList problems = info().problems();
    m_problems->setText(problems.join(QLatin1Char('\n')));
    m_problems->setVisible(!problems.isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(problems.isEmpty());
}

} // namespace SystemEditor
