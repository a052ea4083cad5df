// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QTabWidget;

namespace Studio {

class BasicPage;
class RtcDocument;

/**
 * The Builder's editor of one component: the editor pages of an RtcDocument as tabs along the
 * bottom, as RTC Builder arranges them. It starts with the "Basic" page; further pages
 * (Activity, Data Ports, Service Ports, Configuration, …) are added with addPage().
 */
class RtcEditor : public QWidget
{
    Q_OBJECT

public:
    explicit RtcEditor(RtcDocument *document, QWidget *parent = nullptr);

    RtcDocument *document() const { return m_document; }
    BasicPage *basicPage() const { return m_basicPage; }

    /// Adds a page; the editor takes ownership.
    void addPage(QWidget *page, const QString &title);
    QTabWidget *pages() const { return m_pages; }

private:
    RtcDocument *m_document;
    QTabWidget *m_pages;
    BasicPage *m_basicPage;
};

} // namespace Studio
