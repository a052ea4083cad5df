// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QListWidget;

namespace Builder {

class TypeCatalog;

/**
 * The small settings dialog of the IDL folders the type lists are read from: the bundled folder
 * (shown, fixed) and the user's folders (added and removed here). Accepting stores the folders
 * and reloads the catalog.
 */
class IdlSettingsDialog : public QDialog
{
    Q_OBJECT

public:
    explicit IdlSettingsDialog(TypeCatalog *catalog, QWidget *parent = nullptr);

    /// The user folders as listed.
    QStringList directories() const;
    /// Adds a folder to the list (the Add button asks for one).
    void addDirectory(const QString &directory);
    void removeSelected();

    void accept() override;

private:
    TypeCatalog *m_catalog;
    QListWidget *m_list;
};

/// A row with "IDL Folders..." and "Reload Types" buttons for pages that offer IDL types.
QWidget *createTypeCatalogButtons(TypeCatalog *catalog, QWidget *parent);

} // namespace Builder
