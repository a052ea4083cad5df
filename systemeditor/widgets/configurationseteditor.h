// SPDX-License-Identifier: MIT
#pragma once

#include "parameterrule.h"
#include "rtscomponent.h"

#include <optional>

#include <QPointer>
#include <QStringList>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QUndoStack;

namespace Profile {
struct RtcConfiguration;
}

namespace SystemEditor {

class ElementListEditor;
class ParameterEditor;
struct ElementRules;
class SystemModel;

/**
 * Offline editing of a component's configuration sets: choose a set (hidden `__x__` sets only
 * with "Show hidden sets"), make it active, add a set (the profile's defaults), copy or delete
 * it, and edit each value with the widget and the constraint of the component's RTC profile
 * (`__widget__` property, Constraint; else the hidden `__widget__` / `__constraints__` sets;
 * else plain text). A value that breaks its constraint shows the reason under its widget and
 * does not reach the model; every accepted edit is an undo command.
 */
class ConfigurationSetEditor : public QWidget
{
    Q_OBJECT

public:
    ConfigurationSetEditor(SystemModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    /// Shows `instanceName`'s sets (empty: nothing).
    void setComponent(const QString &instanceName);
    QString component() const { return m_component; }

    /// The set shown.
    QString shownSet() const;
    void setShownSet(const QString &setId);
    void setShowHidden(bool show);
    /// The editor of `parameter` in the shown set, or null.
    ParameterEditor *parameterEditor(const QString &parameter) const;
    /// The per-element editor of array parameter `parameter` (a `vector<T>` type or a list
    /// constraint in the RTC profile) in the shown set, or null.
    ElementListEditor *elementEditor(const QString &parameter) const;
    /// How `parameter` of the shown component is edited.
    ParameterRule ruleFor(const QString &parameter) const;
    QComboBox *setCombo() const { return m_sets; }

    /// Editing as the widgets do it (each one undo step; a value breaking its constraint, for
    /// an array any element breaking its own, is refused and false returned). Edits of one
    /// value merge (typing) unless `structural` (elements added or removed).
    bool setValue(const QString &parameter, const QString &value, bool structural = false);
    void activateShownSet();
    void addSet();
    void addSetCopy();
    void deleteShownSet();

private:
    const Profile::RtsComponent *current() const;
    void refresh();
    void fillSets();
    void fillValues();
    void updateValues(const Profile::RtsConfigurationSet &set);
    void onEdited(ParameterEditor *editor);
    std::optional<ElementRules> elementRulesFor(const QString &parameter) const;
    void addElementList(const QString &parameter, const ElementRules &rules, const QString &value);
    const Profile::RtcConfiguration *profileConfiguration(const QString &parameter) const;
    QLabel *parameterLabel(const QString &parameter) const;
    void pushSets(const QList<Profile::RtsConfigurationSet> &sets,
                  const std::optional<QString> &active);
    static bool isHidden(const QString &setId);

    QPointer<SystemModel> m_model;
    QPointer<QUndoStack> m_undoStack;
    QString m_component;
    QComboBox *m_sets;
    QCheckBox *m_showHidden;
    QPushButton *m_activate;
    QPushButton *m_delete;
    QWidget *m_valuesArea;
    QFormLayout *m_valuesForm;
    QList<ParameterEditor *> m_editors;
    QList<ElementListEditor *> m_lists;
    QStringList m_shownNames; ///< the parameters the editors show, in order
    QString m_editorsSet; ///< the set the editors show
    bool m_filling = false;
};

} // namespace SystemEditor
