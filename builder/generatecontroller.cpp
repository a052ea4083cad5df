// SPDX-License-Identifier: MIT
#include "generatecontroller.h"

#include "backups.h"
#include "codegenerator.h"
#include "componenteditor.h"
#include "componentmodel.h"
#include "idlsearchpath.h"
#include "idltypelibrary.h"
#include "installation.h"
#include "typecatalog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QSettings>
#include <QUrl>

using namespace Codegen;
using namespace Profile;

namespace Builder {

namespace {

const char BackupsKeptKey[] = "builder/generate/backupsKept";
const char TestComponentKey[] = "builder/generate/testComponent";
const char OutputFoldersGroup[] = "builder/generate/outputFolders/";

Diagnostic problem(const QString &file, const QString &message)
{
    return Diagnostic::error(file, 0, 0, message);
}

QString section(const QString &title, const QStringList &paths)
{
    if (paths.isEmpty())
        return {};
    QString text = QStringLiteral("%1 (%2):\n").arg(title).arg(paths.size());
    for (const QString &path : paths)
        text += QStringLiteral("  %1\n").arg(path);
    return text;
}

QString stampText(const QString &stamp)
{
    const QDateTime when = QDateTime::fromString(stamp, QStringLiteral("yyyyMMddHHmmss"));
    return when.isValid() ? when.toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) : stamp;
}

} // namespace

GenerateController::GenerateController(ComponentModel *model, TypeCatalog *types,
                                       GeneratePrompts *prompts, QObject *parent)
    : QObject(parent)
    , m_model(model)
    , m_types(types)
    , m_prompts(prompts)
    , m_profilePath([] { return QString(); })
    , m_clock([] { return QDateTime::currentDateTime(); })
{ }

GenerateController::GenerateController(ComponentModel *model, TypeCatalog *types,
                                       std::unique_ptr<GeneratePrompts> prompts, QObject *parent)
    : GenerateController(model, types, prompts.get(), parent)
{
    m_ownedPrompts = std::move(prompts);
}

GenerateController::~GenerateController() = default;

void GenerateController::connectEditor(ComponentEditor *editor)
{
    connect(editor, &ComponentEditor::generateRequested, this, &GenerateController::generate);
    connect(editor, &ComponentEditor::codeRestoreRequested, this, &GenerateController::restoreCode);
    connect(editor, &ComponentEditor::clearBackupsRequested, this,
            &GenerateController::clearBackups);
}

void GenerateController::setProfilePathProvider(std::function<QString()> provider)
{
    m_profilePath = provider ? std::move(provider) : [] { return QString(); };
}

QString GenerateController::settingsKey() const
{
    // The component id names the component across files and sessions; percent-encoding keeps
    // a '/' in a vendor or category from opening a settings group.
    QString id = m_model ? m_model->componentId() : QString();
    if (id.isEmpty() && m_model)
        id = m_model->profile().basicInfo.name;
    return QLatin1String(OutputFoldersGroup) + QString::fromLatin1(QUrl::toPercentEncoding(id));
}

QString GenerateController::outputFolder() const
{
    const QString remembered = QSettings().value(settingsKey()).toString();
    if (!remembered.isEmpty())
        return remembered;
    // An RTC.xml opened from a generated project (which keeps a copy of its profile) works there.
    const QString profilePath = m_profilePath();
    const QDir folder = QFileInfo(profilePath).dir();
    if (!profilePath.isEmpty() && folder.exists(QStringLiteral("CMakeLists.txt")))
        return folder.absolutePath();
    return {};
}

void GenerateController::setOutputFolder(const QString &folder)
{
    QSettings().setValue(settingsKey(), folder);
}

int GenerateController::backupsKept()
{
    bool ok = false;
    const int count = QSettings().value(QLatin1String(BackupsKeptKey)).toInt(&ok);
    return ok && count >= 0 ? count : Backups::DefaultKept;
}

void GenerateController::setBackupsKept(int count)
{
    QSettings().setValue(QLatin1String(BackupsKeptKey), std::max(count, 0));
}

