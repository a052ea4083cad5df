// SPDX-License-Identifier: MIT
#include "librarytablemodel.h"

#include "componentcommands.h"

#include <QUndoStack>

namespace Builder {

Profile::RtcLanguage languageForEditing(const Profile::RtcProfile &profile)
{
    Profile::RtcLanguage language;
    language.kind = QStringLiteral("C++");
    language = profile.language.value_or(language);
    if (language.targets.isEmpty())
        language.targets.append(Profile::RtcTargetEnvironment());
    return language;
}

LibraryTableModel::LibraryTableModel(ComponentModel *model, QUndoStack *undoStack, QObject *parent)
    : QAbstractTableModel(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_rows(int(libraries().size()))
{
    connect(model, &ComponentModel::languageChanged, this, &LibraryTableModel::sync);
    connect(model, &ComponentModel::profileAboutToBeReset, this, [this] { beginResetModel(); });
    connect(model, &ComponentModel::profileReset, this, [this] {
        m_rows = int(libraries().size());
        endResetModel();
    });
}

QList<Profile::RtcLibrary> LibraryTableModel::libraries() const
{
    if (!m_model || !m_model->profile().language || m_model->profile().language->targets.isEmpty())
        return {};
    return m_model->profile().language->targets.first().libraries;
}

void LibraryTableModel::sync()
{
    // Libraries are only appended or removed one at a time; anything else is a reset.
    const int rows = int(libraries().size());
    if (rows == m_rows) {
        if (rows > 0)
            emit dataChanged(index(0, 0), index(rows - 1, ColumnCount - 1));
        return;
    }
    beginResetModel();
    m_rows = rows;
    endResetModel();
}

int LibraryTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : m_rows;
}

int LibraryTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant LibraryTableModel::data(const QModelIndex &index, int role) const
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid)
        || (role != Qt::DisplayRole && role != Qt::EditRole))
        return {};
    const Profile::RtcLibrary library = libraries().value(index.row());
    switch (index.column()) {
    case NameColumn:
        return library.name;
    case VersionColumn:
        return library.version.value_or(QString());
    default:
        break;
    }
    return library.other.value_or(QString());
}

bool LibraryTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!checkIndex(index, CheckIndexOption::IndexIsValid) || role != Qt::EditRole || !m_model)
        return false;
    Profile::RtcLanguage language = languageForEditing(m_model->profile());
    Profile::RtcLibrary &library = language.targets.first().libraries[index.row()];
    const QString text = value.toString();
    if (index.column() == NameColumn)
        library.name = text;
    else if (index.column() == VersionColumn)
        library.version = text;
    else
        library.other = text;
    if (language == m_model->profile().language)
        return false;
    m_undoStack->push(new SetLanguageCommand(m_model, language));
    return true;
}

Qt::ItemFlags LibraryTableModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    return Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable;
}

QVariant LibraryTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (role != Qt::DisplayRole || orientation != Qt::Horizontal)
        return {};
    switch (section) {
    case NameColumn:
        return tr("Library");
    case VersionColumn:
        return tr("Version");
    default:
        break;
    }
    return tr("Other");
}

void LibraryTableModel::addLibrary(const QString &name)
{
    Profile::RtcLanguage language = languageForEditing(m_model->profile());
    Profile::RtcLibrary library;
    library.name = name;
    language.targets.first().libraries.append(library);
    m_undoStack->push(new SetLanguageCommand(m_model, language));
}

void LibraryTableModel::removeLibrary(int row)
{
    Profile::RtcLanguage language = languageForEditing(m_model->profile());
    if (row < 0 || row >= language.targets.first().libraries.size())
        return;
    language.targets.first().libraries.removeAt(row);
    m_undoStack->push(new SetLanguageCommand(m_model, language));
}

} // namespace Builder
