// SPDX-License-Identifier: MIT
#include "document.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QUndoStack>

namespace Studio {

Document::Document(QObject *parent)
    : QObject(parent)
    , m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this,
            [this](bool clean) { emit modifiedChanged(!clean); });
}

Document::~Document() = default;

QString Document::displayName() const
{
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).fileName();
    if (!m_untitledName.isEmpty())
        return m_untitledName;
    return tr("Untitled");
}

void Document::setUntitledName(const QString &name)
{
    if (m_untitledName == name)
        return;
    m_untitledName = name;
    if (isUntitled())
        emit displayNameChanged(displayName());
}

bool Document::isModified() const
{
    return !m_undoStack->isClean();
}

bool Document::save(Profile::Diagnostics *diagnostics)
{
    if (isUntitled()) {
        if (diagnostics) {
            diagnostics->append(Profile::Diagnostic::error(
                displayName(), 0, 0, tr("the document has no file yet; use Save As")));
        }
        return false;
    }
    return writeTo(m_filePath, m_format, diagnostics);
}

bool Document::saveAs(const QString &path, Profile::Diagnostics *diagnostics)
{
    const Profile::FileFormat format = Profile::formatForFileName(path);
    if (!writeTo(path, format, diagnostics))
        return false;
    setFile(QFileInfo(path).absoluteFilePath(), format);
    return true;
}

void Document::attachToFile(const QString &path, Profile::FileFormat format,
                            const Profile::Diagnostics &loadWarnings)
{
    m_loadWarnings = loadWarnings;
    setFile(QFileInfo(path).absoluteFilePath(), format);
}

void Document::setFile(const QString &path, Profile::FileFormat format)
{
    const QString oldName = displayName();
    m_format = format;
    if (m_filePath != path) {
        m_filePath = path;
        emit filePathChanged(path);
    }
    if (displayName() != oldName)
        emit displayNameChanged(displayName());
}

bool Document::writeTo(const QString &path, Profile::FileFormat format,
                       Profile::Diagnostics *diagnostics)
{
    // Serialising first and writing atomically means a failed save leaves both the old file
    // and the document (still modified) as they were.
    if (!writeFiles(path, format, diagnostics))
        return false;
    m_undoStack->setClean();
    return true;
}

bool Document::writeFiles(const QString &path, Profile::FileFormat format,
                          Profile::Diagnostics *diagnostics)
{
    return Profile::writeFileAtomically(path, serialize(format), diagnostics);
}

} // namespace Studio
