// SPDX-License-Identifier: MIT
#include "generatedialogprompts.h"

#include "buildcontroller.h"
#include "coderestoredialog.h"
#include "componenteditor.h"
#include "generatecontroller.h"
#include "generateoptionsdialog.h"
#include "regenerationdialog.h"

#include <QDir>
#include <QMessageBox>

namespace Builder {

GenerateDialogPrompts::GenerateDialogPrompts(QWidget *parent)
    : m_parent(parent)
{ }

std::optional<GenerateOptions>
GenerateDialogPrompts::askGenerateOptions(const GenerateOptions &current)
{
    GenerateOptionsDialog dialog(current, m_parent);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return dialog.options();
}

FileChoice GenerateDialogPrompts::askFileDecision(const QString &relativePath,
                                                  const QByteArray &existing,
                                                  const QByteArray &fresh)
{
    RegenerationDialog dialog(relativePath, existing, fresh, m_parent);
    dialog.exec();
    return dialog.choice();
}

QString GenerateDialogPrompts::askRestoreStamp(const QString &projectDir, const QStringList &stamps)
{
    CodeRestoreDialog dialog(projectDir, stamps, m_parent);
    return dialog.exec() == QDialog::Accepted ? dialog.selectedStamp() : QString();
}

bool GenerateDialogPrompts::confirmClearBackups(const QString &projectDir, int count)
{
    return QMessageBox::question(m_parent, QObject::tr("Clear Backups"),
                                 QObject::tr("Delete all %1 backup files of generated code in "
                                             "%2? They cannot be restored afterwards.")
                                     .arg(count)
                                     .arg(QDir::toNativeSeparators(projectDir)),
                                 QMessageBox::Yes | QMessageBox::No, QMessageBox::No)
        == QMessageBox::Yes;
}

void GenerateDialogPrompts::showSummary(const QString &title, const QString &text,
                                        const Profile::Diagnostics &problems)
{
    if (m_quiet && m_quiet() && title == GenerateController::tr("Generate"))
        return;
    QMessageBox box(problems.isEmpty() ? QMessageBox::Information : QMessageBox::Warning, title,
                    text.section(QLatin1Char('\n'), 0, 0), QMessageBox::Ok, m_parent);
    QStringList details;
    const QString rest = text.section(QLatin1Char('\n'), 1).trimmed();
    // A short file list is shown at once; a long one would make the box taller than the screen.
    if (rest.count(QLatin1Char('\n')) < 20)
        box.setInformativeText(rest);
    else
        details << rest;
    for (const Profile::Diagnostic &d : problems)
        details << d.toString();
    if (!details.isEmpty())
        box.setDetailedText(details.join(QLatin1Char('\n')));
    box.exec();
}

GenerateController *installGenerateController(ComponentEditor *editor,
                                              std::function<QString()> profilePath)
{
    auto prompts = std::make_unique<GenerateDialogPrompts>(editor);
    const QPointer<ComponentEditor> target(editor);
    prompts->setGenerateSummaryQuiet([target] { return target && target->reportsGeneration(); });
    auto *controller = new GenerateController(editor->model(), editor->typeCatalog(),
                                              std::move(prompts), editor);
    controller->setProfilePathProvider(std::move(profilePath));
    controller->connectEditor(editor);
    QObject::connect(controller, &GenerateController::generated, editor,
                     [editor, controller](const Codegen::WriteReport &report) {
                         editor->reportGeneration(
                             GenerateOutcome::fromReport(controller->outputFolder(), report));
                     });
    QObject::connect(controller, &GenerateController::problemsFound, editor,
                     [editor](const Profile::Diagnostics &problems) {
                         editor->reportGeneration(GenerateOutcome::failed(problems));
                     });
    installBuildController(editor, controller);
    return controller;
}

} // namespace Builder
