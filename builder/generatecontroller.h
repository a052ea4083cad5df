// SPDX-License-Identifier: MIT
#pragma once

#include "diagnostic.h"
#include "generateprompts.h"
#include "projectwriter.h"
#include "rtcprofile.h"
#include "targetlanguage.h"

#include <QDateTime>
#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>

namespace Builder {

class ComponentEditor;
class ComponentModel;
class TypeCatalog;

/**
 * RTC Builder's Generate, Code restore and Clear backups for one component.
 *
 * Generate renders the component's project (languages from the profile's `rtc:Language @kind`)
 * in memory and writes it with Codegen::ProjectWriter into the output folder the user picks
 * (remembered per component id in QSettings). For every existing file that differs the user
 * chooses keep / merge / overwrite (optionally for all remaining files); merged and overwritten
 * files are backed up first, and only the newest backupsKept() backups of a file stay.
 * Code restore swaps a chosen backup set back; Clear backups deletes all backups after asking.
 * Every question and the summary go through GeneratePrompts.
 */
class GenerateController : public QObject
{
    Q_OBJECT

public:
    /// `types` null: the bundled OpenRTM IDL only. `prompts` must outlive the controller.
    GenerateController(ComponentModel *model, TypeCatalog *types, GeneratePrompts *prompts,
                       QObject *parent = nullptr);
    /// The same, owning its prompts.
    GenerateController(ComponentModel *model, TypeCatalog *types,
                       std::unique_ptr<GeneratePrompts> prompts, QObject *parent = nullptr);
    ~GenerateController() override;

    /// Runs generate(), restoreCode() and clearBackups() on the editor's requests.
    void connectEditor(ComponentEditor *editor);
    /// The path of the profile's file (its folder and idl/ are searched for IDL); empty: unsaved.
    void setProfilePathProvider(std::function<QString()> provider);
    /// The time stamped on backups (default: now).
    void setClock(std::function<QDateTime()> clock) { m_clock = std::move(clock); }

    /// The output folder remembered for this component; empty when none yet.
    QString outputFolder() const;
    void setOutputFolder(const QString &folder);
    /// Backups kept per generated file (a setting shared by all components, default 3).
    static int backupsKept();
    static void setBackupsKept(int count);
    /// Whether Generate also writes the C++ test component (shared by all components, default
    /// off).
    static bool testComponent();
    static void setTestComponent(bool on);

    /**
     * The languages named by the profile's `rtc:Language @kind` (several may be separated by
     * `,` or `;`); C++ when the profile names none, as RTC Builder defaults to it. Kinds no
     * generator knows are appended to `unknown`.
     */
    static QList<Codegen::TargetLanguage> languagesOf(const Profile::RtcProfile &profile,
                                                      QStringList *unknown);
    /// The summary of a write, one section per outcome with the relative paths.
    static QString summaryText(const Codegen::WriteReport &report);

public slots:
    /// Asks for the folder, generates and writes; false when cancelled or failed.
    bool generate();
    /// Asks for a backup set of the output folder and swaps it back; false when none restored.
    bool restoreCode();
    /// Asks, then deletes every backup below the output folder; false when nothing deleted.
    bool clearBackups();

signals:
    /// A Generate wrote its files.
    void generated(const Codegen::WriteReport &report);
    /// An action failed or met problems (also shown in the summary).
    void problemsFound(const Profile::Diagnostics &problems);

private:
    QString settingsKey() const;
    QString suggestedFolder() const;
    QString folderForBackups();
    Codegen::ProjectWriter::DecisionCallback
    decisionCallback(const QString &folder, const QList<Codegen::GeneratedFile> &files) const;
    void fail(const QString &title, const QString &text, const Profile::Diagnostics &problems);

    QPointer<ComponentModel> m_model;
    QPointer<TypeCatalog> m_types;
    std::unique_ptr<GeneratePrompts> m_ownedPrompts;
    GeneratePrompts *m_prompts;
    std::function<QString()> m_profilePath;
    std::function<QDateTime()> m_clock;
};

} // namespace Builder

Q_DECLARE_METATYPE(Codegen::WriteReport)
