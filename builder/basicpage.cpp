// SPDX-License-Identifier: MIT
#include "basicpage.h"

#include "builderfieldrules.h"
#include "componentcommands.h"
#include "componentrules.h"
#include "kindchoices.h"
#include "profiletransfer.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QUndoStack>
#include <QVBoxLayout>

namespace Builder {

namespace {

using Field = BasicField;

constexpr Field AllFields[] = {
    Field::Name,          Field::Description,   Field::Version,       Field::Vendor,
    Field::Category,      Field::ComponentType, Field::ActivityType,  Field::MaxInstances,
    Field::ExecutionType, Field::ExecutionRate, Field::ComponentKind, Field::Abstract,
    Field::RtcType,
};

/// The text an editor shows; `modelValue` for the check box group, which shows no text.
QString editorText(const QWidget *editor, const QString &modelValue)
{
    if (const auto *line = qobject_cast<const QLineEdit *>(editor))
        return line->text();
    if (const auto *combo = qobject_cast<const QComboBox *>(editor))
        return combo->currentText();
    if (const auto *text = qobject_cast<const QPlainTextEdit *>(editor))
        return text->toPlainText();
    return modelValue;
}

/// The language kind the page shows: RTC Builder's C++ when the profile names none.
QString languageKind(const Profile::RtcProfile &profile)
{
    return profile.language ? profile.language->kind : QStringLiteral("C++");
}

QLabel *problemLabel(QWidget *parent)
{
    auto *message = new QLabel(parent);
    message->setWordWrap(true);
    message->setStyleSheet(QStringLiteral("color: #b3261e;"));
    message->hide();
    return message;
}

/// Marks an editor holding a problem with a reddish background, the usual inline cue.
void setInvalidLook(QWidget *editor, bool invalid)
{
    QPalette palette = editor->parentWidget()->palette();
    if (invalid) {
        // Line edits and editable combos paint Base; non-editable combos paint Button.
        palette.setColor(QPalette::Base, QColor(255, 228, 225));
        palette.setColor(QPalette::Button, QColor(255, 228, 225));
    }
    editor->setPalette(palette);
}

} // namespace

BasicPage::BasicPage(ComponentModel *model, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_model(model)
    , m_undoStack(undoStack)
{
    buildForm();
    refreshAll();
    connect(model, &ComponentModel::basicFieldChanged, this, [this](Field field) {
        refresh(field);
        refreshHeader();
    });
    connect(model, &ComponentModel::componentIdChanged, this, &BasicPage::refreshHeader);
    connect(model, &ComponentModel::profileReset, this, &BasicPage::refreshAll);
    connect(model, &ComponentModel::languageChanged, this, &BasicPage::refreshLanguages);
    // The composite rule depends on the ports, which other pages change.
    connect(model, &ComponentModel::changed, this, [this] { refresh(Field::Category); });
}

QWidget *BasicPage::editor(BasicField field) const
{
    return m_rows.value(int(field)).editor;
}

QCheckBox *BasicPage::componentKindBox(const QString &part) const
{
    return m_kindBoxes.value(part);
}

QCheckBox *BasicPage::languageBox(const QString &language) const
{
    return m_languageBoxes.value(language);
}

QString BasicPage::languageProblem() const
{
    return m_languageMessage->isHidden() ? QString() : m_languageMessage->text();
}

QString BasicPage::problem(BasicField field) const
{
    const QLabel *message = m_rows.value(int(field)).message;
    return message && !message->isHidden() ? message->text() : QString();
}

QStringList BasicPage::categoryPresets()
{
    return {
        QStringLiteral("Actuator"),
        QStringLiteral("Animation"),
        QStringLiteral("Autonomous Decentralized System"),
        QStringLiteral("Chatbot"),
        QStringLiteral("Computer Algebra System"),
        QStringLiteral("Controller"),
        QStringLiteral("Converter"),
        QStringLiteral("Database"),
        QStringLiteral("Educational Tool"),
        QStringLiteral("Game"),
        QStringLiteral("ImageProcessing"),
        QStringLiteral("Machine Learning"),
        QStringLiteral("Manipulator"),
        QStringLiteral("Manufacturing System"),
        QStringLiteral("Master-Slave"),
        QStringLiteral("Mobile Robot"),
        QStringLiteral("Motion Capture"),
        QStringLiteral("Navigation"),
        QStringLiteral("Nonholonomic System"),
        QStringLiteral("Office Suite"),
        QStringLiteral("Robot"),
        QStringLiteral("Sample"),
        QStringLiteral("Script Engine"),
        QStringLiteral("Sensor"),
        QStringLiteral("Simulator"),
        QStringLiteral("Speech Processing"),
        QStringLiteral("Streaming"),
        QStringLiteral("Test"),
        QStringLiteral("Transport System"),
        QStringLiteral("User Interface"),
        QStringLiteral("Vehicle"),
        QStringLiteral("Web Application Server"),
    };
}

QStringList BasicPage::executionTypePresets()
{
    return {QStringLiteral("PeriodicExecutionContext"), QStringLiteral("ExtTrigExecutionContext")};
}

void BasicPage::buildForm()
{
    m_content = new QWidget;
    auto *contentLayout = new QVBoxLayout(m_content);
    m_title = new QLabel(m_content);
    QFont titleFont = m_title->font();
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.4);
    titleFont.setBold(true);
    m_title->setFont(titleFont);
    m_componentId = new QLabel(m_content);
    m_componentId->setTextInteractionFlags(Qt::TextSelectableByMouse);
    contentLayout->addWidget(m_title);
    contentLayout->addWidget(m_componentId);
    contentLayout->addWidget(buildButtonRow());

    QFormLayout *component = addSection(tr("Component"));
    addLineEdit(component, Field::Name, tr("&Name:"), QString());
    addLineEdit(component, Field::Description, tr("&Description:"), tr("(none)"));
    addLineEdit(component, Field::Version, tr("&Version:"), QString());
    addLineEdit(component, Field::Vendor, tr("V&endor:"), QString());
    addComboBox(component, Field::Category, tr("&Category:"), categoryPresets(), true);
    addAbstractEdit(component);
    addLineEdit(component, Field::RtcType, tr("RTC t&ype:"), tr("(not set)"));

    QFormLayout *behaviour = addSection(tr("Behaviour"));
    addComboBox(behaviour, Field::ComponentType, tr("Component &type:"),
                Profile::rtcComponentTypes(), false);
    addComboBox(behaviour, Field::ActivityType, tr("&Activity type:"), Profile::rtcActivityTypes(),
                false);
    addKindBoxes(behaviour);
    addLineEdit(behaviour, Field::MaxInstances, tr("&Max instances:"), tr("(not set)"));

    QFormLayout *execution = addSection(tr("Execution Context"));
    addComboBox(execution, Field::ExecutionType, tr("E&xecution type:"), executionTypePresets(),
                true);
    addLineEdit(execution, Field::ExecutionRate, tr("Execution &rate (Hz):"), tr("(not set)"));
    QFormLayout *language = addSection(tr("Language"));
    addLanguageBoxes(language);
    contentLayout->addStretch(1);
    alignLabels({component, behaviour, execution, language});

    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_content);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);
}

