// SPDX-License-Identifier: MIT
#include "languagepage.h"

#include "componentcommands.h"
#include "librarytablemodel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QTableView>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

QStringList splitList(const QString &text)
{
    QStringList items;
    for (const QString &item : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        if (!item.trimmed().isEmpty())
            items << item.trimmed();
    }
    return items;
}

std::optional<QString> optionalText(const QString &text, const std::optional<QString> &before)
{
    if (text.isEmpty() && !before)
        return std::nullopt;
    return text;
}

} // namespace

QStringList LanguagePage::languages()
{
    return {QStringLiteral("C++"), QStringLiteral("Python"), QStringLiteral("Java")};
}

LanguagePage::LanguagePage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_kind(new QComboBox(this))
    , m_libraryTable(new LibraryTableModel(model, undoStack, this))
    , m_libraries(new QTableView(this))
{
    m_kind->setEditable(true);
    m_kind->setInsertPolicy(QComboBox::NoInsert);
    m_kind->addItems(languages());
    connect(m_kind, &QComboBox::currentTextChanged, this, [this](const QString &text) {
        if (!m_updating)
            userEdited(Field::Kind, text);
    });
    auto *languageGroup = new QGroupBox(tr("Language"), this);
    auto *languageForm = new QFormLayout(languageGroup);
    languageForm->addRow(tr("&Language:"), m_kind);

    auto *environment = new QGroupBox(tr("Target environment"), this);
    auto *form = new QFormLayout(environment);
    const QList<QPair<Field, QString>> rows {
        {Field::LangVersion, tr("Language &version:")},
        {Field::Os, tr("&OS:")},
        {Field::OsVersions, tr("OS ve&rsions (comma separated):")},
        {Field::Cpus, tr("&CPUs (comma separated):")},
    };
    for (const auto &[field, label] : rows) {
        auto *edit = new QLineEdit(environment);
        connect(edit, &QLineEdit::textEdited, this,
                [this, field = field](const QString &text) { userEdited(field, text); });
        form->addRow(label, edit);
        m_edits << edit;
    }
    m_libraries->setModel(m_libraryTable);
    m_libraries->horizontalHeader()->setStretchLastSection(true);
    auto *add = new QPushButton(tr("Add Library"), environment);
    auto *remove = new QPushButton(tr("Remove Library"), environment);
    connect(add, &QPushButton::clicked, this,
            [this] { m_libraryTable->addLibrary(tr("library")); });
    connect(remove, &QPushButton::clicked, this,
            [this] { m_libraryTable->removeLibrary(m_libraries->currentIndex().row()); });
    auto *buttonRow = new QWidget(environment);
    auto *buttons = new QHBoxLayout(buttonRow);
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    form->addRow(tr("Libraries:"), m_libraries);
    form->addRow(QString(), buttonRow);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(languageGroup);
    layout->addWidget(environment, 1);
    connect(model, &ComponentModel::languageChanged, this, &LanguagePage::refresh);
    connect(model, &ComponentModel::profileReset, this, &LanguagePage::refresh);
    refresh();
}

QWidget *LanguagePage::editor(Field field) const
{
    return field == Field::Kind ? static_cast<QWidget *>(m_kind) : m_edits.at(int(field) - 1);
}

void LanguagePage::refresh()
{
    if (!m_model)
        return;
    const Profile::RtcLanguage language = languageForEditing(m_model->profile());
    const Profile::RtcTargetEnvironment &target = language.targets.first();
    m_updating = true;
    if (m_kind->currentText() != language.kind)
        m_kind->setEditText(language.kind);
    const QStringList texts {target.langVersion.value_or(QString()), target.os.value_or(QString()),
                             target.osVersions.join(QStringLiteral(", ")),
                             target.cpus.join(QStringLiteral(", "))};
    for (int i = 0; i < m_edits.size(); ++i) {
        // The list fields are shown normalised; leave the one being typed in alone.
        if (m_edits.at(i)->text() != texts.at(i) && !m_edits.at(i)->hasFocus())
            m_edits.at(i)->setText(texts.at(i));
    }
    m_updating = false;
}

void LanguagePage::userEdited(Field field, const QString &text)
{
    if (!m_model)
        return;
    Profile::RtcLanguage language = languageForEditing(m_model->profile());
    Profile::RtcTargetEnvironment &target = language.targets.first();
    const char *key = "kind";
    switch (field) {
    case Field::Kind:
        language.kind = text;
        break;
    case Field::LangVersion:
        target.langVersion = optionalText(text, target.langVersion);
        key = "langVersion";
        break;
    case Field::Os:
        target.os = optionalText(text, target.os);
        key = "os";
        break;
    case Field::OsVersions:
        target.osVersions = splitList(text);
        key = "osVersions";
        break;
    case Field::Cpus:
        target.cpus = splitList(text);
        key = "cpus";
        break;
    }
    // A target that is still empty is not written into the file.
    if (target == Profile::RtcTargetEnvironment()
        && !(m_model->profile().language && !m_model->profile().language->targets.isEmpty()))
        language.targets.clear();
    if (language == m_model->profile().language)
        return;
    m_undoStack->push(new SetLanguageCommand(m_model, language, QLatin1String(key)));
}

} // namespace Builder