bool GenerateController::testComponent()
{
    return QSettings().value(QLatin1String(TestComponentKey), false).toBool();
}

void GenerateController::setTestComponent(bool on)
{
    QSettings().setValue(QLatin1String(TestComponentKey), on);
}

QList<TargetLanguage> GenerateController::languagesOf(const RtcProfile &profile,
                                                      QStringList *unknown)
{
    QList<TargetLanguage> languages;
    const QString kind = profile.language ? profile.language->kind : QString();
    static const QRegularExpression separators(QStringLiteral("[,;]"));
    for (const QString &part : kind.split(separators, Qt::SkipEmptyParts)) {
        const QString name = part.trimmed();
        if (name.isEmpty())
            continue;
        const std::optional<TargetLanguage> language = targetLanguageFromString(name);
        if (!language)
            unknown->append(name);
        else if (!languages.contains(*language))
            languages << *language;
    }
    if (languages.isEmpty() && unknown->isEmpty())
        languages << TargetLanguage::Cpp;
    return languages;
}

QString GenerateController::summaryText(const WriteReport &report)
{
    QString text = section(tr("Created"), report.created) + section(tr("Merged"), report.merged)
        + section(tr("Overwritten"), report.overwritten) + section(tr("Kept"), report.kept)
        + section(tr("Unchanged"), report.unchanged) + section(tr("Backups made"), report.backups)
        + section(tr("Old backups deleted"), report.pruned)
        + section(tr("Warnings"), report.warnings);
    return text.trimmed();
}

QString GenerateController::suggestedFolder() const
{
    const QString remembered = outputFolder();
    if (!remembered.isEmpty())
        return remembered;
    const QString name = m_model ? m_model->profile().basicInfo.name : QString();
    const QString profilePath = m_profilePath();
    const QDir base = profilePath.isEmpty() ? QDir::home() : QFileInfo(profilePath).dir();
    // Next to a saved RTC.xml RTC Builder's project folder is the profile's own folder.
    if (!profilePath.isEmpty())
        return base.absolutePath();
    return base.filePath(name.isEmpty() ? QStringLiteral("rtc") : name);
}

ProjectWriter::DecisionCallback
GenerateController::decisionCallback(const QString &folder, const QList<GeneratedFile> &files) const
{
    auto fresh = std::make_shared<QHash<QString, QByteArray>>();
    for (const GeneratedFile &file : files)
        fresh->insert(file.path, file.content);
    auto forAll = std::make_shared<std::optional<FileDecision>>();
    GeneratePrompts *prompts = m_prompts;
    return [=](const QString &path) {
        if (*forAll)
            return **forAll;
        QFile existing(QDir(folder).filePath(path));
        QByteArray old;
        if (existing.open(QIODevice::ReadOnly))
            old = existing.readAll();
        const FileChoice choice = prompts->askFileDecision(path, old, fresh->value(path));
        if (choice.applyToAll)
            *forAll = choice.decision;
        return choice.decision;
    };
}

void GenerateController::fail(const QString &title, const QString &text,
                              const Diagnostics &problems)
{
    emit problemsFound(problems);
    m_prompts->showSummary(title, text, problems);
}

