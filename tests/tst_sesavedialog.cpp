// SPDX-License-Identifier: MIT
// The "profile information" asked when a system is saved: the dialog, its undoable application
// and the save flow of the application through its prompt interface.
#include "documentcontroller.h"
#include "profileio.h"
#include "rtsdocument.h"
#include "saveprofiledialog.h"
#include "systemmodel.h"
#include "userprompts.h"

#include <QDialogButtonBox>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QFileInfo>
#include <QUndoCommand>
#include <QUndoStack>

#include <memory>

using namespace SystemEditor;
using namespace Studio;

namespace {

/// Answers the profile-information question from a script and records what it was shown.
class ScriptedPrompts : public UserPrompts
{
public:
    std::optional<SystemProfileInfo> answer;
    QString saveFileName;
    QList<SystemProfileInfo> asked;
    QStringList askedComponents;
    int problemsShown = 0;

    SaveChoice askSaveChanges(const QString &) override { return SaveChoice::Cancel; }
    QStringList askOpenFileNames(const QString &) override { return {}; }
    QString askSaveFileName(Profile::ProfileKind, const QString &) override
    {
        return saveFileName;
    }
    void showProblems(const QString &, const QString &, const Profile::Diagnostics &) override
    {
        ++problemsShown;
    }
    void showAbout() override { }
    std::optional<SystemProfileInfo> askSystemProfileInfo(const SystemProfileInfo &current,
                                                          const QStringList &components) override
    {
        asked << current;
        askedComponents = components;
        return answer;
    }
};

Profile::RtsComponent component(const QString &name, bool required)
{
    Profile::RtsComponent c;
    c.id = QStringLiteral("RTC:Test:demo:%1:1.0.0").arg(name);
    c.pathUri = QStringLiteral("localhost/%1.rtc").arg(name);
    c.instanceName = name;
    c.isRequired = required ? QStringLiteral("true") : QStringLiteral("false");
    return c;
}

Profile::RtsProfile twoComponentSystem()
{
    Profile::RtsProfile profile;
    profile.id = QStringLiteral("RTSystem:Acme:Demo:1.0");
    profile.version = QStringLiteral("0.2");
    profile.creationDate = QStringLiteral("2026-01-01T00:00:00");
    profile.updateDate = QStringLiteral("2026-01-01T00:00:00");
    profile.components << component(QStringLiteral("Camera0"), true)
                       << component(QStringLiteral("Viewer0"), false);
    return profile;
}

SystemProfileInfo editedInfo(const SystemProfileInfo &from)
{
    SystemProfileInfo info = from;
    info.vendor = QStringLiteral("Robotics");
    info.systemName = QStringLiteral("Vision");
    info.version = QStringLiteral("2.1");
    info.abstract = QStringLiteral("Camera to viewer");
    info.requiredComponents = {QStringLiteral("Viewer0")};
    return info;
}

std::optional<Profile::RtsProfile> loadSaved(const QString &path)
{
    Profile::Diagnostics diagnostics;
    const std::optional<Profile::LoadedProfile> loaded = Profile::loadProfileFile(path, &diagnostics);
    return loaded ? loaded->rts : std::nullopt;
}

bool isRequired(const SystemModel &model, const QString &name)
{
    return model.component(name)->isRequiredValue();
}

} // namespace