QWidget *BasicPage::buildButtonRow()
{
    auto *row = new QWidget(m_content);
    auto *layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 4, 0, 4);
    m_generate = new QPushButton(tr("&Generate"), row);
    m_generate->setToolTip(tr("Generate the component's code from this profile"));
    auto *restore = new QPushButton(tr("Code &Restore..."), row);
    restore->setToolTip(tr("Put back generated files from a backup"));
    auto *clear = new QPushButton(tr("Clear &Backups"), row);
    clear->setToolTip(tr("Delete the backups made when generating over existing files"));
    m_generate->setObjectName(QStringLiteral("generateButton"));
    restore->setObjectName(QStringLiteral("codeRestoreButton"));
    clear->setObjectName(QStringLiteral("clearBackupsButton"));
    connect(m_generate, &QPushButton::clicked, this, &BasicPage::generateRequested);
    connect(restore, &QPushButton::clicked, this, &BasicPage::codeRestoreRequested);
    connect(clear, &QPushButton::clicked, this, &BasicPage::clearBackupsRequested);
    layout->addWidget(m_generate);
    layout->addWidget(restore);
    layout->addWidget(clear);
    layout->addStretch(1);
    layout->addWidget(buildTransferButtons(row));
    auto *box = new QWidget(m_content);
    auto *boxLayout = new QVBoxLayout(box);
    boxLayout->setContentsMargins(0, 0, 0, 0);
    boxLayout->addWidget(row);
    m_generationProblems = new QLabel(box);
    m_generationProblems->setObjectName(QStringLiteral("generationProblems"));
    m_generationProblems->setWordWrap(true);
    m_generationProblems->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_generationProblems->setStyleSheet(QStringLiteral("color: #b3261e;"));
    m_generationProblems->hide();
    boxLayout->addWidget(m_generationProblems);
    m_transferMessage = new QLabel(box);
    m_transferMessage->setObjectName(QStringLiteral("transferMessage"));
    m_transferMessage->setWordWrap(true);
    m_transferMessage->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_transferMessage->hide();
    boxLayout->addWidget(m_transferMessage);
    return box;
}