bool GenerateController::generate()
{
    if (!m_model)
        return false;
    const RtcProfile profile = m_model->profile();
    QStringList unknown;
    const QList<TargetLanguage> languages = languagesOf(profile, &unknown);
    if (!unknown.isEmpty()) {
        fail(tr("Generate"), tr("No code can be generated for this language."),
             {problem(m_profilePath(),
                      tr("unknown language '%1' (C++, Python or Java)").arg(unknown.join(", ")))});
        return false;
    }
    const std::optional<GenerateOptions> options
        = m_prompts->askGenerateOptions({suggestedFolder(), backupsKept(), testComponent()});
    if (!options || options->outputFolder.isEmpty())
        return false;
    setOutputFolder(options->outputFolder);
    setBackupsKept(options->backupsKept);
    setTestComponent(options->testComponent);

    const QString profilePath = m_profilePath();
    const QStringList leading
        = m_types ? m_types->directories() : QStringList {Codegen::Installation::bundledIdlDirectory()};
    const IdlTypeLibrary library(idlSearchDirs(
        profile, profilePath.isEmpty() ? QString() : QFileInfo(profilePath).absolutePath(),
        leading));
    CodeGenerator generator(profile, library.model());
    generator.setTestComponent(options->testComponent);
    Diagnostics problems;
    const std::optional<QList<GeneratedFile>> files = generator.generate(languages, &problems);
    if (!files) {
        // IDL problems explain a missing interface type, so they are shown with the failure.
        fail(tr("Generate"), tr("The code could not be generated."),
             library.diagnostics() + problems);
        return false;
    }
    ProjectWriter writer(options->outputFolder);
    writer.setDecisionCallback(decisionCallback(options->outputFolder, *files));
    writer.setBackupsKept(options->backupsKept);
    writer.setClock(m_clock);
    const std::optional<WriteReport> report = writer.write(*files, &problems);
    if (!report) {
        fail(tr("Generate"), tr("Nothing was written to %1.").arg(options->outputFolder), problems);
        return false;
    }
    emit generated(*report);
    m_prompts->showSummary(tr("Generate"),
                           tr("Generated into %1.").arg(options->outputFolder) + "\n\n"
                               + summaryText(*report),
                           problems);
    return true;
}

QString GenerateController::folderForBackups()
{
    const QString remembered = outputFolder();
    if (!remembered.isEmpty())
        return remembered;
    const std::optional<GenerateOptions> options
        = m_prompts->askGenerateOptions({suggestedFolder(), backupsKept(), testComponent()});
    if (!options || options->outputFolder.isEmpty())
        return {};
    setOutputFolder(options->outputFolder);
    setBackupsKept(options->backupsKept);
    setTestComponent(options->testComponent);
    return options->outputFolder;
}

bool GenerateController::restoreCode()
{
    const QString folder = folderForBackups();
    if (folder.isEmpty())
        return false;
    const QStringList stamps = Backups::stamps(folder);
    if (stamps.isEmpty()) {
        m_prompts->showSummary(tr("Code Restore"), tr("%1 has no backups.").arg(folder), {});
        return false;
    }
    const QString stamp = m_prompts->askRestoreStamp(folder, stamps);
    if (stamp.isEmpty())
        return false;
    const QStringList backups = Backups::filesOfSet(folder, stamp);
    Diagnostics problems;
    if (!Backups::restore(folder, stamp, &problems)) {
        fail(tr("Code Restore"), tr("The backup of %1 was not restored.").arg(stampText(stamp)),
             problems);
        return false;
    }
    QStringList restored;
    for (const QString &backup : backups)
        restored << QDir(folder).relativeFilePath(backup.left(backup.size() - stamp.size()));
    m_prompts->showSummary(tr("Code Restore"),
                           tr("Restored the files of %1; the replaced files are now that "
                              "backup, so restoring it again undoes this.")
                                   .arg(stampText(stamp))
                               + "\n\n" + section(tr("Restored"), restored).trimmed(),
                           {});
    return true;
}

bool GenerateController::clearBackups()
{
    const QString folder = folderForBackups();
    if (folder.isEmpty())
        return false;
    int count = 0;
    for (const QString &stamp : Backups::stamps(folder))
        count += int(Backups::filesOfSet(folder, stamp).size());
    if (count == 0) {
        m_prompts->showSummary(tr("Clear Backups"), tr("%1 has no backups.").arg(folder), {});
        return false;
    }
    if (!m_prompts->confirmClearBackups(folder, count))
        return false;
    const int removed = Backups::clear(folder);
    Diagnostics problems;
    if (removed < count)
        problems << problem(folder,
                            tr("%1 backup files could not be deleted").arg(count - removed));
    m_prompts->showSummary(tr("Clear Backups"), tr("Deleted %1 backup files.").arg(removed),
                           problems);
    if (!problems.isEmpty())
        emit problemsFound(problems);
    return removed > 0;
}

} // namespace Builder
