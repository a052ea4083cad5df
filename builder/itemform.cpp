// SPDX-License-Identifier: MIT
#include "itemform.h"

#include "itemcommands.h"

#include <QComboBox>
#include <QCompleter>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

void setInvalidLook(QWidget *editor, bool invalid)
{
    QPalette palette = editor->parentWidget()->palette();
    if (invalid) {
        palette.setColor(QPalette::Base, QColor(255, 228, 225));
        palette.setColor(QPalette::Button, QColor(255, 228, 225));
    }
    editor->setPalette(palette);
}

} // namespace

ItemForm::ItemForm(ComponentModel *model, QUndoStack *undoStack, Part part, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
    , m_part(part)
    , m_problems([part](const Profile::RtcProfile &profile, int index) {
        return itemProblems(profile, part, index);
    })
    , m_form(new QFormLayout(this))
{
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    connect(model, &ComponentModel::changed, this, &ItemForm::refresh);
    followListChanges();
    setEnabled(false);
}

void ItemForm::followListChanges()
{
    // The form addresses its element by position: keep pointing at the same one. This happens
    // before the change, so a list view that makes another element current afterwards passes
    // positions that are already right.
    connect(m_model, &ComponentModel::itemAboutToBeInserted, this, [this](Part part, int index) {
        if (part == m_part && m_index >= 0 && index <= m_index)
            ++m_index;
    });
    connect(m_model, &ComponentModel::itemAboutToBeRemoved, this, [this](Part part, int index) {
        if (part != m_part || m_index < 0)
            return;
        if (index == m_index)
            m_index = -1;
        else if (index < m_index)
            --m_index;
    });
    connect(m_model, &ComponentModel::itemAboutToBeMoved, this,
            [this](Part part, int from, int to) {
                if (part != m_part || m_index < 0)
                    return;
                if (m_index == from)
                    m_index = to;
                else if (from < m_index && to >= m_index)
                    --m_index;
                else if (from > m_index && to <= m_index)
                    ++m_index;
            });
    connect(m_model, &ComponentModel::profileReset, this, [this] { m_index = -1; });
}

void ItemForm::addSection(const QString &title)
{
    auto *label = new QLabel(QStringLiteral("<b>%1</b>").arg(title.toHtmlEscaped()), this);
    m_form->addRow(label);
}

QWidget *ItemForm::addField(const ItemField &field)
{
    auto *cell = new QWidget(this);
    auto *layout = new QVBoxLayout(cell);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    QWidget *editor = nullptr;
    if (field.choices) {
        auto *combo = new QComboBox(cell);
        combo->setEditable(field.editableChoices);
        combo->setInsertPolicy(QComboBox::NoInsert);
        // Long IDL names must not widen the form beyond its pane.
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(12);
        combo->addItems(field.choices());
        if (field.editableChoices) {
            // Long IDL type lists: match anywhere in the name while typing.
            combo->completer()->setFilterMode(Qt::MatchContains);
            combo->completer()->setCompletionMode(QCompleter::PopupCompletion);
        }
        connect(combo, &QComboBox::currentTextChanged, this,
                [this, key = field.key](const QString &t) {
                    if (!m_updating)
                        userEdited(key, t);
                });
        editor = combo;
    } else {
        auto *line = new QLineEdit(cell);
        connect(line, &QLineEdit::textEdited, this,
                [this, key = field.key](const QString &t) { userEdited(key, t); });
        editor = line;
    }
    editor->setObjectName(field.key);
    auto *message = new QLabel(cell);
    message->setWordWrap(true);
    message->setStyleSheet(QStringLiteral("color: #b3261e;"));
    message->hide();
    layout->addWidget(editor);
    layout->addWidget(message);
    m_form->addRow(field.label + QLatin1Char(':'), cell);
    if (auto *buddy = qobject_cast<QLabel *>(m_form->labelForField(cell)))
        buddy->setBuddy(editor);
    m_rows.append(Row {field, editor, message});
    return editor;
}

void ItemForm::setCurrentIndex(int index)
{
    m_index = index;
    refresh();
}

void ItemForm::refresh()
{
    const bool valid = m_model && m_index >= 0 && m_index < m_model->itemCount(m_part);
    if (!valid)
        m_index = -1;
    setEnabled(valid);
    std::optional<PartItem> item;
    FieldProblems problems;
    if (valid) {
        item = m_model->item(m_part, m_index);
        problems = m_problems(m_model->profile(), m_index);
    }
    m_updating = true;
    for (const Row &row : std::as_const(m_rows))
        showRow(row, item ? &*item : nullptr, problems);
    m_updating = false;
}

void ItemForm::showRow(const Row &row, const PartItem *item, const FieldProblems &problems)
{
    const QString value = item ? row.field.get(*item) : QString();
    if (row.field.key == m_editingKey) {
        // keep the user's text
    } else if (auto *line = qobject_cast<QLineEdit *>(row.editor)) {
        if (line->text() != value)
            line->setText(value);
    } else {
        auto *combo = static_cast<QComboBox *>(row.editor);
        // Equal text means the user is typing here; touching it would break the completion.
        if (combo->currentText() != value) {
            const int found = combo->findText(value);
            if (found >= 0)
                combo->setCurrentIndex(found);
            else if (combo->isEditable())
                combo->setEditText(value);
            else {
                combo->addItem(value);
                combo->setCurrentIndex(combo->count() - 1);
            }
        }
    }
    const QString problem = problems.value(row.field.key);
    row.message->setText(problem);
    row.message->setVisible(!problem.isEmpty());
    row.editor->setToolTip(problem);
    setInvalidLook(row.editor, !problem.isEmpty());
}

QWidget *ItemForm::editor(const QString &key) const
{
    for (const Row &row : m_rows) {
        if (row.field.key == key)
            return row.editor;
    }
    return nullptr;
}

QString ItemForm::problem(const QString &key) const
{
    for (const Row &row : m_rows) {
        if (row.field.key == key)
            return row.message->isHidden() ? QString() : row.message->text();
    }
    return {};
}

void ItemForm::reloadChoices()
{
    m_updating = true;
    for (const Row &row : std::as_const(m_rows)) {
        auto *combo = qobject_cast<QComboBox *>(row.editor);
        if (!combo || !row.field.choices)
            continue;
        const QString text = combo->currentText();
        combo->clear();
        combo->addItems(row.field.choices());
        combo->setEditText(text);
    }
    m_updating = false;
    refresh();
}

void ItemForm::userEdited(const QString &key, const QString &text)
{
    if (!m_model || m_index < 0)
        return;
    for (const Row &row : std::as_const(m_rows)) {
        if (row.field.key != key)
            continue;
        if (row.field.check) {
            const QString problem = row.field.check(text);
            if (!problem.isEmpty()) {
                row.message->setText(problem);
                row.message->show();
                row.editor->setToolTip(problem);
                setInvalidLook(row.editor, true);
                return;
            }
        }
        PartItem edited = m_model->item(m_part, m_index);
        row.field.set(edited, text);
        if (edited == m_model->item(m_part, m_index))
            return;
        // The field being typed in keeps its text as typed (a getter may normalise it).
        m_editingKey = key;
        m_undoStack->push(new EditItemCommand(
            m_model, m_part, m_index, edited, m_mergePrefix + key,
            tr("Change %1 of %2")
                .arg(row.field.label.toLower(), m_model->itemName(m_part, m_index))));
        m_editingKey.clear();
        return;
    }
}

} // namespace Builder
