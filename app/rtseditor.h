// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QSplitter;
class QTreeView;

namespace Studio {

class RtsDocument;
class SystemInfoForm;
class SystemOutlineModel;

/**
 * The System Editor's editor of one system: the outline of its components and connectors on
 * the left, the system info form on the right. Both only listen to the RtsDocument; edits go
 * through its undo stack.
 */
class RtsEditor : public QWidget
{
    Q_OBJECT

public:
    explicit RtsEditor(RtsDocument *document, QWidget *parent = nullptr);

    RtsDocument *document() const { return m_document; }
    SystemOutlineModel *outlineModel() const { return m_outlineModel; }
    QTreeView *outlineView() const { return m_outlineView; }
    SystemInfoForm *systemInfoForm() const { return m_systemInfo; }

private:
    RtsDocument *m_document;
    SystemOutlineModel *m_outlineModel;
    QTreeView *m_outlineView;
    SystemInfoForm *m_systemInfo;
    QSplitter *m_splitter;
};

} // namespace Studio
