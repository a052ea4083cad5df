// SPDX-License-Identifier: MIT
#include "systeminfoform.h"

#include "fieldrules.h"
#include "rtscommands.h"

#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QRegularExpressionValidator>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Studio {

namespace {

using Field = RtsDocument::SystemField;

constexpr Field IdFields[] = {Field::Vendor, Field::Name, Field::Version};

} // namespace

SystemInfoForm::SystemInfoForm(RtsDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_abstract(new QPlainTextEdit(this))
    , m_systemId(new QLabel(this))
    , m_dates(new QLabel(this))
{
    auto *form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    addIdRow(form, Field::Vendor, tr("V&endor:"));
    addIdRow(form, Field::Name, tr("&System name:"));
    addIdRow(form, Field::Version, tr("&Version:"));
    m_abstract->setPlaceholderText(tr("(none)"));
    m_abstract->setTabChangesFocus(true);
    m_abstract->setMaximumHeight(m_abstract->fontMetrics().lineSpacing() * 6);
    form->addRow(tr("&Abstract:"), m_abstract);
    m_systemId->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_dates->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(tr("System id:"), m_systemId);
    form->addRow(tr("Dates:"), m_dates);

    connect(m_abstract, &QPlainTextEdit::textChanged, this, [this] {
        if (!m_updating)
            userEdited(Field::Abstract, m_abstract->toPlainText());
    });
    connect(document, &RtsDocument::systemInfoChanged, this, &SystemInfoForm::refresh);
    refresh();
}

QWidget *SystemInfoForm::editor(RtsDocument::SystemField field) const
{
    if (field == Field::Abstract)
        return m_abstract;
    return m_lineEdits.value(int(field));
}

QString SystemInfoForm::problem(RtsDocument::SystemField field) const
{
    const QLabel *message = m_messages.value(int(field));
    return message && !message->isHidden() ? message->text() : QString();
}

void SystemInfoForm::addIdRow(QFormLayout *form, RtsDocument::SystemField field,
                              const QString &label)
{
    // The editor and its problem line share one cell, so the message sits right under it.
    auto *cell = new QWidget(this);
    auto *layout = new QVBoxLayout(cell);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto *edit = new QLineEdit(cell);
    // ':' separates the parts of the system id, so it cannot be part of one; refusing it at the
    // keyboard keeps the id unambiguous.
    edit->setValidator(
        new QRegularExpressionValidator(QRegularExpression(QStringLiteral("[^:]*")), edit));
    connect(edit, &QLineEdit::textEdited, this,
            [this, field](const QString &text) { userEdited(field, text); });
    auto *message = new QLabel(cell);
    message->setWordWrap(true);
    message->setStyleSheet(QStringLiteral("color: #b3261e;"));
    message->hide();
    layout->addWidget(edit);
    layout->addWidget(message);
    m_lineEdits.insert(int(field), edit);
    m_messages.insert(int(field), message);
    form->addRow(label, cell);
    if (auto *buddy = qobject_cast<QLabel *>(form->labelForField(cell)))
        buddy->setBuddy(edit);
}

void SystemInfoForm::userEdited(RtsDocument::SystemField field, const QString &text)
{
    if (!m_document || m_document->systemField(field) == text)
        return;
    m_document->undoStack()->push(new EditSystemInfoCommand(m_document, field, text));
}

void SystemInfoForm::refresh()
{
    if (!m_document)
        return;
    m_updating = true;
    for (Field field : IdFields) {
        QLineEdit *edit = m_lineEdits.value(int(field));
        const QString value = m_document->systemField(field);
        if (edit->text() != value)
            edit->setText(value);
        showProblem(field, FieldRules::systemIdPartProblem(value));
    }
    const QString abstract = m_document->systemField(Field::Abstract);
    if (m_abstract->toPlainText() != abstract)
        m_abstract->setPlainText(abstract);
    m_updating = false;

    const Profile::RtsProfile &profile = m_document->profile();
    m_systemId->setText(
        m_document->hasWellFormedId()
            ? profile.id
            : tr("%1 (not of the form RTSystem:vendor:name:version)").arg(profile.id));
    m_dates->setText(
        tr("created %1, updated %2")
            .arg(profile.creationDate.isEmpty() ? tr("(unknown)") : profile.creationDate,
                 profile.updateDate.isEmpty() ? tr("(unknown)") : profile.updateDate));
}

void SystemInfoForm::showProblem(RtsDocument::SystemField field, const QString &text)
{
    QLabel *message = m_messages.value(int(field));
    QLineEdit *edit = m_lineEdits.value(int(field));
    message->setText(text);
    message->setVisible(!text.isEmpty());
    QPalette palette = this->palette();
    if (!text.isEmpty())
        palette.setColor(QPalette::Base, QColor(255, 228, 225));
    edit->setPalette(palette);
    edit->setToolTip(text);
}

} // namespace Studio
