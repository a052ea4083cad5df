// SPDX-License-Identifier: MIT
#include "regenerationdialog.h"

#include "generatediff.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QTextCursor>
#include <QVBoxLayout>

using Codegen::FileDecision;

namespace Builder {

RegenerationDialog::RegenerationDialog(const QString &relativePath, const QByteArray &existing,
                                       const QByteArray &fresh, QWidget *parent)
    : QDialog(parent)
    , m_diff(new QPlainTextEdit(this))
    , m_applyToAll(new QCheckBox(tr("&Apply to all remaining changed files"), this))
{
    setWindowTitle(tr("Generated File Changed"));
    auto *layout = new QVBoxLayout(this);
    auto *label = new QLabel(tr("<b>%1</b> exists and differs from the newly generated file. "
                                "Lines starting with - are in your file only, + in the new one.")
                                 .arg(relativePath.toHtmlEscaped()),
                             this);
    label->setWordWrap(true);
    layout->addWidget(label);
    m_diff->setReadOnly(true);
    m_diff->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_diff->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    showDiff(unifiedDiff(QString::fromUtf8(existing), QString::fromUtf8(fresh),
                         tr("%1 (existing)").arg(relativePath), tr("%1 (new)").arg(relativePath)));
    layout->addWidget(m_diff, 1);
    layout->addWidget(m_applyToAll);
    auto *box = new QDialogButtonBox(this);
    box->addButton(addChoice(tr("&Keep"), tr("Leave your file as it is"), FileDecision::Keep),
                   QDialogButtonBox::RejectRole);
    box->addButton(addChoice(tr("&Merge"),
                             tr("Back your file up, then refresh only its generated regions"),
                             FileDecision::Merge),
                   QDialogButtonBox::AcceptRole);
    box->addButton(addChoice(tr("&Overwrite"),
                             tr("Back your file up, then replace it with the new file"),
                             FileDecision::Overwrite),
                   QDialogButtonBox::AcceptRole);
    button(FileDecision::Merge)->setDefault(true);
    layout->addWidget(box);
    resize(760, 520);
}

QPushButton *RegenerationDialog::addChoice(const QString &text, const QString &toolTip,
                                           FileDecision decision)
{
    auto *button = new QPushButton(text, this);
    button->setToolTip(toolTip);
    m_buttons.append({decision, button});
    connect(button, &QPushButton::clicked, this, [this, decision] {
        m_decision = decision;
        // Keep is the safe answer, so it also stands for closing the dialog.
        if (decision == FileDecision::Keep)
            reject();
        else
            accept();
    });
    return button;
}

QPushButton *RegenerationDialog::button(FileDecision decision) const
{
    for (const auto &entry : m_buttons) {
        if (entry.first == decision)
            return entry.second;
    }
    return nullptr;
}

FileChoice RegenerationDialog::choice() const
{
    return {m_decision, m_applyToAll->isChecked()};
}

void RegenerationDialog::showDiff(const QString &diff)
{
    m_diff->setPlainText(diff.isEmpty() ? tr("(only line endings differ)") : diff);
    // Colour removed and added lines like a diff viewer; headers and context stay plain.
    for (QTextBlock block = m_diff->document()->begin(); block.isValid(); block = block.next()) {
        const QString text = block.text();
        QColor background;
        if (block.blockNumber() < 2) // the --- / +++ file names
            continue;
        if (text.startsWith(QLatin1String("@@")))
            background = QColor(0xe8, 0xe8, 0xf8);
        else if (text.startsWith(QLatin1Char('-')))
            background = QColor(0xfb, 0xe0, 0xe0);
        else if (text.startsWith(QLatin1Char('+')))
            background = QColor(0xdf, 0xf5, 0xdf);
        if (!background.isValid())
            continue;
        QTextCursor cursor(block);
        QTextBlockFormat format;
        format.setBackground(background);
        cursor.setBlockFormat(format);
    }
}

} // namespace Builder
