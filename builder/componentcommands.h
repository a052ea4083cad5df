// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>

namespace Builder {

/**
 * Changes one field of the basic information. When the field is part of the component id and
 * the id followed the basic info, the id is updated with it; both are stored before and after.
 *
 * Clearing an optional field (absent value or empty text) keeps an empty attribute when the
 * field had one before the edit and leaves it absent otherwise, so that typing and deleting
 * changes nothing in the file. Consecutive edits of the same field merge (typing a word is one
 * undo step; the component kind, set by check boxes, never merges); an edit that ends where it
 * started disappears from the stack.
 */
class SetBasicFieldCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetBasicFieldCommand)

public:
    SetBasicFieldCommand(ComponentModel *model, BasicField field,
                         const std::optional<QString> &value, QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

    BasicField field() const { return m_field; }

private:
    void apply(const std::optional<QString> &value, const QString &componentId);
    std::optional<QString> normalized(const std::optional<QString> &value) const;

    QPointer<ComponentModel> m_model;
    BasicField m_field;
    std::optional<QString> m_before;
    std::optional<QString> m_after;
    QString m_idBefore;
    QString m_idAfter;
};

/**
 * Sets the whole entry of one action (on/off and its documentation). `mergeKey` names what is
 * being typed (e.g. "description"): consecutive edits with the same action and key merge.
 */
class SetActionCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetActionCommand)

public:
    SetActionCommand(ComponentModel *model, Profile::RtcAction action,
                     const std::optional<Profile::RtcActionStatus> &status,
                     const QString &mergeKey = QString(), QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<ComponentModel> m_model;
    Profile::RtcAction m_action;
    QString m_mergeKey;
    std::optional<Profile::RtcActionStatus> m_before;
    std::optional<Profile::RtcActionStatus> m_after;
};

/// Sets the component's documentation (`rtcDoc:Doc` of the basic info); merges like
/// SetActionCommand.
class SetComponentDocCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetComponentDocCommand)

public:
    SetComponentDocCommand(ComponentModel *model, const std::optional<Profile::RtcBasicDoc> &doc,
                           const QString &mergeKey = QString(), QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<ComponentModel> m_model;
    QString m_mergeKey;
    std::optional<Profile::RtcBasicDoc> m_before;
    std::optional<Profile::RtcBasicDoc> m_after;
};

/// Sets the language with its targets and libraries; merges like SetActionCommand.
class SetLanguageCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(SetLanguageCommand)

public:
    SetLanguageCommand(ComponentModel *model, const std::optional<Profile::RtcLanguage> &language,
                       const QString &mergeKey = QString(), QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand *other) override;

private:
    QPointer<ComponentModel> m_model;
    QString m_mergeKey;
    std::optional<Profile::RtcLanguage> m_before;
    std::optional<Profile::RtcLanguage> m_after;
};

/// Replaces the whole profile (applying the RTC.xml page): one undo step.
class ReplaceProfileCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(ReplaceProfileCommand)

public:
    ReplaceProfileCommand(ComponentModel *model, const Profile::RtcProfile &profile,
                          QUndoCommand *parent = nullptr);

    void undo() override;
    void redo() override;

private:
    QPointer<ComponentModel> m_model;
    Profile::RtcProfile m_before;
    Profile::RtcProfile m_after;
};

} // namespace Builder