QWidget *BasicPage::buildTransferButtons(QWidget *parent)
{
    auto *buttons = new QWidget(parent);
    auto *layout = new QHBoxLayout(buttons);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *import = new QPushButton(tr("&Import..."), buttons);
    import->setToolTip(tr("Replace this component by the profile of an RTC.xml or YAML file"));
    import->setObjectName(QStringLiteral("importButton"));
    auto *exportButton = new QPushButton(tr("E&xport..."), buttons);
    exportButton->setToolTip(tr("Write this component's profile to an XML or YAML file"));
    exportButton->setObjectName(QStringLiteral("exportButton"));
    connect(import, &QPushButton::clicked, this, [this] { askTransferFile(true); });
    connect(exportButton, &QPushButton::clicked, this, [this] { askTransferFile(false); });
    layout->addWidget(import);
    layout->addWidget(exportButton);
    return buttons;
}

void BasicPage::askTransferFile(bool import)
{
    // A window-modal dialog that is not run by exec(): the event loop stays the application's.
    auto *dialog = new QFileDialog(this, import ? tr("Import Profile") : tr("Export Profile"));
    dialog->setObjectName(QStringLiteral("transferDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setOption(QFileDialog::DontUseNativeDialog);
    dialog->setNameFilter(ProfileTransfer::fileFilter());
    dialog->setAcceptMode(import ? QFileDialog::AcceptOpen : QFileDialog::AcceptSave);
    dialog->setFileMode(import ? QFileDialog::ExistingFile : QFileDialog::AnyFile);
    if (!import) {
        dialog->setDefaultSuffix(QStringLiteral("xml"));
        dialog->selectFile(QStringLiteral("RTC.xml"));
    }
    connect(dialog, &QFileDialog::fileSelected, this, [this, import](const QString &path) {
        if (import)
            importProfile(path);
        else
            exportProfile(path);
    });
    dialog->setWindowModality(Qt::WindowModal);
    dialog->show();
}

bool BasicPage::importProfile(const QString &path)
{
    if (!m_model)
        return false;
    Profile::Diagnostics problems;
    QUndoCommand *command = ProfileTransfer::importCommand(m_model, path, &problems);
    const QString name = QFileInfo(path).fileName();
    if (!command) {
        const bool failed = Profile::hasErrors(problems);
        showTransferResult(failed ? tr("Nothing was imported from %1:").arg(name)
                                  : tr("%1 holds the same component; nothing changed.").arg(name),
                           problems);
        if (failed)
            emit transferFailed(problems);
        return false;
    }
    m_undoStack->push(command);
    showTransferResult(tr("Imported %1 (Undo puts the previous component back).").arg(name),
                       problems);
    return true;
}

bool BasicPage::exportProfile(const QString &path)
{
    if (!m_model)
        return false;
    Profile::Diagnostics problems;
    if (!ProfileTransfer::exportProfile(m_model->profile(), path, &problems)) {
        showTransferResult(tr("Nothing was exported:"), problems);
        emit transferFailed(problems);
        return false;
    }
    showTransferResult(tr("Exported to %1.").arg(QDir::toNativeSeparators(path)), problems);
    return true;
}

QString BasicPage::transferMessage() const
{
    return m_transferMessage->isHidden() ? QString() : m_transferMessage->text();
}

void BasicPage::showTransferResult(const QString &text, const Profile::Diagnostics &problems)
{
    QStringList lines {text};
    for (const Profile::Diagnostic &d : problems)
        lines << d.toString();
    m_transferMessage->setText(lines.join(QLatin1Char('\n')));
    m_transferMessage->setStyleSheet(
        Profile::hasErrors(problems) ? QStringLiteral("color: #b3261e;") : QString());
    m_transferMessage->show();
}

void BasicPage::showGenerationProblems(const Profile::Diagnostics &problems)
{
    QStringList lines;
    for (const Profile::Diagnostic &d : problems)
        lines << (d.object.isEmpty() ? d.message
                                     : QStringLiteral("%1: %2").arg(d.object, d.message));
    m_generationProblems->setText(lines.isEmpty()
                                      ? QString()
                                      : tr("Cannot generate while these problems remain:\n%1")
                                            .arg(lines.join(QLatin1Char('\n'))));
    m_generationProblems->setVisible(!lines.isEmpty());
}

QString BasicPage::generationProblems() const
{
    return m_generationProblems->isHidden() ? QString() : m_generationProblems->text();
}

void BasicPage::alignLabels(const QList<QFormLayout *> &forms)
{
    // Each group has its own form; equal label widths line the fields up across the groups.
    QList<QWidget *> labels;
    int width = 0;
    for (QFormLayout *form : forms) {
        for (int row = 0; row < form->rowCount(); ++row) {
            if (QLayoutItem *item = form->itemAt(row, QFormLayout::LabelRole)) {
                labels << item->widget();
                width = qMax(width, item->widget()->sizeHint().width());
            }
        }
    }
    for (QWidget *label : labels)
        label->setMinimumWidth(width);
}

QFormLayout *BasicPage::addSection(const QString &title)
{
    auto *group = new QGroupBox(title, m_content);
    auto *form = new QFormLayout(group);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    group->setMaximumWidth(720);
    m_content->layout()->addWidget(group);
    return form;
}

void BasicPage::addLineEdit(QFormLayout *form, BasicField field, const QString &label,
                            const QString &placeholder)
{
    auto *edit = new QLineEdit;
    edit->setPlaceholderText(placeholder);
    // textEdited fires for the user's typing only, never for refreshes from the document.
    connect(edit, &QLineEdit::textEdited, this,
            [this, field](const QString &text) { userEdited(field, text); });
    addRow(form, field, label, edit);
}

void BasicPage::addComboBox(QFormLayout *form, BasicField field, const QString &label,
                            const QStringList &items, bool editable)
{
    auto *combo = new QComboBox;
    combo->setEditable(editable);
    combo->addItems(items);
    if (editable)
        combo->setInsertPolicy(QComboBox::NoInsert);
    connect(combo, &QComboBox::currentTextChanged, this, [this, field](const QString &text) {
        if (!m_updating)
            userEdited(field, text);
    });
    addRow(form, field, label, combo);
}

void BasicPage::addRow(QFormLayout *form, BasicField field, const QString &label, QWidget *editor)
{
    // The editor and its problem line share one cell, so the message sits right under it.
    auto *cell = new QWidget;
    auto *cellLayout = new QVBoxLayout(cell);
    cellLayout->setContentsMargins(0, 0, 0, 0);
    cellLayout->setSpacing(2);
    QLabel *message = problemLabel(cell);
    editor->setParent(cell);
    cellLayout->addWidget(editor);
    cellLayout->addWidget(message);
    form->addRow(label, cell);
    if (auto *buddy = qobject_cast<QLabel *>(form->labelForField(cell)))
        buddy->setBuddy(editor);
    m_rows.insert(int(field), Row {editor, message});
}

void BasicPage::addAbstractEdit(QFormLayout *form)
{
    auto *edit = new QPlainTextEdit;
    edit->setPlaceholderText(tr("(none)"));
    edit->setTabChangesFocus(true);
    // About four lines: room for a paragraph without pushing the other fields away.
    edit->setFixedHeight(edit->fontMetrics().lineSpacing() * 4 + 12);
    connect(edit, &QPlainTextEdit::textChanged, this, [this, edit] {
        if (!m_updating)
            userEdited(Field::Abstract, edit->toPlainText());
    });
    addRow(form, Field::Abstract, tr("A&bstract:"), edit);
}

QWidget *BasicPage::addCheckBoxes(const QStringList &names, const QStringList &labels,
                                  QHash<QString, QCheckBox *> *boxes,
                                  const std::function<void(const QString &, bool)> &toggled)
{
    auto *group = new QWidget;
    auto *layout = new QHBoxLayout(group);
    layout->setContentsMargins(0, 0, 0, 0);
    for (int i = 0; i < names.size(); ++i) {
        auto *box = new QCheckBox(labels.at(i), group);
        box->setObjectName(names.at(i));
        // clicked fires for the user only, never for refreshes from the model.
        connect(box, &QCheckBox::clicked, this,
                [toggled, name = names.at(i)](bool on) { toggled(name, on); });
        layout->addWidget(box);
        boxes->insert(names.at(i), box);
    }
    layout->addStretch(1);
    return group;
}

void BasicPage::addKindBoxes(QFormLayout *form)
{
    QWidget *group = addCheckBoxes(KindChoices::componentKindParts(),
                                   {tr("DataFlow"), tr("FSM"), tr("MultiMode")}, &m_kindBoxes,
                                   [this](const QString &part, bool on) { toggleKind(part, on); });
    addRow(form, Field::ComponentKind, tr("Component &kind:"), group);
}

void BasicPage::addLanguageBoxes(QFormLayout *form)
{
    const QStringList &names = KindChoices::languages();
    QWidget *group
        = addCheckBoxes(names, names, &m_languageBoxes,
                        [this](const QString &language, bool on) { toggleLanguage(language, on); });
    auto *cell = new QWidget;
    auto *cellLayout = new QVBoxLayout(cell);
    cellLayout->setContentsMargins(0, 0, 0, 0);
    cellLayout->setSpacing(2);
    group->setParent(cell);
    cellLayout->addWidget(group);
    m_languageMessage = problemLabel(cell);
    cellLayout->addWidget(m_languageMessage);
    form->addRow(tr("Generate for:"), cell);
}

void BasicPage::toggleKind(const QString &part, bool on)
{
    if (!m_model)
        return;
    const QString kind = m_model->basicField(Field::ComponentKind).value_or(QString());
    const QString changed = KindChoices::withComponentKind(kind, part, on);
    if (changed != kind)
        m_undoStack->push(new SetBasicFieldCommand(m_model, Field::ComponentKind, changed));
    else
        refresh(Field::ComponentKind); // a box the model does not follow goes back
}

void BasicPage::toggleLanguage(const QString &language, bool on)
{
    if (!m_model)
        return;
    const Profile::RtcProfile &profile = m_model->profile();
    Profile::RtcLanguage edited = profile.language.value_or(Profile::RtcLanguage());
    edited.kind = KindChoices::withLanguage(languageKind(profile), language, on);
    // No merge key: every click is its own undo step.
    if (edited != profile.language)
        m_undoStack->push(new SetLanguageCommand(m_model, edited));
}

void BasicPage::refreshLanguages()
{
    if (!m_model)
        return;
    const QString kind = languageKind(m_model->profile());
    for (auto it = m_languageBoxes.cbegin(); it != m_languageBoxes.cend(); ++it)
        it.value()->setChecked(KindChoices::hasLanguage(kind, it.key()));
    const QString problem = KindChoices::languageProblem(kind);
    m_languageMessage->setText(problem);
    m_languageMessage->setVisible(!problem.isEmpty());
}

void BasicPage::userEdited(BasicField field, const QString &text)
{
    if (!m_model || m_model->basicField(field).value_or(QString()) == text)
        return;
    std::optional<QString> value = text;
    if (ComponentModel::isOptional(field) && text.isEmpty())
        value = std::nullopt;
    m_undoStack->push(new SetBasicFieldCommand(m_model, field, value));
}

void BasicPage::refresh(BasicField field)
{
    const Row row = m_rows.value(int(field));
    if (!row.editor || !m_model)
        return;
    const QString value = m_model->basicField(field).value_or(QString());
    m_updating = true;
    showInEditor(row.editor, value);
    m_updating = false;
    showProblem(field, problemFor(field, editorText(row.editor, value)));
}

void BasicPage::showInEditor(QWidget *editor, const QString &value)
{
    if (auto *line = qobject_cast<QLineEdit *>(editor)) {
        if (line->text() != value)
            line->setText(value);
    } else if (auto *combo = qobject_cast<QComboBox *>(editor)) {
        // Equal text means the user is typing here: touching the combo would break the inline
        // completion's selection.
        if (combo->currentText() != value)
            showInComboBox(combo, value);
    } else if (auto *text = qobject_cast<QPlainTextEdit *>(editor)) {
        // Setting equal text would move the cursor of the user typing here.
        if (text->toPlainText() != value)
            text->setPlainText(value);
    } else {
        for (auto it = m_kindBoxes.cbegin(); it != m_kindBoxes.cend(); ++it)
            it.value()->setChecked(KindChoices::hasComponentKind(value, it.key()));
    }
}

void BasicPage::showInComboBox(QComboBox *combo, const QString &value)
{
    int index = combo->findText(value);
    // A value outside the list is shown as it is, never replaced by a list entry.
    if (index < 0 && !combo->isEditable()) {
        combo->addItem(value);
        index = combo->count() - 1;
    }
    if (index >= 0)
        combo->setCurrentIndex(index);
    else
        combo->setEditText(value);
}

void BasicPage::refreshAll()
{
    for (Field field : AllFields)
        refresh(field);
    refreshLanguages();
    refreshHeader();
}

void BasicPage::refreshHeader()
{
    if (!m_model)
        return;
    const QString name = m_model->basicField(Field::Name).value_or(QString());
    m_title->setText(name.isEmpty() ? tr("(unnamed component)") : name);
    m_componentId->setText(tr("Component id: %1").arg(m_model->componentId()));
}

void BasicPage::showProblem(BasicField field, const QString &text)
{
    const Row row = m_rows.value(int(field));
    row.message->setText(text);
    row.message->setVisible(!text.isEmpty());
    setInvalidLook(row.editor, !text.isEmpty());
    row.editor->setToolTip(text);
}

QString BasicPage::problemFor(BasicField field, const QString &text) const
{
    switch (field) {
    case Field::Name:
        return FieldRules::componentNameProblem(text);
    case Field::Category:
        if (const QString problem = FieldRules::requiredProblem(text); !problem.isEmpty())
            return problem;
        return m_model ? compositePortsProblem(m_model->profile()) : QString();
    case Field::Version:
    case Field::Vendor:
    case Field::ExecutionType:
        return FieldRules::requiredProblem(text);
    case Field::ComponentType:
        return FieldRules::enumerationProblem(text, Profile::rtcComponentTypes());
    case Field::ActivityType:
        return FieldRules::enumerationProblem(text, Profile::rtcActivityTypes());
    case Field::MaxInstances:
        return FieldRules::nonNegativeIntegerProblem(text);
    case Field::ExecutionRate:
        return FieldRules::nonNegativeNumberProblem(text);
    case Field::ComponentKind:
        return KindChoices::componentKindProblem(text);
    case Field::Description:
    case Field::Abstract:
    case Field::RtcType:
        break;
    }
    return {};
}

} // namespace Builder
