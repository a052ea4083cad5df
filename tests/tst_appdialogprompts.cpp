// SPDX-License-Identifier: MIT
// The real dialogs behind UserPrompts: each answer maps to the right choice, file names get the
// extension of the chosen format, problem reports carry their diagnostics.
#include "dialogprompts.h"
#include "modalguard.h"

#include <QApplication>
#include <QFileDialog>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

using namespace Studio;
using Expected = GuiTest::ModalGuard::Expected;

class TestAppDialogPrompts : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void saveChangesButtons_data();
    void saveChangesButtons();
    void saveFileNameGetsFormatExtension_data();
    void saveFileNameGetsFormatExtension();
    void problemsShowDiagnosticsAsDetails();

private:
    QTemporaryDir m_settingsDir;
};

void TestAppDialogPrompts::initTestCase()
{
    // QFileDialog remembers its state in the user's settings; keep that out of the real ones.
    QVERIFY(m_settingsDir.isValid());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, m_settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
}

void TestAppDialogPrompts::saveChangesButtons_data()
{
    QTest::addColumn<int>("button");
    QTest::addColumn<int>("choice");
    QTest::newRow("save") << int(QMessageBox::Save) << int(UserPrompts::SaveChoice::Save);
    QTest::newRow("discard") << int(QMessageBox::Discard) << int(UserPrompts::SaveChoice::Discard);
    QTest::newRow("cancel") << int(QMessageBox::Cancel) << int(UserPrompts::SaveChoice::Cancel);
}

void TestAppDialogPrompts::saveChangesButtons()
{
    QFETCH(int, button);
    QFETCH(int, choice);
    QWidget parent;
    DialogPrompts prompts(&parent);
    QString shownText;
    const Expected answer([&](QWidget *modal) {
        auto *box = qobject_cast<QMessageBox *>(modal);
        QVERIFY(box);
        shownText = box->text();
        box->button(QMessageBox::StandardButton(button))->click();
    });
    QCOMPARE(int(prompts.askSaveChanges(QStringLiteral("RTC.xml"))), choice);
    QVERIFY(shownText.contains(QStringLiteral("RTC.xml")));
}

void TestAppDialogPrompts::saveFileNameGetsFormatExtension_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<bool>("yamlFilter");
    QTest::addColumn<QString>("expected");
    QTest::newRow("xml filter, no extension") << "Comp" << false << "Comp.xml";
    QTest::newRow("yaml filter, no extension") << "Comp" << true << "Comp.yaml";
    QTest::newRow("extension typed wins") << "Comp.yml" << false << "Comp.yml";
}

void TestAppDialogPrompts::saveFileNameGetsFormatExtension()
{
    QFETCH(QString, typed);
    QFETCH(bool, yamlFilter);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QWidget parent;
    DialogPrompts prompts(&parent);
    const Expected answer([&](QWidget *modal) {
        auto *dialog = qobject_cast<QFileDialog *>(modal);
        QVERIFY(dialog);
        const QStringList filters = dialog->nameFilters();
        QCOMPARE(filters.size(), 2);
        dialog->selectNameFilter(filters.at(yamlFilter ? 1 : 0));
        dialog->selectFile(typed);
        QMetaObject::invokeMethod(dialog, "accept");
    });
    const QString path = prompts.askSaveFileName(Profile::ProfileKind::Rtc,
                                                 dir.filePath(QStringLiteral("RTC.xml")));
    QCOMPARE(path, dir.filePath(expected));
}

void TestAppDialogPrompts::problemsShowDiagnosticsAsDetails()
{
    QWidget parent;
    DialogPrompts prompts(&parent);
    QString details;
    QString text;
    const Expected answer([&](QWidget *modal) {
        auto *box = qobject_cast<QMessageBox *>(modal);
        QVERIFY(box);
        text = box->text();
        details = box->detailedText();
        box->button(QMessageBox::Ok)->click();
    });
    prompts.showProblems(QStringLiteral("Open Failed"), QStringLiteral("Could not open x.xml."),
                         {Profile::Diagnostic::error(QStringLiteral("x.xml"), 3, 7,
                                                     QStringLiteral("unexpected end"))});
    QCOMPARE(text, QStringLiteral("Could not open x.xml."));
    QVERIFY2(details.contains(QStringLiteral("x.xml:3:7")), qPrintable(details));
    QVERIFY(details.contains(QStringLiteral("unexpected end")));
}

QTEST_MAIN(TestAppDialogPrompts)
#include "tst_appdialogprompts.moc"
