// SPDX-License-Identifier: MIT
#pragma once

#include "rtscomponent.h"

#include <QPointer>
#include <QWidget>

class QComboBox;
class QFormLayout;
class QLabel;
class QPushButton;
class QStackedWidget;
class QTableWidget;
class QUndoStack;

namespace SystemEditor {

class SystemModel;
class SystemScene;

/**
 * The Properties view of the canvas selection. For a component: instance name, type id, path
 * URI, type name, and its configuration sets edited offline (choose a set, edit values, make a
 * set active, add a copy, delete a set); for a connector: name, ends, data type and every
 * property. Configuration edits go through SetConfigurationSetsCommand on the undo stack; the
 * panel follows model changes (undo included).
 */
class PropertiesPanel : public QWidget
{
    Q_OBJECT

public:
    PropertiesPanel(SystemModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    /// Follows the selection of `scene` from now on.
    void followScene(SystemScene *scene);
    void showComponent(const QString &instanceName);
    void showConnector(const QString &connectorId);
    void showNothing();

    QString shownComponent() const { return m_component; }
    QString shownConnector() const { return m_connector; }
    /// The configuration set shown in the table.
    QString shownSet() const;
    void setShownSet(const QString &setId);
    /// Configuration editing, as the buttons do it (each one undo step).
    void setValue(const QString &parameter, const QString &value);
    void activateShownSet();
    void addSetCopy();
    void deleteShownSet();

    QLabel *field(const QString &name) const;
    QComboBox *setCombo() const { return m_sets; }
    QTableWidget *valueTable() const { return m_values; }
    QTableWidget *connectorTable() const { return m_connectorProperties; }

signals:
    /// The user asked to edit the shown connector (its dialog belongs to the canvas view).
    void editConnectorRequested(const QString &connectorId);

private:
    QWidget *buildComponentPage();
    QWidget *buildConnectorPage();
    QLabel *addField(QFormLayout *form, const QString &name, const QString &label);
    void refresh();
    void fillComponent();
    void fillValues();
    void fillConnector();
    void onValueEdited(int row, int column);
    void pushSets(const QList<Profile::RtsConfigurationSet> &sets,
                  const std::optional<QString> &active);
    void followSelection();

    QPointer<SystemModel> m_model;
    QPointer<QUndoStack> m_undoStack;
    QPointer<SystemScene> m_scene;
    QString m_component;
    QString m_connector;
    QStackedWidget *m_pages;
    QComboBox *m_sets = nullptr;
    QTableWidget *m_values = nullptr;
    QPushButton *m_activate = nullptr;
    QPushButton *m_delete = nullptr;
    QTableWidget *m_connectorProperties = nullptr;
    bool m_filling = false;
};

} // namespace SystemEditor
