// SPDX-License-Identifier: MIT
#include "openingprogress.h"

#include "documentcontroller.h"

#include <QApplication>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>

namespace Studio {

namespace {

/// How long a file is read before the bar appears (quick opens do not flicker).
constexpr int ShowDelayMs = 300;

bool isUserInput(QEvent::Type type)
{
    switch (type) {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
    case QEvent::Wheel:
    case QEvent::ContextMenu:
    case QEvent::Drop:
    case QEvent::Close:
        return true;
    default:
        return false;
    }
}

} // namespace

OpeningProgress::OpeningProgress(DocumentController *controller, QWidget *parent)
    : QWidget(parent)
    , m_label(new QLabel(this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_delay(new QTimer(this))
{
    setObjectName(QStringLiteral("openingProgress"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *bar = new QProgressBar(this);
    bar->setRange(0, 0);
    bar->setMaximumWidth(120);
    m_cancel->setObjectName(QStringLiteral("cancelOpening"));
    m_cancel->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    m_cancel->setToolTip(tr("Stop opening this file; open documents stay as they are"));
    layout->addWidget(m_label);
    layout->addWidget(bar);
    layout->addWidget(m_cancel);
    setVisible(false);
    m_delay->setSingleShot(true);
    m_delay->setInterval(ShowDelayMs);
    connect(m_delay, &QTimer::timeout, this, [this] { setVisible(m_blocking); });
    connect(controller, &DocumentController::openingStarted, this, &OpeningProgress::started);
    connect(controller, &DocumentController::openingFinished, this, &OpeningProgress::finished);
    connect(m_cancel, &QPushButton::clicked, controller, &DocumentController::cancelOpening);
}

OpeningProgress::~OpeningProgress()
{
    if (m_blocking)
        qApp->removeEventFilter(this);
}

void OpeningProgress::started(const QString &filePath)
{
    m_label->setText(tr("Opening %1…").arg(QFileInfo(filePath).fileName()));
    if (!m_blocking)
        qApp->installEventFilter(this);
    m_blocking = true;
    m_delay->start();
}

void OpeningProgress::finished()
{
    if (m_blocking)
        qApp->removeEventFilter(this);
    m_blocking = false;
    m_delay->stop();
    setVisible(false);
}

bool OpeningProgress::eventFilter(QObject *watched, QEvent *event)
{
    switch (event->type()) {
    case QEvent::Shortcut:
        // Actions get their shortcuts as events of their own.
        return true;
    case QEvent::ShortcutOverride:
        // "Taken": the key then goes to the focus widget as input, refused below.
        event->accept();
        return true;
    default:
        break;
    }
    // Input reaches widgets (not their windows) here; only Cancel may take it while a file is read.
    auto *widget = qobject_cast<QWidget *>(watched);
    if (!widget || !isUserInput(event->type()) || widget == m_cancel)
        return false;
    event->ignore();
    return true;
}

} // namespace Studio
