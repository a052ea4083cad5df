// SPDX-License-Identifier: MIT
#include "systemcommands.h"

#include "systemcommandids.h"

namespace SystemEditor {

SetSystemInfoCommand::SetSystemInfoCommand(SystemModel *model, const SystemProfileInfo &info,
                                           int mergeKey, const QString &text,
                                           QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_before(model->systemInfo())
    , m_after(info)
    , m_beforeId(model->profile().id)
    , m_mergeKey(mergeKey)
{
    setText(text.isEmpty() ? tr("Edit system profile") : text);
}

void SetSystemInfoCommand::redo()
{
    if (m_model)
        m_model->setSystemInfo(m_after);
}

void SetSystemInfoCommand::undo()
{
    if (!m_model)
        return;
    m_model->setSystemInfo(m_before);
    m_model->setSystemId(m_beforeId);
}

int SetSystemInfoCommand::id() const
{
    return m_mergeKey < 0 ? -1 : int(SystemInfoCommandId);
}

bool SetSystemInfoCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SetSystemInfoCommand *>(other);
    if (next->m_model != m_model || next->m_mergeKey != m_mergeKey)
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before && m_before.systemId() == m_beforeId);
    return true;
}

} // namespace SystemEditor
