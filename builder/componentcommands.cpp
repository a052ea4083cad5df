// SPDX-License-Identifier: MIT
#include "componentcommands.h"

#include "buildercommandids.h"

namespace Builder {

SetBasicFieldCommand::SetBasicFieldCommand(ComponentModel *model, BasicField field,
                                           const std::optional<QString> &value,
                                           QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_field(field)
    , m_before(model->basicField(field))
    , m_idBefore(model->componentId())
{
    m_after = normalized(value);
    m_idAfter = ComponentModel::idAfterEdit(model->profile(), field, m_after.value_or(QString()));
    setText(tr("Change %1").arg(ComponentModel::fieldLabel(field)));
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
    return BasicFieldCommandId;
}

bool SetBasicFieldCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const SetBasicFieldCommand *>(other);
    // Component kind changes are clicks on check boxes: each click is its own step.
    if (edit->m_model != m_model || edit->m_field != m_field
        || m_field == BasicField::ComponentKind)
        return false;
    m_after = normalized(edit->m_after);
    m_idAfter = edit->m_idAfter;
    // Normalising against the older "before" can differ from what the newer edit applied
    // (typing into an absent field and deleting again); the merged step must end where it says.
    apply(m_after, m_idAfter);
    setObsolete(m_after == m_before && m_idAfter == m_idBefore);
    return true;
}

void SetBasicFieldCommand::apply(const std::optional<QString> &value, const QString &componentId)
{
    if (!m_model)
        return;
    m_model->setBasicField(m_field, value);
    m_model->setComponentId(componentId);
}

std::optional<QString> SetBasicFieldCommand::normalized(const std::optional<QString> &value) const
{
    if (!ComponentModel::isOptional(m_field))
        return value.value_or(QString());
    if (value && !value->isEmpty())
        return value;
    return m_before ? std::optional<QString>(QString()) : std::nullopt;
}

// ---- SetActionCommand

SetActionCommand::SetActionCommand(ComponentModel *model, Profile::RtcAction action,
                                   const std::optional<Profile::RtcActionStatus> &status,
                                   const QString &mergeKey, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_action(action)
    , m_mergeKey(mergeKey)
    , m_before(model->action(action))
    , m_after(status)
{
    setText(tr("Change %1").arg(Profile::rtcActionKey(action)));
}

void SetActionCommand::undo()
{
    if (m_model)
        m_model->setAction(m_action, m_before);
}

void SetActionCommand::redo()
{
    if (m_model)
        m_model->setAction(m_action, m_after);
}

int SetActionCommand::id() const
{
    return ActionCommandId;
}

bool SetActionCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const SetActionCommand *>(other);
    if (edit->m_model != m_model || edit->m_action != m_action || m_mergeKey.isEmpty()
        || edit->m_mergeKey != m_mergeKey)
        return false;
    m_after = edit->m_after;
    setObsolete(m_after == m_before);
    return true;
}

// ---- SetComponentDocCommand

SetComponentDocCommand::SetComponentDocCommand(ComponentModel *model,
                                               const std::optional<Profile::RtcBasicDoc> &doc,
                                               const QString &mergeKey, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_mergeKey(mergeKey)
    , m_before(model->profile().basicInfo.doc)
    , m_after(doc)
{
    setText(tr("Change documentation"));
}

void SetComponentDocCommand::undo()
{
    if (m_model)
        m_model->setComponentDoc(m_before);
}

void SetComponentDocCommand::redo()
{
    if (m_model)
        m_model->setComponentDoc(m_after);
}

int SetComponentDocCommand::id() const
{
    return ComponentDocCommandId;
}

bool SetComponentDocCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const SetComponentDocCommand *>(other);
    if (edit->m_model != m_model || m_mergeKey.isEmpty() || edit->m_mergeKey != m_mergeKey)
        return false;
    m_after = edit->m_after;
    setObsolete(m_after == m_before);
    return true;
}

// ---- SetLanguageCommand

SetLanguageCommand::SetLanguageCommand(ComponentModel *model,
                                       const std::optional<Profile::RtcLanguage> &language,
                                       const QString &mergeKey, QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_mergeKey(mergeKey)
    , m_before(model->profile().language)
    , m_after(language)
{
    setText(tr("Change language and environment"));
}

void SetLanguageCommand::undo()
{
    if (m_model)
        m_model->setLanguage(m_before);
}

void SetLanguageCommand::redo()
{
    if (m_model)
        m_model->setLanguage(m_after);
}

int SetLanguageCommand::id() const
{
    return LanguageCommandId;
}

bool SetLanguageCommand::mergeWith(const QUndoCommand *other)
{
    const auto *edit = static_cast<const SetLanguageCommand *>(other);
    if (edit->m_model != m_model || m_mergeKey.isEmpty() || edit->m_mergeKey != m_mergeKey)
        return false;
    m_after = edit->m_after;
    setObsolete(m_after == m_before);
    return true;
}

// ---- ReplaceProfileCommand

ReplaceProfileCommand::ReplaceProfileCommand(ComponentModel *model,
                                             const Profile::RtcProfile &profile,
                                             QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_before(model->profile())
    , m_after(profile)
{
    setText(tr("Edit RTC.xml"));
}

void ReplaceProfileCommand::undo()
{
    if (m_model)
        m_model->setProfile(m_before);
}

void ReplaceProfileCommand::redo()
{
    if (m_model)
        m_model->setProfile(m_after);
}

} // namespace Builder
