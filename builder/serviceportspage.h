// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QWidget>

class QPushButton;
class QStackedWidget;
class QTreeView;
class QUndoStack;

namespace Builder {

class ItemForm;
class ServicePortTreeModel;
class TypeCatalog;

/**
 * The Builder's "Service Ports" page: the ports and their interfaces as a tree, with a form for
 * the selected port (name, position, documentation) or interface (name, direction, instance and
 * variable name, interface type from the parsed IDL, IDL file, documentation).
 */
class ServicePortsPage : public QWidget
{
    Q_OBJECT

public:
    ServicePortsPage(ComponentModel *model, QUndoStack *undoStack, TypeCatalog *types,
                     QWidget *parent = nullptr);

    QTreeView *view() const { return m_view; }
    ServicePortTreeModel *tree() const { return m_tree; }
    ItemForm *portForm() const { return m_portForm; }
    ItemForm *interfaceForm() const { return m_interfaceForm; }

    void addPort();
    /// Adds an interface to the selected port (or the port of the selected interface).
    void addInterface();
    void removeSelected();
    /// Selects a port, or one of its interfaces.
    void select(int port, int interface = -1);

private:
    void buildPortForm();
    void buildInterfaceForm();
    void showSelection();

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    TypeCatalog *m_types;
    ServicePortTreeModel *m_tree;
    QTreeView *m_view;
    QStackedWidget *m_forms;
    ItemForm *m_portForm = nullptr;
    ItemForm *m_interfaceForm = nullptr;
    QPushButton *m_addInterface = nullptr;
    QPushButton *m_remove = nullptr;
    int m_interface = -1; ///< the interface the interface form edits
    int m_selectedPort = -1;
};

} // namespace Builder
