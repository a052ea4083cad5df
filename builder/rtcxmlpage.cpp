// SPDX-License-Identifier: MIT
#include "rtcxmlpage.h"

#include "componentcommands.h"
#include "profilechanges.h"
#include "rtcxml.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTextBlock>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

const QString FileName = QStringLiteral("RTC.xml");

} // namespace

RtcXmlPage::RtcXmlPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_text(new QPlainTextEdit(this))
    , m_problems(new QListWidget(this))
    , m_pendingBox(new QWidget(this))
    , m_pendingLabel(new QLabel(m_pendingBox))
    , m_status(new QLabel(this))
{
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_text->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_problems->setObjectName(QStringLiteral("problems"));
    m_problems->setMaximumHeight(m_problems->fontMetrics().lineSpacing() * 6 + 8);
    m_problems->hide();
    connect(m_problems, &QListWidget::itemActivated, this, [this](QListWidgetItem *item) {
        jumpTo(item->data(Qt::UserRole).toInt(), item->data(Qt::UserRole + 1).toInt());
    });

    auto *applyButton = new QPushButton(tr("&Apply"), this);
    auto *revertButton = new QPushButton(tr("Re&vert"), this);
    applyButton->setToolTip(tr("Read the XML and show what it changes"));
    revertButton->setToolTip(tr("Show the component's XML again, dropping your edits"));
    connect(applyButton, &QPushButton::clicked, this, &RtcXmlPage::apply);
    connect(revertButton, &QPushButton::clicked, this, &RtcXmlPage::revert);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(applyButton);
    buttons->addWidget(revertButton);
    buttons->addWidget(m_status, 1);

    auto *confirmButton = new QPushButton(tr("&Confirm"), m_pendingBox);
    auto *cancelButton = new QPushButton(tr("Ca&ncel"), m_pendingBox);
    connect(confirmButton, &QPushButton::clicked, this, &RtcXmlPage::confirm);
    connect(cancelButton, &QPushButton::clicked, this, &RtcXmlPage::cancel);
    m_pendingLabel->setWordWrap(true);
    m_pendingLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *pendingLayout = new QVBoxLayout(m_pendingBox);
    pendingLayout->addWidget(m_pendingLabel);
    auto *pendingButtons = new QHBoxLayout;
    pendingButtons->addWidget(confirmButton);
    pendingButtons->addWidget(cancelButton);
    pendingButtons->addStretch(1);
    pendingLayout->addLayout(pendingButtons);
    m_pendingBox->setStyleSheet(QStringLiteral("QWidget#pending { background: #fff8e1; }"));
    m_pendingBox->setObjectName(QStringLiteral("pending"));
    m_pendingBox->setAttribute(Qt::WA_StyledBackground);
    m_pendingBox->hide();

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_problems);
    layout->addWidget(m_pendingBox);

    connect(model, &ComponentModel::changed, this, &RtcXmlPage::followModel);
    connect(m_text, &QPlainTextEdit::textChanged, this, [this] {
        if (m_pending)
            cancel();
    });
    showText();
}

void RtcXmlPage::followModel()
{
    if (isEdited())
        return;
    // Writing the XML on every keystroke elsewhere is wasted while the page is hidden.
    if (isVisible())
        showText();
    else
        m_stale = true;
}

void RtcXmlPage::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    if (m_stale && !isEdited())
        showText();
}

void RtcXmlPage::showText()
{
    if (!m_model)
        return;
    m_stale = false;
    m_shownText = QString::fromUtf8(Profile::writeRtcXml(m_model->profile()));
    const QSignalBlocker blocker(m_text);
    m_text->setPlainText(m_shownText);
}

bool RtcXmlPage::isEdited() const
{
    return m_text->toPlainText() != m_shownText;
}

bool RtcXmlPage::apply()
{
    if (!m_model)
        return false;
    Profile::Diagnostics diagnostics;
    auto profile = Profile::readRtcXml(m_text->toPlainText().toUtf8(), FileName, &diagnostics);
    if (!profile || Profile::hasErrors(diagnostics)) {
        showProblems(diagnostics);
        m_status->setText(tr("The XML has errors; the component is unchanged."));
        return false;
    }
    // The writer always writes the current format version; that is no change of the component.
    if (profile->version == Profile::RtcProfile::CurrentVersion)
        profile->version = m_model->profile().version;
    showProblems(diagnostics);
    m_pendingChanges = describeChanges(m_model->profile(), *profile);
    if (m_pendingChanges.isEmpty()) {
        m_status->setText(tr("No changes."));
        return true;
    }
    m_pending = profile;
    m_pendingLabel->setText(tr("Applying changes the component:\n• %1")
                                .arg(m_pendingChanges.join(QStringLiteral("\n• "))));
    m_pendingBox->show();
    m_status->setText(tr("Confirm to take the changes."));
    return true;
}

void RtcXmlPage::confirm()
{
    if (!m_pending || !m_model)
        return;
    const Profile::RtcProfile profile = *m_pending;
    cancel();
    m_undoStack->push(new ReplaceProfileCommand(m_model, profile));
    showText();
    m_status->setText(tr("Applied."));
}

void RtcXmlPage::cancel()
{
    m_pending.reset();
    m_pendingChanges.clear();
    m_pendingBox->hide();
}

void RtcXmlPage::revert()
{
    cancel();
    showProblems({});
    showText();
    m_status->clear();
}

QStringList RtcXmlPage::problems() const
{
    QStringList result;
    for (int i = 0; i < m_problems->count(); ++i)
        result << m_problems->item(i)->text();
    return result;
}

QStringList RtcXmlPage::pendingChanges() const
{
    return m_pending ? m_pendingChanges : QStringList();
}

void RtcXmlPage::showProblems(const Profile::Diagnostics &diagnostics)
{
    m_problems->clear();
    for (const Profile::Diagnostic &d : diagnostics) {
        auto *item = new QListWidgetItem(d.toString(), m_problems);
        item->setData(Qt::UserRole, d.line);
        item->setData(Qt::UserRole + 1, d.column);
    }
    m_problems->setVisible(!diagnostics.isEmpty());
    if (!diagnostics.isEmpty())
        jumpTo(diagnostics.first().line, diagnostics.first().column);
}

void RtcXmlPage::jumpTo(int line, int column)
{
    if (line <= 0)
        return;
    const QTextBlock block = m_text->document()->findBlockByNumber(line - 1);
    if (!block.isValid())
        return;
    QTextCursor cursor(block);
    cursor.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor,
                        qBound(0, column - 1, block.length() - 1));
    m_text->setTextCursor(cursor);
    m_text->centerCursor();
}

} // namespace Builder
