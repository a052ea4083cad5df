// SPDX-License-Identifier: MIT
#pragma once

#include <QHash>
#include <QWidget>

class QLabel;
class QStackedWidget;
class QTabWidget;

namespace Studio {

class Document;

/**
 * One of the main window's working modes (Builder, System Editor): its own area of document tabs,
 * each tab showing one document's editor. It shows an empty-state hint while no document is open.
 *
 * The perspective does not own documents, only their editor widgets.
 */
class Perspective : public QWidget
{
    Q_OBJECT

public:
    enum class Id { Builder, SystemEditor };

    Perspective(Id id, const QString &title, QWidget *parent = nullptr);

    Id id() const { return m_id; }
    QString title() const { return m_title; }
    /// Text shown while no document is open.
    void setEmptyHint(const QString &text);

    /// Adds a tab showing `editor` (which the perspective now owns) for `document`, and shows it.
    void addDocument(Document *document, QWidget *editor);
    /// Removes the document's tab and deletes its editor.
    void removeDocument(Document *document);
    bool contains(const Document *document) const;

    QList<Document *> documents() const;
    Document *currentDocument() const;
    void setCurrentDocument(Document *document);
    QWidget *editor(const Document *document) const;
    QTabWidget *tabWidget() const { return m_tabs; }

signals:
    void currentDocumentChanged(Studio::Document *document);
    /// The user clicked the tab's close button.
    void closeRequested(Studio::Document *document);

private:
    int indexOf(const Document *document) const;
    Document *documentAt(int index) const;
    void updateTab(Document *document);
    void updateEmptyState();

    Id m_id;
    QString m_title;
    QStackedWidget *m_stack;
    QLabel *m_emptyHint;
    QTabWidget *m_tabs;
    QHash<QWidget *, Document *> m_documentByEditor;
};

} // namespace Studio
