// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QAbstractItemModel>
#include <QPointer>

namespace Builder {

/**
 * Service ports and their interfaces as a tree (port → interfaces) with two columns: the name,
 * and the port's position or the interface's direction and type. Problems are shown as a reddish
 * background with the reason as tool tip. Read-only; the Service Ports page edits through forms.
 */
class ServicePortTreeModel : public QAbstractItemModel
{
    Q_OBJECT

public:
    enum Column { NameColumn, DetailColumn, ColumnCount };

    explicit ServicePortTreeModel(ComponentModel *model, QObject *parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    /// The port of an index (its own, or its interface's); -1 for none.
    static int portOf(const QModelIndex &index);
    /// The interface of an index; -1 for a port row.
    static int interfaceOf(const QModelIndex &index);
    /// The index of a port, or of one of its interfaces.
    QModelIndex indexFor(int port, int interface = -1) const;

private:
    void rememberShape();
    void onItemChanged(Part part, int index);

    QPointer<ComponentModel> m_model;
    QList<int> m_interfaceCounts; ///< per port, as last reported to views
};

} // namespace Builder
