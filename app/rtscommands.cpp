// SPDX-License-Identifier: MIT
#include "rtscommands.h"

#include "commandids.h"

namespace Studio {

EditSystemInfoCommand::EditSystemInfoCommand(RtsDocument *document, RtsDocument::SystemField field,
                                             const QString &value, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_document(document)
    , m_field(field)
{
    m_before = currentValue();
    if (field == RtsDocument::SystemField::Abstract) {
        m_after = normalizedAbstract(value);
    } else {
        m_after = RtsDocument::idWithField(document->systemId(), field, value);
    }
    updateText();
}

void EditSystemInfoCommand::undo()
{
    apply(m_before);
}

void EditSystemInfoCommand::redo()
{
    apply(m_after);
}

int EditSystemInfoCommand::id() const
{
    return SystemInfoCommandId;
}

bool EditSystemInfoCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const EditSystemInfoCommand *>(other);
    if (edit->m_document != m_document || edit->m_field != m_field)
        return false;
    m_after = m_field == RtsDocument::SystemField::Abstract ? normalizedAbstract(edit->m_after)
                                                            : edit->m_after;
    // Normalising against the older "before" can differ from what the newer edit applied; the
    // merged step must end where it says it does.
    apply(m_after);
    setObsolete(m_after == m_before);
    return true;
}

void EditSystemInfoCommand::apply(const std::optional<QString> &value)
{
    if (!m_document)
        return;
    if (m_field == RtsDocument::SystemField::Abstract)
        m_document->setAbstract(value);
    else
        m_document->setSystemId(value.value_or(QString()));
}

std::optional<QString> EditSystemInfoCommand::currentValue() const
{
    if (m_field == RtsDocument::SystemField::Abstract)
        return m_document->abstract();
    return m_document->systemId();
}

std::optional<QString>
EditSystemInfoCommand::normalizedAbstract(const std::optional<QString> &value) const
{
    // An abstract the file never had must not turn into an empty attribute by typing and
    // deleting; one it had stays, empty, when cleared.
    if (value && !value->isEmpty())
        return value;
    return m_before ? std::optional<QString>(QString()) : std::nullopt;
}

void EditSystemInfoCommand::updateText()
{
    setText(tr("Change %1").arg(RtsDocument::fieldLabel(m_field)));
}

} // namespace Studio
