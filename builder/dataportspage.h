// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QPointer>
#include <QWidget>

class QLabel;
class QUndoStack;

namespace Builder {

class ItemForm;
class ListEditor;
class TypeCatalog;

/**
 * The Builder's "Data Ports" page: InPort and OutPort tables (name, data type, variable,
 * position) and, for the selected port, a form with every field and its documentation.
 */
class DataPortsPage : public QWidget
{
    Q_OBJECT

public:
    DataPortsPage(ComponentModel *model, QUndoStack *undoStack, TypeCatalog *types,
                  QWidget *parent = nullptr);

    ListEditor *inPorts() const { return m_inPorts; }
    ListEditor *outPorts() const { return m_outPorts; }
    ItemForm *form() const { return m_form; }

private:
    ListEditor *makeList(Profile::RtcPortType type, const QString &title);
    void buildForm();
    void showPort(int itemIndex);
    void refreshComposite();

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    TypeCatalog *m_types;
    ListEditor *m_inPorts = nullptr;
    ListEditor *m_outPorts = nullptr;
    ItemForm *m_form = nullptr;
    QLabel *m_composite = nullptr;
};

} // namespace Builder
