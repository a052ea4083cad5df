// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"
#include "itemcolumn.h"

#include <QPointer>
#include <QWidget>

class QUndoStack;

namespace Builder {

class ItemForm;
class ListEditor;

/**
 * The Builder's "Configuration" page: the parameters as a table (name, type, default, variable,
 * unit, constraint in RTC Builder's string syntax, widget and step) and a form with the selected
 * parameter's fields and documentation.
 */
class ConfigurationPage : public QWidget
{
    Q_OBJECT

public:
    ConfigurationPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent = nullptr);

    ListEditor *list() const { return m_list; }
    ItemForm *form() const { return m_form; }

    /// Type presets of a parameter (any IDL type may be typed).
    static QStringList typePresets();
    /// The table's columns (also the form's first fields).
    static QList<ItemField> columns();

private:
    QPointer<ComponentModel> m_model;
    ListEditor *m_list = nullptr;
    ItemForm *m_form = nullptr;
};

} // namespace Builder
