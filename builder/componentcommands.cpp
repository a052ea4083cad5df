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

// ---- SetActionCommand, SetComponentDocCommand, SetLanguageCommand

SetActionCommand::SetActionCommand(ComponentModel *model, Profile::RtcAction action,
                                   const std::optional<Profile::RtcActionStatus> &status,
                                   const QString &mergeKey, QUndoCommand *parent)
    : SetPartCommand(
        model, ActionCommandId, int(action),
        [](ComponentModel &m, int part, const std::optional<Profile::RtcActionStatus> &value) {
            m.setAction(Profile::RtcAction(part), value);
        },
        model->action(action), status, mergeKey, parent)
{
    setText(tr("Change %1").arg(Profile::rtcActionKey(action)));
}

SetComponentDocCommand::SetComponentDocCommand(ComponentModel *model,
                                               const std::optional<Profile::RtcBasicDoc> &doc,
                                               const QString &mergeKey, QUndoCommand *parent)
    : SetPartCommand(
        model, ComponentDocCommandId, 0,
        [](ComponentModel &m, int, const std::optional<Profile::RtcBasicDoc> &value) {
            m.setComponentDoc(value);
        },
        model->profile().basicInfo.doc, doc, mergeKey, parent)
{
    setText(tr("Change documentation"));
}

SetLanguageCommand::SetLanguageCommand(ComponentModel *model,
                                       const std::optional<Profile::RtcLanguage> &language,
                                       const QString &mergeKey, QUndoCommand *parent)
    : SetPartCommand(
        model, LanguageCommandId, 0,
        [](ComponentModel &m, int, const std::optional<Profile::RtcLanguage> &value) {
            m.setLanguage(value);
        },
        model->profile().language, language, mergeKey, parent)
{
    setText(tr("Change language and environment"));
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
