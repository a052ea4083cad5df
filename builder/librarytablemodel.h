// SPDX-License-Identifier: MIT
#pragma once

#include "componentmodel.h"

#include <QAbstractTableModel>
#include <QPointer>

class QUndoStack;

namespace Builder {

/**
 * The libraries of the component's first target environment (name, version, other) as a table;
 * editing, adding and removing push SetLanguageCommand.
 */
class LibraryTableModel : public QAbstractTableModel
{
    Q_OBJECT

public:
    enum Column { NameColumn, VersionColumn, OtherColumn, ColumnCount };

    LibraryTableModel(ComponentModel *model, QUndoStack *undoStack, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    void addLibrary(const QString &name);
    void removeLibrary(int row);

private:
    QList<Profile::RtcLibrary> libraries() const;
    void sync();

    QPointer<ComponentModel> m_model;
    QUndoStack *m_undoStack;
    int m_rows = 0; ///< as last reported to views
};

/// The component's language, or C++ when it has none; with at least one target environment.
Profile::RtcLanguage languageForEditing(const Profile::RtcProfile &profile);

} // namespace Builder
