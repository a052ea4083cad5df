// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QWidget>

class QGroupBox;
class QLabel;
class QTableView;
class QUndoStack;

namespace Builder {

class EventTableModel;
class ItemForm;
class ListEditor;
class TypeCatalog;

/**
 * The Builder's "Data Ports" page: InPort, OutPort and EventPort tables (name, data type,
 * variable, position) and, for the selected port, a form with every field and its
 * documentation. An EventPort carries FSM events: for the selected one the events table edits
 * name, data type, source and target state, condition and description.
 */
class DataPortsPage : public QWidget
{
    Q_OBJECT

public:
    DataPortsPage(ComponentModel *model, QUndoStack *undoStack, TypeCatalog *types,
                  QWidget *parent = nullptr);

    ListEditor *inPorts() const { return m_inPorts; }
    ListEditor *outPorts() const { return m_outPorts; }
    ListEditor *eventPorts() const { return m_eventPorts; }
    /// The events of the selected EventPort.
    QTableView *events() const { return m_events; }
    EventTableModel *eventTable() const { return m_eventTable; }
    ItemForm *form() const { return m_form; }

private:
    ListEditor *makeList(Profile::RtcPortType type, const QString &title);
    void buildForm();
    QGroupBox *buildEventsBox();
    void showPort(int itemIndex);
    void refreshComposite();

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    TypeCatalog *m_types;
    ListEditor *m_inPorts = nullptr;
    ListEditor *m_outPorts = nullptr;
    ListEditor *m_eventPorts = nullptr;
    EventTableModel *m_eventTable = nullptr;
    QTableView *m_events = nullptr;
    QGroupBox *m_eventsBox = nullptr;
    ItemForm *m_form = nullptr;
    QLabel *m_composite = nullptr;
};

} // namespace Builder
