// SPDX-License-Identifier: MIT
#include "rtseditor.h"

#include "rtsdocument.h"
#include "systeminfoform.h"
#include "systemoutlinemodel.h"

#include <QGroupBox>
#include <QHeaderView>
#include <QScrollArea>
#include <QSplitter>
#include <QTreeView>
#include <QVBoxLayout>

namespace Studio {

RtsEditor::RtsEditor(RtsDocument *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_outlineModel(new SystemOutlineModel(document, this))
    , m_outlineView(new QTreeView)
    , m_systemInfo(new SystemInfoForm(document))
    , m_splitter(new QSplitter(Qt::Horizontal, this))
{
    m_outlineView->setModel(m_outlineModel);
    m_outlineView->setUniformRowHeights(true);
    m_outlineView->setAlternatingRowColors(true);
    m_outlineView->header()->setSectionResizeMode(SystemOutlineModel::NameColumn,
                                                  QHeaderView::ResizeToContents);
    m_outlineView->expandAll();

    auto *systemBox = new QGroupBox(tr("System"));
    auto *boxLayout = new QVBoxLayout(systemBox);
    boxLayout->addWidget(m_systemInfo);
    systemBox->setMaximumWidth(720);
    auto *right = new QWidget;
    auto *rightLayout = new QVBoxLayout(right);
    rightLayout->addWidget(systemBox);
    rightLayout->addStretch(1);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(right);

    m_splitter->addWidget(m_outlineView);
    m_splitter->addWidget(scroll);
    m_splitter->setStretchFactor(0, 2);
    m_splitter->setStretchFactor(1, 3);
    m_splitter->setSizes({460, 740});

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);
}

} // namespace Studio
