// SPDX-License-Identifier: MIT
#include "rtceditor.h"

#include "basicpage.h"
#include "rtcdocument.h"

#include <QTabWidget>
#include <QVBoxLayout>

namespace Studio {

RtcEditor::RtcEditor(RtcDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_pages(new QTabWidget(this))
    , m_basicPage(new BasicPage(document))
{
    m_pages->setTabPosition(QTabWidget::South);
    m_pages->setDocumentMode(true);
    addPage(m_basicPage, tr("Basic"));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_pages);
}

void RtcEditor::addPage(QWidget *page, const QString &title)
{
    m_pages->addTab(page, title);
}

} // namespace Studio
