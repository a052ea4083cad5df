// SPDX-License-Identifier: MIT
#pragma once

#include "rtsdocument.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

namespace Studio {

/**
 * Changes one "system info" field of an RtsDocument: vendor, name or version (which rewrite the
 * system id) or the abstract. Stores the whole id (or abstract) before and after, so that undo
 * restores exactly what the file had even when its id was malformed.
 *
 * Consecutive edits of the same field merge into one step (typing a word is one undo step);
 * an edit that ends where it started disappears from the stack.
 */
class EditSystemInfoCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(EditSystemInfoCommand)

public:
    /// Clearing the abstract keeps an empty attribute when the system had one before the edit
    /// and leaves it absent otherwise.
    EditSystemInfoCommand(RtsDocument *document, RtsDocument::SystemField field,
                          const QString &value, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

    RtsDocument::SystemField field() const { return m_field; }

private:
    void apply(const std::optional<QString> &value);
    std::optional<QString> currentValue() const;
    std::optional<QString> normalizedAbstract(const std::optional<QString> &value) const;
    void updateText();

    QPointer<RtsDocument> m_document;
    RtsDocument::SystemField m_field;
    std::optional<QString> m_before;
    std::optional<QString> m_after;
};

} // namespace Studio
