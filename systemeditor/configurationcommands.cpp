// SPDX-License-Identifier: MIT
#include "configurationcommands.h"

#include "systemcommandids.h"

#include <algorithm>

namespace SystemEditor {

using namespace Profile;

QList<RtsConfigurationSet> withConfigurationValue(QList<RtsConfigurationSet> sets,
                                                  const QString &setId, const QString &parameter,
                                                  const QString &value)
{
    for (RtsConfigurationSet &set : sets) {
        if (set.id != setId)
            continue;
        auto found = std::find_if(set.data.begin(), set.data.end(),
                                  [&](const RtsConfigurationData &d) { return d.name == parameter; });
        if (found == set.data.end()) {
            RtsConfigurationData data;
            data.name = parameter;
            set.data.append(data);
            found = set.data.end() - 1;
        }
        found->data = value;
    }
    return sets;
}

QString uniqueSetId(const QList<RtsConfigurationSet> &sets, const QString &base)
{
    const auto taken = [&sets](const QString &id) {
        return std::any_of(sets.begin(), sets.end(),
                           [&id](const RtsConfigurationSet &s) { return s.id == id; });
    };
    QString id = base;
    for (int n = 2; taken(id); ++n)
        id = base + QString::number(n);
    return id;
}

SetConfigurationValueCommand::SetConfigurationValueCommand(SystemModel *model,
                                                           const QString &instanceName,
                                                           const QString &setId,
                                                           const QString &parameter,
                                                           const QString &value,
                                                           QUndoCommand *parent)
    : QUndoCommand(parent)
    , m_model(model)
    , m_instance(instanceName)
    , m_setId(setId)
    , m_parameter(parameter)
{
    if (const RtsComponent *c = model->component(instanceName)) {
        m_before = c->configurationSets;
        m_after = withConfigurationValue(m_before, setId, parameter, value);
    }
    setText(tr("Set %1 of %2 to \"%3\"").arg(parameter, instanceName, value));
}

void SetConfigurationValueCommand::apply(const QList<RtsConfigurationSet> &sets)
{
    const RtsComponent *c = m_model ? m_model->component(m_instance) : nullptr;
    if (c)
        m_model->setConfigurationSets(m_instance, sets, c->activeConfigurationSet);
}

void SetConfigurationValueCommand::redo()
{
    apply(m_after);
}

void SetConfigurationValueCommand::undo()
{
    apply(m_before);
}

int SetConfigurationValueCommand::id() const
{
    return ConfigurationValueCommandId;
}

bool SetConfigurationValueCommand::mergeWith(const QUndoCommand *other)
{
    const auto *next = static_cast<const SetConfigurationValueCommand *>(other);
    if (!m_mergeable || !next->m_mergeable || next->m_model != m_model
        || next->m_instance != m_instance || next->m_setId != m_setId
        || next->m_parameter != m_parameter)
        return false;
    m_after = next->m_after;
    setText(next->text());
    setObsolete(m_after == m_before);
    return true;
}

} // namespace SystemEditor
