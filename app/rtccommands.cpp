// SPDX-License-Identifier: MIT
#include "rtccommands.h"

#include "commandids.h"

namespace Studio {

SetBasicFieldCommand::SetBasicFieldCommand(RtcDocument *document, RtcDocument::BasicField field,
                                           const std::optional<QString> &value,
                                           QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_document(document)
    , m_field(field)
    , m_before(document->basicField(field))
    , m_idBefore(document->componentId())
{
    m_after = normalized(value);
    m_idAfter = RtcDocument::idAfterEdit(document->profile(), field, m_after.value_or(QString()));
    setText(tr("Change %1").arg(RtcDocument::fieldLabel(field)));
}

void SetBasicFieldCommand::undo()
{
    apply(m_before, m_idBefore);
}

void SetBasicFieldCommand::redo()
{
    apply(m_after, m_idAfter);
}

int SetBasicFieldCommand::id() const
{
    return RtcBasicFieldCommandId;
}

bool SetBasicFieldCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const SetBasicFieldCommand *>(other);
    if (edit->m_document != m_document || edit->m_field != m_field)
        return false;
    m_after = normalized(edit->m_after);
    m_idAfter = edit->m_idAfter;
    // Normalising against the older "before" can differ from what the newer edit applied
    // (e.g. typing into an absent field and deleting again); the merged step must end where
    // it says it does.
    apply(m_after, m_idAfter);
    setObsolete(m_after == m_before && m_idAfter == m_idBefore);
    return true;
}

void SetBasicFieldCommand::apply(const std::optional<QString> &value, const QString &componentId)
{
    if (!m_document)
        return;
    m_document->setBasicField(m_field, value);
    m_document->setComponentId(componentId);
}

std::optional<QString> SetBasicFieldCommand::normalized(const std::optional<QString> &value) const
{
    if (!RtcDocument::isOptional(m_field))
        return value.value_or(QString());
    if (value && !value->isEmpty())
        return value;
    return m_before ? std::optional<QString>(QString()) : std::nullopt;
}

} // namespace Studio