class TestSaveDialog : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void dialogIsPrefilledFromTheModel()
    {
        SystemModel model;
        model.setProfile(twoComponentSystem());
        SaveProfileDialog dialog(model.systemInfo(), model.componentIds());
        QCOMPARE(dialog.findChild<QLineEdit *>(QStringLiteral("vendorEdit"))->text(),
                 QStringLiteral("Acme"));
        QCOMPARE(dialog.findChild<QLineEdit *>(QStringLiteral("systemNameEdit"))->text(),
                 QStringLiteral("Demo"));
        QCOMPARE(dialog.findChild<QLineEdit *>(QStringLiteral("versionEdit"))->text(),
                 QStringLiteral("1.0"));
        auto *list = dialog.findChild<QListWidget *>(QStringLiteral("requiredList"));
        QCOMPARE(list->count(), 2);
        QCOMPARE(list->item(0)->text(), QStringLiteral("Camera0"));
        QCOMPARE(list->item(0)->checkState(), Qt::Checked);
        QCOMPARE(list->item(1)->checkState(), Qt::Unchecked);
        QCOMPARE(dialog.info(), model.systemInfo());
    }

    void typingAndTickingChangeTheInfo()
    {
        SystemModel model;
        model.setProfile(twoComponentSystem());
        SaveProfileDialog dialog(model.systemInfo(), model.componentIds());
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto *name = dialog.findChild<QLineEdit *>(QStringLiteral("systemNameEdit"));
        name->selectAll();
        QTest::keyClicks(name, QStringLiteral("Vision"));
        QTest::keyClicks(dialog.findChild<QPlainTextEdit *>(QStringLiteral("abstractEdit")),
                         QStringLiteral("About it"));
        QVERIFY(dialog.setRequired(QStringLiteral("Viewer0"), true));
        QVERIFY(!dialog.setRequired(QStringLiteral("Nobody"), true));
        const SystemProfileInfo info = dialog.info();
        QCOMPARE(info.systemId(), QStringLiteral("RTSystem:Acme:Vision:1.0"));
        QCOMPARE(info.abstract, std::optional<QString>(QStringLiteral("About it")));
        QCOMPARE(info.requiredComponents,
                 (QSet<QString> {QStringLiteral("Camera0"), QStringLiteral("Viewer0")}));
        QCOMPARE(info.creationDate, model.systemInfo().creationDate);
    }

    void okIsDisabledWhileThePartsAreUnacceptable_data()
    {
        QTest::addColumn<QString>("vendor");
        QTest::addColumn<bool>("acceptable");
        QTest::newRow("fine") << QStringLiteral("Acme") << true;
        QTest::newRow("empty") << QString() << false;
        QTest::newRow("colon") << QStringLiteral("Ac:me") << false;
    }

    void okIsDisabledWhileThePartsAreUnacceptable()
    {
        QFETCH(QString, vendor);
        QFETCH(bool, acceptable);
        SystemModel model;
        model.setProfile(twoComponentSystem());
        SaveProfileDialog dialog(model.systemInfo(), model.componentIds());
        dialog.findChild<QLineEdit *>(QStringLiteral("vendorEdit"))->setText(vendor);
        QPushButton *ok
            = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
        QCOMPARE(ok->isEnabled(), acceptable);
    }

    void okAcceptsAndCancelRejects()
    {
        SystemModel model;
        model.setProfile(twoComponentSystem());
        for (const auto button : {QDialogButtonBox::Ok, QDialogButtonBox::Cancel}) {
            SaveProfileDialog dialog(model.systemInfo(), model.componentIds());
            dialog.show();
            QTest::mouseClick(dialog.findChild<QDialogButtonBox *>()->button(button),
                              Qt::LeftButton);
            QCOMPARE(dialog.result(), button == QDialogButtonBox::Ok ? int(QDialog::Accepted)
                                                                     : int(QDialog::Rejected));
        }
    }

    void applyCommandIsOneUndoStep()
    {
        SystemModel model;
        model.setProfile(twoComponentSystem());
        const Profile::RtsProfile a = model.profile();
        QVERIFY(!SaveProfileDialog::applyCommand(&model, model.systemInfo()));

        QUndoStack stack;
        stack.push(SaveProfileDialog::applyCommand(&model, editedInfo(model.systemInfo())));
        QCOMPARE(stack.count(), 1);
        const Profile::RtsProfile b = model.profile();
        QCOMPARE(b.id, QStringLiteral("RTSystem:Robotics:Vision:2.1"));
        QCOMPARE(b.abstract, std::optional<QString>(QStringLiteral("Camera to viewer")));
        QVERIFY(!isRequired(model, QStringLiteral("Camera0")));
        QVERIFY(isRequired(model, QStringLiteral("Viewer0")));
        stack.undo();
        QCOMPARE(model.profile(), a);
        stack.redo();
        QCOMPARE(model.profile(), b);
    }

    void saveAsksAppliesAndWrites()
    {
        QTemporaryDir dir;
        ScriptedPrompts prompts;
        DocumentController controller(&prompts);
        RtsDocument *document = controller.newSystem();
        document->model()->setProfile(twoComponentSystem());
        prompts.answer = editedInfo(document->model()->systemInfo());
        prompts.saveFileName = dir.filePath(QStringLiteral("vision.xml"));

        QVERIFY(controller.saveAs(document));
        QCOMPARE(prompts.asked.size(), 1);
        QCOMPARE(prompts.asked.first().systemName, QStringLiteral("Demo"));
        QCOMPARE(prompts.askedComponents,
                 (QStringList {QStringLiteral("Camera0"), QStringLiteral("Viewer0")}));
        QCOMPARE(document->undoStack()->count(), 1);
        QVERIFY(!document->isModified());

        const std::optional<Profile::RtsProfile> saved = loadSaved(prompts.saveFileName);
        QVERIFY(saved);
        QCOMPARE(saved->id, QStringLiteral("RTSystem:Robotics:Vision:2.1"));
        QCOMPARE(saved->abstract, std::optional<QString>(QStringLiteral("Camera to viewer")));
        QCOMPARE(saved->components.at(0).isRequired, QStringLiteral("false"));
        QCOMPARE(saved->components.at(1).isRequired, QStringLiteral("true"));

        // Undo takes the edit back like any other and makes the document modified again.
        document->undoStack()->undo();
        QCOMPARE(document->profile().id, QStringLiteral("RTSystem:Acme:Demo:1.0"));
        QVERIFY(document->isModified());
    }

    void plainSaveAsksToo()
    {
        QTemporaryDir dir;
        ScriptedPrompts prompts;
        DocumentController controller(&prompts);
        RtsDocument *document = controller.newSystem();
        document->model()->setProfile(twoComponentSystem());
        prompts.answer = document->model()->systemInfo();
        QVERIFY(controller.saveAs(document, dir.filePath(QStringLiteral("demo.xml"))));
        QCOMPARE(prompts.asked.size(), 1);
        QCOMPARE(document->undoStack()->count(), 0); // an unchanged answer is no edit

        prompts.answer = editedInfo(document->model()->systemInfo());
        QVERIFY(controller.save(document));
        QCOMPARE(prompts.asked.size(), 2);
        QCOMPARE(document->undoStack()->count(), 1);
        QCOMPARE(document->filePath(), dir.filePath(QStringLiteral("demo.xml")));
        const std::optional<Profile::RtsProfile> saved = loadSaved(document->filePath());
        QVERIFY(saved);
        QCOMPARE(saved->id, QStringLiteral("RTSystem:Robotics:Vision:2.1"));
    }

    void cancelSavesNothing()
    {
        QTemporaryDir dir;
        ScriptedPrompts prompts;
        DocumentController controller(&prompts);
        RtsDocument *document = controller.newSystem();
        document->model()->setProfile(twoComponentSystem());
        prompts.answer = std::nullopt;
        const QString path = dir.filePath(QStringLiteral("never.xml"));
        QVERIFY(!controller.saveAs(document, path));
        QCOMPARE(prompts.asked.size(), 1);
        QVERIFY(!QFileInfo::exists(path));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("RTCs"))));
        QCOMPARE(document->undoStack()->count(), 0);
        QCOMPARE(document->profile().id, QStringLiteral("RTSystem:Acme:Demo:1.0"));
        QVERIFY(document->isUntitled());
        QCOMPARE(prompts.problemsShown, 0);
    }
};

QTEST_MAIN(TestSaveDialog)
#include "tst_sesavedialog.moc"
