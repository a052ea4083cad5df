// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "profileio.h"

#include <QObject>
#include <QString>

class QUndoStack;

namespace Studio {

/**
 * An open profile: the model value, the file it belongs to, its format and its undo history.
 *
 * Subclasses (RtcDocument, RtsDocument) own the model and offer public setters; every user edit
 * goes through a QUndoCommand that calls them, and the document announces each change with a
 * signal that views listen to. The document is modified while its undo stack is not clean.
 */
class Document : public QObject
{
    Q_OBJECT

public:
    ~Document() override;

    virtual Profile::ProfileKind kind() const = 0;

    /// The file the document was loaded from or last saved to; empty while untitled.
    QString filePath() const { return m_filePath; }
    bool isUntitled() const { return m_filePath.isEmpty(); }
    /// The format Save writes: the format the file had, or the one its extension names.
    Profile::FileFormat format() const { return m_format; }
    /// The file name, or the untitled name given by setUntitledName().
    QString displayName() const;
    void setUntitledName(const QString &name);

    QUndoStack *undoStack() const { return m_undoStack; }
    bool isModified() const;

    /// Warnings the reader had when the document was loaded.
    Profile::Diagnostics loadWarnings() const { return m_loadWarnings; }

    /**
     * Writes the document to filePath() in format(). On failure the document stays modified and
     * the reasons are appended to `diagnostics`. An untitled document cannot be saved this way.
     */
    bool save(Profile::Diagnostics *diagnostics);
    /**
     * Writes the document to `path` in the format its extension names (.yaml/.yml → YAML, else
     * XML) and makes it the document's file. On failure nothing about the document changes.
     */
    bool saveAs(const QString &path, Profile::Diagnostics *diagnostics);

    /// The document as file content in `format`, as save() would write it.
    virtual QByteArray serialize(Profile::FileFormat format) const = 0;

    /**
     * Ties a freshly loaded document to the file it was read from (used by loadDocument()); does
     * not touch the model or the undo history.
     */
    void attachToFile(const QString &path, Profile::FileFormat format,
                      const Profile::Diagnostics &loadWarnings);

signals:
    void filePathChanged(const QString &path);
    void displayNameChanged(const QString &name);
    void modifiedChanged(bool modified);

protected:
    explicit Document(QObject *parent = nullptr);

    /**
     * Writes the document to `path` in `format`; the default writes serialize() atomically.
     * Documents that write more than one file (a system with its RTC profiles) override it.
     */
    virtual bool writeFiles(const QString &path, Profile::FileFormat format,
                            Profile::Diagnostics *diagnostics);

private:
    void setFile(const QString &path, Profile::FileFormat format);
    bool writeTo(const QString &path, Profile::FileFormat format,
                 Profile::Diagnostics *diagnostics);

    QUndoStack *m_undoStack;
    QString m_filePath;
    QString m_untitledName;
    Profile::FileFormat m_format = Profile::FileFormat::Xml;
    Profile::Diagnostics m_loadWarnings;
};

} // namespace Studio
