// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "profileio.h"

#include <QList>
#include <QObject>
#include <QStringList>

class QEventLoop;

namespace SystemEditor {
class OnlineSession;
}

namespace Studio {

class Document;
class OnlineDocument;
class RecentFiles;
class RtcDocument;
class RtsDocument;
class UserPrompts;

/**
 * The open documents and the file operations on them: new, open, save, save as, close, with
 * the questions these ask (through UserPrompts) and the problems they report.
 *
 * It owns the documents; windows learn about them through documentAdded() and
 * documentClosing() and never create or delete documents themselves.
 */
class DocumentController : public QObject
{
    Q_OBJECT

public:
    /// `prompts` must outlive the controller (or be replaced with setPrompts()).
    explicit DocumentController(UserPrompts *prompts, QObject *parent = nullptr);
    ~DocumentController() override;

    void setPrompts(UserPrompts *prompts) { m_prompts = prompts; }
    RecentFiles *recentFiles() const { return m_recentFiles; }

    QList<Document *> documents() const { return m_documents; }
    /// The open document of this file (compared as absolute, clean paths), or null.
    Document *findByPath(const QString &path) const;

    /// A new component with RTC Builder's defaults, untitled and unmodified.
    RtcDocument *newComponent();
    /// A new empty system, untitled and unmodified.
    RtsDocument *newSystem();
    /// A new, empty online diagram whose remote calls go through `session`.
    OnlineDocument *newOnlineDiagram(SystemEditor::OnlineSession *session);

    /**
     * Opens the files; a file that is open already is not read again, its document is returned.
     * Files that fail to load change nothing; all their diagnostics are reported together.
     * Returns the documents of the files that could be opened.
     *
     * Each file is read on a worker thread. One that takes longer than a glance is announced
     * with openingStarted() and the event loop runs until it is read or cancelOpening() gives up
     * on it (and on the files after it).
     */
    QList<Document *> openFiles(const QStringList &paths);
    /// Asks for files and opens them.
    QList<Document *> openWithDialog();

    /// Saves to the document's file, or asks for one when untitled. False on failure or cancel.
    bool save(Document *document);
    /// Asks for a file name and saves there (format by extension).
    bool saveAs(Document *document);
    /// Saves to `path` (format by extension); on failure the document stays as it was. An
    /// online diagram saves its live system there, asynchronously (the result is reported).
    bool saveAs(Document *document, const QString &path);

    /**
     * For a system: asks where to export its diagram (.png or .svg) and writes it; a system
     * without saved positions is drawn auto-laid-out, the document unchanged. False on cancel,
     * failure (reported) or for a component.
     */
    bool exportDiagram(Document *document);

    /// Closes a document, asking about unsaved changes. False when the user cancelled or the
    /// requested save failed; the document is then still open.
    bool close(Document *document);
    /// Asks about every modified document, then closes all. False (nothing closed) on cancel.
    bool closeAll();

    /// Where the file dialogs start: the folder of the last opened or saved file.
    QString lastDirectory() const;

public slots:
    /// Stops waiting for the file being read; the open documents stay as they were.
    void cancelOpening();

signals:
    void documentAdded(Studio::Document *document);
    /// An already open document was asked for again (e.g. opened a second time): show it.
    void activationRequested(Studio::Document *document);
    /// The document is about to be deleted; drop every reference to it.
    void documentClosing(Studio::Document *document);
    /// Diagnostics of a failed operation, or warnings of a successful load.
    void problemsReported(const QString &summary, const Profile::Diagnostics &diagnostics);
    void statusMessage(const QString &message);
    /// A file takes a moment to read; openingFinished() follows in any case.
    void openingStarted(const QString &filePath);
    void openingFinished();

private:
    Document *openOne(const QString &path, Profile::Diagnostics *failures, bool *cancelled);
    std::optional<Profile::LoadedProfile> readProfile(const QString &path,
                                                      Profile::Diagnostics *diagnostics,
                                                      bool *cancelled);
    void addDocument(Document *document);
    void reportLiveSave(const QString &path, const QString &error, const QStringList &warnings);
    bool saveTo(Document *document, const QString &path, bool keepFormat);
    /// For a system: asks its profile information and applies it; false when cancelled.
    bool confirmSystemProfile(Document *document);
    bool confirmClose(Document *document);
    void discard(Document *document);
    void rememberDirectory(const QString &filePath);
    QString suggestedSavePath(const Document *document) const;

    UserPrompts *m_prompts;
    RecentFiles *m_recentFiles;
    QList<Document *> m_documents;
    int m_newComponents = 0;
    int m_newSystems = 0;
    int m_newOnlineDiagrams = 0;
    QEventLoop *m_openingLoop = nullptr; ///< runs while a slow file is read
    bool m_openingCancelled = false;
};

} // namespace Studio
