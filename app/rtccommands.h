// SPDX-License-Identifier: MIT
#pragma once

#include "rtcdocument.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

namespace Studio {

/**
 * Changes one field of an RtcDocument's basic information. When the field is part of the
 * component id and the id followed the basic info, the id is updated with it; both the field and
 * the id are stored before and after, so undo restores exactly what was there.
 *
 * Clearing an optional field (absent value or empty text) keeps an empty attribute when the field
 * had one before the edit and leaves it absent otherwise, so that typing and deleting changes
 * nothing in the file.
 *
 * Consecutive edits of the same field merge into one step (typing a word is one undo step);
 * an edit that ends where it started disappears from the stack.
 */
class SetBasicFieldCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetBasicFieldCommand)

public:
    SetBasicFieldCommand(RtcDocument *document, RtcDocument::BasicField field,
                         const std::optional<QString> &value, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

    RtcDocument::BasicField field() const { return m_field; }

private:
    void apply(const std::optional<QString> &value, const QString &componentId);
    std::optional<QString> normalized(const std::optional<QString> &value) const;

    QPointer<RtcDocument> m_document;
    RtcDocument::BasicField m_field;
    std::optional<QString> m_before;
    std::optional<QString> m_after;
    QString m_idBefore;
    QString m_idAfter;
};

} // namespace Studio
