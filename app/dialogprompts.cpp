// SPDX-License-Identifier: MIT
#include "dialogprompts.h"

#include "saveprofiledialog.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>

namespace Studio {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(Studio::DialogPrompts)
};

QString xmlFilter()
{
    return Text::tr("Profile XML (*.xml)");
}

QString yamlFilter()
{
    return Text::tr("Profile YAML (*.yaml *.yml)");
}

} // namespace

DialogPrompts::DialogPrompts(QWidget *parent)
    : m_parent(parent)
{ }

UserPrompts::SaveChoice DialogPrompts::askSaveChanges(const QString &documentName)
{
    QMessageBox box(QMessageBox::Warning, Text::tr("Unsaved Changes"),
                    Text::tr("\"%1\" has unsaved changes.").arg(documentName),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_parent);
    box.setInformativeText(Text::tr("Do you want to save them before closing?"));
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save:
        return SaveChoice::Save;
    case QMessageBox::Discard:
        return SaveChoice::Discard;
    default:
        return SaveChoice::Cancel;
    }
}

QStringList DialogPrompts::askOpenFileNames(const QString &directory)
{
    const QString filters
        = Text::tr("Profiles (*.xml *.yaml *.yml)") + QStringLiteral(";;") + Text::tr("All files (*)");
    return QFileDialog::getOpenFileNames(m_parent, Text::tr("Open Profile"), directory, filters);
}

QString DialogPrompts::askSaveFileName(Profile::ProfileKind kind, const QString &suggestedPath)
{
    const QString title = kind == Profile::ProfileKind::Rts ? Text::tr("Save System Profile")
                                                            : Text::tr("Save Component Profile");
    QString selected = Profile::formatForFileName(suggestedPath) == Profile::FileFormat::Yaml
        ? yamlFilter()
        : xmlFilter();
    QString path = QFileDialog::getSaveFileName(m_parent, title, suggestedPath,
                                                xmlFilter() + QStringLiteral(";;") + yamlFilter(),
                                                &selected);
    // The format follows the extension, so a name typed without one gets the filter's.
    if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty())
        path += selected == yamlFilter() ? QStringLiteral(".yaml") : QStringLiteral(".xml");
    return path;
}

void DialogPrompts::showProblems(const QString &title, const QString &text,
                                 const Profile::Diagnostics &diagnostics)
{
    QMessageBox box(QMessageBox::Critical, title, text, QMessageBox::Ok, m_parent);
    QStringList lines;
    for (const Profile::Diagnostic &diagnostic : diagnostics)
        lines << diagnostic.toString();
    if (!lines.isEmpty())
        box.setDetailedText(lines.join(QLatin1Char('\n')));
    box.exec();
}

void DialogPrompts::showAbout()
{
    QMessageBox::about(
        m_parent, Text::tr("About RT Studio"),
        Text::tr("<h3>RT Studio %1</h3>"
           "<p>An IDE for OpenRTM-aist RT-Components: design components in the Builder, "
           "compose them into systems in the System Editor.</p>"
           "<p>Reads and writes RTC and RTS profiles (XML and YAML) as OpenRTP does.</p>"
           "<p>Licensed under the MIT license.</p>")
            .arg(QCoreApplication::applicationVersion()));
}

std::optional<SystemEditor::SystemProfileInfo>
DialogPrompts::askSystemProfileInfo(const SystemEditor::SystemProfileInfo &current,
                                    const QStringList &components)
{
    SystemEditor::SaveProfileDialog dialog(current, components, m_parent);
    if (dialog.exec() != QDialog::Accepted)
        return std::nullopt;
    return dialog.info();
}

QString DialogPrompts::askExportFileName(const QString &suggestedPath)
{
    const QString png = Text::tr("PNG image (*.png)");
    const QString svg = Text::tr("SVG drawing (*.svg)");
    QString selected = suggestedPath.endsWith(QLatin1String(".svg")) ? svg : png;
    QString path = QFileDialog::getSaveFileName(m_parent, Text::tr("Export Diagram"), suggestedPath,
                                                png + QStringLiteral(";;") + svg, &selected);
    if (!path.isEmpty() && QFileInfo(path).suffix().isEmpty())
        path += selected == svg ? QStringLiteral(".svg") : QStringLiteral(".png");
    return path;
}

} // namespace Studio
