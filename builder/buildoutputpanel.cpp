// SPDX-License-Identifier: MIT
#include "buildoutputpanel.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QScrollBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace Builder {

namespace {

/// Lines kept in the view: a long build must not grow the document without end.
constexpr int maximumLines = 20000;

} // namespace

BuildOutputPanel::BuildOutputPanel(QWidget *parent)
    : QWidget(parent)
    , m_output(new QPlainTextEdit(this))
    , m_progress(new QProgressBar(this))
    , m_status(new QLabel(this))
    , m_cancel(new QToolButton(this))
{
    m_output->setObjectName(QStringLiteral("buildOutput"));
    m_output->setReadOnly(true);
    m_output->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_output->setMaximumBlockCount(maximumLines);
    m_output->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_progress->setObjectName(QStringLiteral("buildProgress"));
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_progress->setMaximumWidth(220);
    m_status->setObjectName(QStringLiteral("buildStatus"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_cancel->setObjectName(QStringLiteral("cancelBuildButton"));
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop the build"));
    m_cancel->setEnabled(false);
    connect(m_cancel, &QToolButton::clicked, this, &BuildOutputPanel::cancelRequested);

    auto *header = new QHBoxLayout;
    header->addWidget(new QLabel(tr("Build output"), this));
    header->addWidget(m_status, 1);
    header->addWidget(m_progress);
    header->addWidget(m_cancel);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 2, 0, 0);
    layout->addLayout(header);
    layout->addWidget(m_output, 1);
}

void BuildOutputPanel::startBuild(const QString &status)
{
    m_running = true;
    m_output->clear();
    m_status->setText(status);
    m_progress->setRange(0, 0);
    m_cancel->setEnabled(true);
}

void BuildOutputPanel::appendLine(const QString &line)
{
    // Follow the output only while the user has not scrolled up to read.
    QScrollBar *bar = m_output->verticalScrollBar();
    const bool atEnd = bar->value() == bar->maximum();
    m_output->appendPlainText(line);
    if (atEnd)
        bar->setValue(bar->maximum());
}

void BuildOutputPanel::setProgress(int done, int total)
{
    if (total <= 0) {
        m_progress->setRange(0, 0);
        return;
    }
    m_progress->setRange(0, total);
    m_progress->setValue(qBound(0, done, total));
}

void BuildOutputPanel::finishBuild(bool ok, const QString &status)
{
    m_running = false;
    m_status->setText(status);
    m_progress->setRange(0, 1);
    m_progress->setValue(ok ? 1 : 0);
    m_cancel->setEnabled(false);
}

QString BuildOutputPanel::text() const
{
    return m_output->toPlainText();
}

QString BuildOutputPanel::status() const
{
    return m_status->text();
}

} // namespace Builder
