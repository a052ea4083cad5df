// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

namespace SystemEditor {

/**
 * Changes the system's profile information (vendor, name, version, abstract, dates, required
 * components). Commands built with the same non-negative `mergeKey` merge (typing into one
 * field is one undo step); a merged step that ends where it began disappears.
 */
class SetSystemInfoCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetSystemInfoCommand)

public:
    SetSystemInfoCommand(SystemModel *model, const SystemProfileInfo &info, int mergeKey = -1,
                         const QString &text = {}, QUndoCommand *parent = nullptr);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<SystemModel> m_model;
    SystemProfileInfo m_before;
    SystemProfileInfo m_after;
    // The exact id text before, so that undo restores a malformed id as the file had it.
    QString m_beforeId;
    int m_mergeKey;
};

} // namespace SystemEditor
