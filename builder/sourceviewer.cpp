// SPDX-License-Identifier: MIT
#include "sourceviewer.h"

#include <QDesktopServices>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QTextBlock>
#include <QToolButton>
#include <QUrl>
#include <QVBoxLayout>

namespace Builder {

namespace {

// Larger files are not what a generated component or a compiler message points into.
constexpr qint64 MaxViewedSize = 8 * 1024 * 1024;

QToolButton *toolButton(const QString &text, const QString &name, QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setText(text);
    button->setObjectName(name);
    button->setAutoRaise(true);
    return button;
}

} // namespace

SourceViewer::SourceViewer(QWidget *parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_editor(new QPlainTextEdit(this))
{
    m_title->setObjectName(QStringLiteral("sourceTitle"));
    m_title->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_editor->setObjectName(QStringLiteral("sourceText"));
    m_editor->setReadOnly(true);
    // Keyboard navigation and selection still work in a read-only view.
    m_editor->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_editor->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_editor->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));

    QToolButton *external
        = toolButton(tr("Open Externally"), QStringLiteral("openExternally"), this);
    external->setToolTip(tr("Open the file in the desktop's editor"));
    QToolButton *close = toolButton(tr("Close"), QStringLiteral("closeSource"), this);
    connect(external, &QToolButton::clicked, this, &SourceViewer::openExternally);
    connect(close, &QToolButton::clicked, this, [this] {
        hide();
        emit closed();
    });

    auto *header = new QHBoxLayout;
    header->addWidget(m_title, 1);
    header->addWidget(external);
    header->addWidget(close);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(header);
    layout->addWidget(m_editor);
}

bool SourceViewer::isTextFile(const QString &path)
{
    QFile file(path);
    if (file.size() > MaxViewedSize || !file.open(QIODevice::ReadOnly))
        return false;
    return !file.read(8192).contains('\0');
}

bool SourceViewer::openFile(const QString &path, int line, int column)
{
    if (!isTextFile(path))
        return false;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return false;
    m_path = path;
    m_editor->setPlainText(QString::fromUtf8(file.readAll()));
    const QTextBlock block = m_editor->document()->findBlockByNumber(qMax(0, line - 1));
    QTextCursor cursor(block);
    if (column > 1)
        cursor.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor,
                            qMin(column - 1, block.length() - 1));
    m_editor->setTextCursor(cursor);
    QList<QTextEdit::ExtraSelection> selections;
    if (line > 0) {
        QTextEdit::ExtraSelection current;
        current.format.setBackground(palette().color(QPalette::Highlight).lighter(170));
        current.format.setProperty(QTextFormat::FullWidthSelection, true);
        current.cursor = QTextCursor(block);
        selections << current;
    }
    m_editor->setExtraSelections(selections);
    m_editor->centerCursor();
    const QString name = QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath());
    m_title->setText(line > 0 ? tr("%1, line %2").arg(name).arg(line) : name);
    return true;
}

int SourceViewer::currentLine() const
{
    return m_editor->textCursor().blockNumber() + 1;
}

void SourceViewer::openExternally()
{
    if (!m_path.isEmpty())
        QDesktopServices::openUrl(QUrl::fromLocalFile(QFileInfo(m_path).absoluteFilePath()));
}

} // namespace Builder
