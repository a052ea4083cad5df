// SPDX-License-Identifier: MIT
#include "documentcontroller.h"

#include "diagramexport.h"
#include "documentloader.h"
#include "onlinedocument.h"
#include "recentfiles.h"
#include "rtcdocument.h"
#include "rtsdocument.h"
#include "saveprofiledialog.h"
#include "systemmodel.h"
#include "userprompts.h"

#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QSettings>
#include <QThread>
#include <QUndoStack>

namespace Studio {

namespace {

const QString LastDirectoryKey = QStringLiteral("lastDirectory");

/// Files read within this time open without any sign of waiting.
constexpr unsigned long QuickReadMs = 100;

QString canonicalPath(const QString &path)
{
    return QDir::cleanPath(QFileInfo(path).absoluteFilePath());
}

} // namespace

DocumentController::DocumentController(UserPrompts *prompts, QObject *parent)
    : QObject(parent)
    , m_prompts(prompts)
    , m_recentFiles(new RecentFiles(QStringLiteral("recentFiles"), this))
{ }

DocumentController::~DocumentController()
{
    // Windows may still hold editors of these documents; tell them before the documents go.
    const QList<Document *> documents = m_documents;
    for (Document *document : documents)
        discard(document);
}

Document *DocumentController::findByPath(const QString &path) const
{
    const QString wanted = canonicalPath(path);
    for (Document *document : m_documents) {
        if (!document->isUntitled() && canonicalPath(document->filePath()) == wanted)
            return document;
    }
    return nullptr;
}

RtcDocument *DocumentController::newComponent()
{
    auto *document = new RtcDocument(Profile::RtcProfile::createDefault(), this);
    document->setUntitledName(tr("New Component %1").arg(++m_newComponents));
    addDocument(document);
    return document;
}

RtsDocument *DocumentController::newSystem()
{
    ++m_newSystems;
    Profile::RtsProfile profile = Profile::RtsProfile::createNew(
        QStringLiteral("VenderName"), QStringLiteral("NewSystem%1").arg(m_newSystems),
        QStringLiteral("1.0"));
    auto *document = new RtsDocument(std::move(profile), this);
    document->setUntitledName(tr("New System %1").arg(m_newSystems));
    addDocument(document);
    return document;
}

OnlineDocument *DocumentController::newOnlineDiagram(SystemEditor::OnlineSession *session)
{
    auto *document = new OnlineDocument(session, this);
    document->setUntitledName(tr("Online Diagram %1").arg(++m_newOnlineDiagrams));
    connect(document, &OnlineDocument::liveSaved, this, &DocumentController::reportLiveSave);
    addDocument(document);
    return document;
}

void DocumentController::reportLiveSave(const QString &path, const QString &error,
                                        const QStringList &warnings)
{
    if (error.isEmpty()) {
        m_recentFiles->add(path);
        rememberDirectory(path);
        emit statusMessage(warnings.isEmpty()
                               ? tr("Saved the live system to %1").arg(path)
                               : tr("Saved the live system to %1 without %n component(s)",
                                    nullptr, int(warnings.size()))
                                     .arg(path));
        return;
    }
    const QString summary = tr("Could not save the live system to %1.").arg(path);
    const Profile::Diagnostics diagnostics {Profile::Diagnostic::error(path, 0, 0, error)};
    emit problemsReported(summary, diagnostics);
    if (m_prompts)
        m_prompts->showProblems(tr("Save Failed"), summary, diagnostics);
}

QList<Document *> DocumentController::openFiles(const QStringList &paths)
{
    QList<Document *> opened;
    Profile::Diagnostics failures;
    QStringList failedNames;
    for (const QString &path : paths) {
        bool cancelled = false;
        if (Document *document = openOne(path, &failures, &cancelled))
            opened << document;
        else if (cancelled)
            break;
        else
            failedNames << QFileInfo(path).fileName();
    }
    if (!failedNames.isEmpty()) {
        const QString summary
            = tr("Could not open %1.").arg(failedNames.join(QStringLiteral(", ")));
        emit problemsReported(summary, failures);
        if (m_prompts) {
            m_prompts->showProblems(
                tr("Open Failed"),
                summary + QLatin1Char(' ') + tr("Open documents were not changed."), failures);
        }
    }
    return opened;
}

void DocumentController::cancelOpening()
{
    if (!m_openingLoop)
        return;
    m_openingCancelled = true;
    m_openingLoop->quit();
}

std::optional<Profile::LoadedProfile> DocumentController::readProfile(const QString &path,
                                                                      Profile::Diagnostics *diagnostics,
                                                                      bool *cancelled)
{
    struct Reading
    {
        std::optional<Profile::LoadedProfile> loaded;
        Profile::Diagnostics diagnostics;
    };
    // Shared with the thread, which may outlive this call when the user gives up on the file.
    auto reading = std::make_shared<Reading>();
    QThread *thread = QThread::create([reading, path] {
        reading->loaded = Profile::loadProfileFile(path, &reading->diagnostics);
    });
    thread->start();
    if (!thread->wait(QuickReadMs)) {
        QEventLoop loop;
        connect(thread, &QThread::finished, &loop, &QEventLoop::quit);
        m_openingLoop = &loop;
        m_openingCancelled = false;
        emit openingStarted(path);
        if (!thread->isFinished())
            loop.exec();
        m_openingLoop = nullptr;
        emit openingFinished();
        if (m_openingCancelled) {
            // Nobody waits for the thread: it ends after reading, and is deleted then.
            connect(thread, &QThread::finished, thread, &QObject::deleteLater);
            if (thread->isFinished())
                delete thread;
            *cancelled = true;
            emit statusMessage(tr("Opening %1 was cancelled").arg(QFileInfo(path).fileName()));
            return std::nullopt;
        }
        thread->wait();
    }
    delete thread;
    diagnostics->append(reading->diagnostics);
    return std::move(reading->loaded);
}

QList<Document *> DocumentController::openWithDialog()
{
    if (!m_prompts)
        return {};
    const QStringList paths = m_prompts->askOpenFileNames(lastDirectory());
    return paths.isEmpty() ? QList<Document *>() : openFiles(paths);
}

bool DocumentController::save(Document *document)
{
    if (document->isUntitled())
        return saveAs(document);
    return saveTo(document, document->filePath(), true);
}

bool DocumentController::saveAs(Document *document)
{
    if (!m_prompts)
        return false;
    const QString path = m_prompts->askSaveFileName(document->kind(), suggestedSavePath(document));
    if (path.isEmpty())
        return false;
    return saveAs(document, path);
}

bool DocumentController::saveAs(Document *document, const QString &path)
{
    if (auto *online = qobject_cast<OnlineDocument *>(document))
        return online->saveLive(path);
    return saveTo(document, path, false);
}

bool DocumentController::exportDiagram(Document *document)
{
    auto *system = qobject_cast<RtsDocument *>(document);
    if (!system || !m_prompts)
        return false;
    const QString base = document->isUntitled() ? suggestedSavePath(document) : document->filePath();
    const QString suggested = QFileInfo(base).dir().filePath(QFileInfo(base).completeBaseName()
                                                             + QStringLiteral(".png"));
    const QString path = m_prompts->askExportFileName(suggested);
    if (path.isEmpty())
        return false;
    QString error;
    if (!SystemEditor::DiagramExport::exportLaidOut(*system->model(), path, &error)) {
        const Profile::Diagnostics diagnostics {Profile::Diagnostic::error(path, 0, 0, error)};
        const QString summary = tr("Could not export the diagram to %1.")
                                    .arg(QFileInfo(path).fileName());
        emit problemsReported(summary, diagnostics);
        m_prompts->showProblems(tr("Export Failed"), summary, diagnostics);
        return false;
    }
    emit statusMessage(tr("Exported the diagram to %1").arg(path));
    return true;
}

bool DocumentController::close(Document *document)
{
    if (!m_documents.contains(document) || !confirmClose(document))
        return false;
    discard(document);
    return true;
}

bool DocumentController::closeAll()
{
    const QList<Document *> documents = m_documents;
    for (Document *document : documents) {
        if (!confirmClose(document))
            return false;
    }
    for (Document *document : documents)
        discard(document);
    return true;
}

QString DocumentController::lastDirectory() const
{
    const QString stored = QSettings().value(LastDirectoryKey).toString();
    return !stored.isEmpty() && QFileInfo(stored).isDir() ? stored : QDir::homePath();
}

Document *DocumentController::openOne(const QString &path, Profile::Diagnostics *failures,
                                      bool *cancelled)
{
    if (Document *existing = findByPath(path)) {
        emit activationRequested(existing);
        return existing;
    }
    Profile::Diagnostics diagnostics;
    std::optional<Profile::LoadedProfile> loaded = readProfile(path, &diagnostics, cancelled);
    if (*cancelled)
        return nullptr;
    std::unique_ptr<Document> document
        = loaded ? documentFromProfile(std::move(*loaded), path, &diagnostics) : nullptr;
    if (!document) {
        if (diagnostics.isEmpty())
            diagnostics << Profile::Diagnostic::error(path, 0, 0, tr("could not be read"));
        failures->append(diagnostics);
        return nullptr;
    }
    Document *added = document.release();
    added->setParent(this);
    addDocument(added);
    m_recentFiles->add(added->filePath());
    rememberDirectory(added->filePath());
    const Profile::Diagnostics warnings = added->loadWarnings();
    if (!warnings.isEmpty()) {
        emit problemsReported(tr("%1 was opened with %n warning(s).", nullptr, int(warnings.size()))
                                  .arg(added->displayName()),
                              warnings);
    }
    emit statusMessage(tr("Opened %1").arg(added->filePath()));
    return added;
}

void DocumentController::addDocument(Document *document)
{
    m_documents << document;
    emit documentAdded(document);
}

bool DocumentController::saveTo(Document *document, const QString &path, bool keepFormat)
{
    if (!confirmSystemProfile(document))
        return false;
    Profile::Diagnostics diagnostics;
    const bool saved
        = keepFormat ? document->save(&diagnostics) : document->saveAs(path, &diagnostics);
    if (!saved) {
        if (diagnostics.isEmpty())
            diagnostics << Profile::Diagnostic::error(path, 0, 0, tr("could not be written"));
        const QString summary = tr("Could not save %1.").arg(QFileInfo(path).fileName());
        emit problemsReported(summary, diagnostics);
        if (m_prompts) {
            m_prompts->showProblems(tr("Save Failed"),
                                    summary + QLatin1Char(' ')
                                        + tr("The document stays open with its changes."),
                                    diagnostics);
        }
        return false;
    }
    m_recentFiles->add(document->filePath());
    rememberDirectory(document->filePath());
    emit statusMessage(tr("Saved %1").arg(document->filePath()));
    return true;
}

bool DocumentController::confirmSystemProfile(Document *document)
{
    auto *system = qobject_cast<RtsDocument *>(document);
    if (!system || !m_prompts)
        return true;
    SystemEditor::SystemModel *model = system->model();
    const std::optional<SystemEditor::SystemProfileInfo> info
        = m_prompts->askSystemProfileInfo(model->systemInfo(), model->componentIds());
    if (!info)
        return false;
    // The answer is an edit like any other: one undo step, and the save stamps the new date.
    if (QUndoCommand *command = SystemEditor::SaveProfileDialog::applyCommand(model, *info))
        system->undoStack()->push(command);
    return true;
}

bool DocumentController::confirmClose(Document *document)
{
    if (!document->isModified())
        return true;
    if (!m_prompts)
        return false; // nobody to ask: never throw changes away silently
    switch (m_prompts->askSaveChanges(document->displayName())) {
    case UserPrompts::SaveChoice::Save:
        return save(document);
    case UserPrompts::SaveChoice::Discard:
        return true;
    case UserPrompts::SaveChoice::Cancel:
        break;
    }
    return false;
}

void DocumentController::discard(Document *document)
{
    emit documentClosing(document);
    m_documents.removeAll(document);
    delete document;
}

void DocumentController::rememberDirectory(const QString &filePath)
{
    QSettings().setValue(LastDirectoryKey, QFileInfo(filePath).absolutePath());
}

QString DocumentController::suggestedSavePath(const Document *document) const
{
    if (!document->isUntitled())
        return document->filePath();
    QString fileName = qobject_cast<const OnlineDocument *>(document)
        ? QStringLiteral("LiveSystem.xml")
        : QStringLiteral("RTC.xml");
    if (const auto *system = qobject_cast<const RtsDocument *>(document)) {
        const QString name = system->systemField(RtsDocument::SystemField::Name);
        fileName = (name.isEmpty() ? QStringLiteral("System") : name) + QStringLiteral(".xml");
    }
    return QDir(lastDirectory()).filePath(fileName);
}

} // namespace Studio
