// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

namespace SystemEditor {

/**
 * Sets one value of one configuration set of a component (`rts:ConfigurationData @data`),
 * adding the parameter to the set when it is not listed. Successive edits of the same value
 * (typing) merge into one undo step.
 */
class SetConfigurationValueCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetConfigurationValueCommand)

public:
    SetConfigurationValueCommand(SystemModel *model, const QString &instanceName,
                                 const QString &setId, const QString &parameter,
                                 const QString &value, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;
    /// False keeps this edit a step of its own (neither merging nor merged into).
    void setMergeable(bool mergeable) { m_mergeable = mergeable; }

private:
    void apply(const QList<Profile::RtsConfigurationSet> &sets);

    QPointer<SystemModel> m_model;
    QString m_instance;
    QString m_setId;
    QString m_parameter;
    QList<Profile::RtsConfigurationSet> m_before, m_after;
    bool m_mergeable = true;
};

/// `sets` with `parameter` of set `setId` set to `value` (appended when the set lacks it).
QList<Profile::RtsConfigurationSet> withConfigurationValue(
    QList<Profile::RtsConfigurationSet> sets, const QString &setId, const QString &parameter,
    const QString &value);

/// `base`, or `base2`, `base3` … : the first id no set in `sets` has.
QString uniqueSetId(const QList<Profile::RtsConfigurationSet> &sets, const QString &base);

} // namespace SystemEditor
