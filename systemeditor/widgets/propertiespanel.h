// SPDX-License-Identifier: MIT
#pragma once

#include <QPointer>
#include <QWidget>

class QComboBox;
class QFormLayout;
class QLabel;
class QStackedWidget;
class QTableWidget;
class QUndoStack;

namespace SystemEditor {

class ConfigurationSetEditor;
class SystemModel;
class SystemScene;

/**
 * The Properties view of the canvas selection. For a component: instance name, type id, path
 * URI, type name, and its configuration sets edited offline with the widgets and constraints of
 * its RTC profile (ConfigurationSetEditor); for a connector: name, ends, data type and every
 * property. Every edit is an undo command; the panel follows model changes (undo included).
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
    /// The configuration set shown.
    QString shownSet() const;
    void setShownSet(const QString &setId);
    /// Configuration editing, as the buttons and value widgets do it (each one undo step; a
    /// value that breaks its constraint is refused).
    bool setValue(const QString &parameter, const QString &value);
    void activateShownSet();
    void addSetCopy();
    void deleteShownSet();

    QLabel *field(const QString &name) const;
    QComboBox *setCombo() const;
    ConfigurationSetEditor *configurationEditor() const { return m_configuration; }
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
    void fillConnector();
    void followSelection();

    QPointer<SystemModel> m_model;
    QPointer<QUndoStack> m_undoStack;
    QPointer<SystemScene> m_scene;
    QString m_component;
    QString m_connector;
    QStackedWidget *m_pages;
    ConfigurationSetEditor *m_configuration = nullptr;
    QTableWidget *m_connectorProperties = nullptr;
};

} // namespace SystemEditor
