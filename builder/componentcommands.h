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
 * Sets one part of the profile from the value it had to a new one. `mergeKey` names what is
 * being typed (e.g. "description"): consecutive edits of the same part with the same key merge
 * into one undo step, and an edit that ends where it started disappears from the stack.
 */
template<typename Value> class SetPartCommand : public QUndoCommand
{
public:
    void undo() override { apply(m_before); }
    void redo() override { apply(m_after); }
    int id() const override { return m_id; }
    bool mergeWith(const QUndoCommand *other) override
    {
        // Qt offers only commands of the same id, and each id belongs to one kind of part.
        const auto *edit = static_cast<const SetPartCommand *>(other);
        if (edit->m_model != m_model || edit->m_part != m_part || m_mergeKey.isEmpty()
            || edit->m_mergeKey != m_mergeKey)
            return false;
        m_after = edit->m_after;
        setObsolete(m_after == m_before);
        return true;
    }

protected:
    /// Writes @p value into part @p part of @p model.
    using Setter = void (*)(ComponentModel &model, int part, const Value &value);

    SetPartCommand(ComponentModel *model, int id, int part, Setter setter, const Value &before,
                   const Value &after, const QString &mergeKey, QUndoCommand *parent)
        : QUndoCommand(parent)
        , m_model(model)
        , m_id(id)
        , m_part(part)
        , m_setter(setter)
        , m_mergeKey(mergeKey)
        , m_before(before)
        , m_after(after)
    { }

private:
    void apply(const Value &value)
    {
        if (m_model)
            m_setter(*m_model, m_part, value);
    }

    QPointer<ComponentModel> m_model;
    int m_id;
    int m_part;
    Setter m_setter;
    QString m_mergeKey;
    Value m_before;
    Value m_after;
};

/// Sets the whole entry of one action (on/off and its documentation).
class SetActionCommand : public SetPartCommand<std::optional<Profile::RtcActionStatus>>
{
    Q_DECLARE_TR_FUNCTIONS(SetActionCommand)

public:
    SetActionCommand(ComponentModel *model, Profile::RtcAction action,
                     const std::optional<Profile::RtcActionStatus> &status,
                     const QString &mergeKey = QString(), QUndoCommand *parent = nullptr);
};

/// Sets the component's documentation (`rtcDoc:Doc` of the basic info).
class SetComponentDocCommand : public SetPartCommand<std::optional<Profile::RtcBasicDoc>>
{
    Q_DECLARE_TR_FUNCTIONS(SetComponentDocCommand)

public:
    SetComponentDocCommand(ComponentModel *model, const std::optional<Profile::RtcBasicDoc> &doc,
                           const QString &mergeKey = QString(), QUndoCommand *parent = nullptr);
};

/// Sets the language with its targets and libraries.
class SetLanguageCommand : public SetPartCommand<std::optional<Profile::RtcLanguage>>
{
    Q_DECLARE_TR_FUNCTIONS(SetLanguageCommand)

public:
    SetLanguageCommand(ComponentModel *model, const std::optional<Profile::RtcLanguage> &language,
                       const QString &mergeKey = QString(), QUndoCommand *parent = nullptr);
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
