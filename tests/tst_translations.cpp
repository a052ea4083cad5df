// SPDX-License-Identifier: MIT
// The Japanese GUI: every string the sources pass through tr() has a translation that keeps its
// placeholders, mnemonic and markup, and the main window with a component and a system open
// shows no English beyond names and technical terms.

#include "mainwindow.h"
#include "uilanguage.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QDockWidget>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QTranslator>
#include <QXmlStreamReader>

using namespace Studio;

namespace {

struct Message
{
    QString context;
    QString source;
    QStringList translations; // one per plural form
    bool finished = false;
    QString location; // file:line of the first use
};

/// The messages of a Qt Linguist file.
QList<Message> readTs(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return {};
    }
    QList<Message> messages;
    QString context;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (xml.name() == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (xml.name() == QLatin1String("message")) {
            Message message;
            message.context = context;
            while (xml.readNextStartElement()) {
                if (xml.name() == QLatin1String("source")) {
                    message.source = xml.readElementText();
                } else if (xml.name() == QLatin1String("location")) {
                    if (message.location.isEmpty())
                        message.location = xml.attributes().value(QLatin1String("filename")).toString()
                            + QLatin1Char(':') + xml.attributes().value(QLatin1String("line")).toString();
                    xml.skipCurrentElement();
                } else if (xml.name() == QLatin1String("translation")) {
                    message.finished = xml.attributes().value(QLatin1String("type")).isEmpty();
                    QString text;
                    while (!xml.atEnd() && !(xml.readNext() == QXmlStreamReader::EndElement
                                             && xml.name() == QLatin1String("translation"))) {
                        if (xml.isCharacters())
                            text += xml.text();
                        else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                            message.translations.append(xml.readElementText());
                    }
                    if (message.translations.isEmpty())
                        message.translations.append(text);
                } else {
                    xml.skipCurrentElement();
                }
            }
            messages.append(message);
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

QStringList sorted(QStringList list)
{
    list.sort();
    return list;
}

QStringList matches(const QRegularExpression &pattern, const QString &text)
{
    QStringList found;
    for (auto it = pattern.globalMatch(text); it.hasNext();)
        found.append(it.next().captured());
    return found;
}

/// The mnemonic letter of a label ("&File" → "F"), or an empty string.
QString mnemonic(const QString &text)
{
    static const QRegularExpression pattern(QStringLiteral("(?<!&)&([^&\\s])"));
    const QRegularExpressionMatch match = pattern.match(QString(text).remove(QStringLiteral("&&")));
    return match.hasMatch() ? match.captured(1).toUpper() : QString();
}

/// Latin words in a Japanese GUI string that are neither names nor technical terms.
QStringList englishWords(const QString &text)
{
    static const QSet<QString> terms = {
        QStringLiteral("RT"), QStringLiteral("RTC"), QStringLiteral("RTCs"), QStringLiteral("RTS"),
        QStringLiteral("IDL"), QStringLiteral("CORBA"), QStringLiteral("XML"), QStringLiteral("YAML"),
        QStringLiteral("JSON"), QStringLiteral("PNG"), QStringLiteral("SVG"), QStringLiteral("OpenRTM"),
        QStringLiteral("aist"), QStringLiteral("OpenRTP"), QStringLiteral("Studio"), QStringLiteral("InPort"),
        QStringLiteral("OutPort"), QStringLiteral("DataFlow"), QStringLiteral("FSM"),
        QStringLiteral("MultiMode"), QStringLiteral("FiniteStateMachine"), QStringLiteral("Push"),
        QStringLiteral("Pull"), QStringLiteral("omniNames"), QStringLiteral("omniORB"),
        QStringLiteral("rtc"), QStringLiteral("conf"), QStringLiteral("rtcd"), QStringLiteral("rtmanager"),
        QStringLiteral("rtctl"), QStringLiteral("Python"), QStringLiteral("Java"), QStringLiteral("CMake"),
        QStringLiteral("corbaloc"), QStringLiteral("iiop"), QStringLiteral("English"), QStringLiteral("Hz"),
        QStringLiteral("Ctrl"), QStringLiteral("Shift"), QStringLiteral("Alt"), QStringLiteral("Del"),
        QStringLiteral("Flush"), QStringLiteral("New"), QStringLiteral("Periodic"),
        QStringLiteral("flush"), QStringLiteral("new"), QStringLiteral("periodic"), QStringLiteral("sync"),
        QStringLiteral("xml"), QStringLiteral("yaml"), QStringLiteral("yml"), QStringLiteral("png"),
        QStringLiteral("svg"), QStringLiteral("Debian"), QStringLiteral("deb"), QStringLiteral("http"),
        QStringLiteral("https"),
    };
    // Tokens that hold a path, a file name, an identifier (snake_case, CamelCase, ACRONYM) or
    // a number are names, whatever the language around them.
    static const QRegularExpression token(QStringLiteral("[A-Za-z0-9_./:\\-]+"));
    static const QRegularExpression name(QStringLiteral("[_./:0-9]|^[A-Z0-9]+$|[a-z][A-Z]"));
    static const QRegularExpression callback(QStringLiteral("^on[A-Z]"));
    QStringList english;
    for (const QString &w : matches(token, text)) {
        const QString bare = QString(w).remove(QRegularExpression(QStringLiteral("^-+|-+$")));
        if (bare.size() < 2 || terms.contains(bare) || name.match(bare).hasMatch()
            || callback.match(bare).hasMatch())
            continue;
        english.append(bare);
    }
    return english;
}

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void everySourceStringIsTranslated();
    void translationsKeepPlaceholdersMnemonicsAndMarkup();
    void languageFollowsSettingThenLocale();
    void japaneseWindowShowsNoEnglish();

private:
    QTemporaryDir m_settingsDir;
    QList<Message> m_committed;
};

void TestTranslations::initTestCase()
{
    QVERIFY(m_settingsDir.isValid());
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RtStudioTest"));
    QCoreApplication::setApplicationName(QStringLiteral("tst_translations"));
    QString error;
    m_committed = readTs(RTSTUDIO_TS_FILE, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY(m_committed.size() > 100);
}

void TestTranslations::everySourceStringIsTranslated()
{
    // lupdate reads today's sources into a copy of the catalogue: a string added or changed since
    // the catalogue was last translated comes back unfinished.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString copy = dir.filePath(QStringLiteral("rtstudio_ja.ts"));
    QVERIFY(QFile::copy(RTSTUDIO_TS_FILE, copy));
    QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
    QProcess lupdate;
    lupdate.setProcessChannelMode(QProcess::MergedChannels);
    lupdate.start(QStringLiteral(RTSTUDIO_LUPDATE),
                  {QStringLiteral("-no-obsolete"), QStringLiteral("-locations"),
                   QStringLiteral("absolute"), QStringLiteral("-target-language"),
                   QStringLiteral("ja_JP"),
                   QLatin1Char('@') + RTSTUDIO_TRANSLATED_SOURCES, QStringLiteral("-ts"),
                   copy});
    QVERIFY(lupdate.waitForFinished(120000));
    QVERIFY2(lupdate.exitCode() == 0, lupdate.readAll().constData());

    QString error;
    const QList<Message> current = readTs(copy, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QStringList untranslated;
    for (const Message &message : current) {
        const bool empty = message.translations.join(QString()).trimmed().isEmpty();
        if (!message.finished || empty)
            untranslated.append(QStringLiteral("%1: [%2] %3")
                                    .arg(message.location, message.context, message.source));
    }
    QVERIFY2(untranslated.isEmpty(),
             qPrintable(QStringLiteral("%1 string(s) without a Japanese translation (translate them in "
                                       "resources/translations/rtstudio_ja.ts after "
                                       "`cmake --build BUILD --target update_translations`):\n%2")
                            .arg(untranslated.size())
                            .arg(untranslated.join(QLatin1Char('\n')))));
    QCOMPARE(current.size(), m_committed.size());
}

void TestTranslations::translationsKeepPlaceholdersMnemonicsAndMarkup()
{
    static const QRegularExpression placeholder(QStringLiteral("%L?(\\d+|n)"));
    static const QRegularExpression tag(QStringLiteral("</?[a-zA-Z][a-zA-Z0-9]*"));
    QStringList problems;
    for (const Message &message : std::as_const(m_committed)) {
        for (const QString &translation : message.translations) {
            const QString what = QStringLiteral("[%1] \"%2\" → \"%3\"")
                                     .arg(message.context, message.source, translation);
            if (sorted(matches(placeholder, message.source)) != sorted(matches(placeholder, translation)))
                problems.append(QStringLiteral("placeholders differ: ") + what);
            if (mnemonic(message.source) != mnemonic(translation))
                problems.append(QStringLiteral("mnemonic differs: ") + what);
            if (sorted(matches(tag, message.source)) != sorted(matches(tag, translation)))
                problems.append(QStringLiteral("markup differs: ") + what);
            if (message.source.endsWith(QStringLiteral("…")) != translation.endsWith(QStringLiteral("…"))
                && !message.source.endsWith(QStringLiteral("...")))
                problems.append(QStringLiteral("ellipsis differs: ") + what);
            if (!englishWords(translation).isEmpty()
                && englishWords(translation) == englishWords(message.source)
                && englishWords(message.source).size() > 2)
                problems.append(QStringLiteral("left in English: ") + what);
        }
    }
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTranslations::languageFollowsSettingThenLocale()
{
    QSettings().clear();
    QCOMPARE(UiLanguage::chosen(), QString());
    QCOMPARE(UiLanguage::resolve(QString(), QLocale(QLocale::Japanese, QLocale::Japan)), QStringLiteral("ja"));
    QCOMPARE(UiLanguage::resolve(QString(), QLocale(QLocale::German, QLocale::Germany)), QStringLiteral("en"));
    QCOMPARE(UiLanguage::resolve(QString(), QLocale::c()), QStringLiteral("en"));
    UiLanguage::choose(QStringLiteral("en"));
    QCOMPARE(UiLanguage::chosen(), QStringLiteral("en"));
    QCOMPARE(UiLanguage::resolve(UiLanguage::chosen(), QLocale(QLocale::Japanese)), QStringLiteral("en"));
    UiLanguage::choose(QStringLiteral("ja"));
    QCOMPARE(UiLanguage::resolve(UiLanguage::chosen(), QLocale::c()), QStringLiteral("ja"));
    QSettings().setValue(QStringLiteral("ui/language"), QStringLiteral("klingon"));
    QCOMPARE(UiLanguage::chosen(), QString()); // unknown values fall back to the system's
    UiLanguage::choose(QString());
    QCOMPARE(UiLanguage::chosen(), QString());

    // The View menu offers each language by its own name and stores the choice.
    MainWindow window;
    auto *japanese = window.findChild<QAction *>(QStringLiteral("actionLanguage_ja"));
    QVERIFY(japanese);
    QCOMPARE(japanese->text(), QStringLiteral("日本語"));
    QVERIFY(window.findChild<QAction *>(QStringLiteral("actionLanguage_system"))->isChecked());
    japanese->trigger();
    QCOMPARE(UiLanguage::chosen(), QStringLiteral("ja"));
    QSettings().clear();
}

void TestTranslations::japaneseWindowShowsNoEnglish()
{
    QSettings().clear();
    QString error;
    QVERIFY2(UiLanguage::install(qApp, QStringLiteral("ja"), &error), qPrintable(error));
    QCOMPARE(QCoreApplication::translate("Studio::MainWindow", "&File"), QStringLiteral("ファイル(&F)"));

    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const QString data = RTSTUDIO_TEST_DATA_DIR + QStringLiteral("/app/");
    QVERIFY(window.openFiles({data + QStringLiteral("component.xml"), data + QStringLiteral("system.xml")}));

    // What the user reads in the window's chrome: menus, actions, docks, tabs, labels, buttons,
    // group titles, column headers and placeholder texts (not the document's own names and values).
    QStringList english;
    const auto check = [&english](const QObject *where, const QString &text) {
        const QString plain = QString(text).remove(QRegularExpression(QStringLiteral("<[^>]*>")));
        const QStringList words = englishWords(plain);
        if (!words.isEmpty())
            english.append(QStringLiteral("%1 \"%2\" (%3)")
                               .arg(QString::fromLatin1(where->metaObject()->className()), text,
                                    words.join(QLatin1Char(' '))));
    };
    for (QAction *action : window.findChildren<QAction *>()) {
        if (action->objectName().startsWith(QLatin1String("actionLanguage_"))
            || action->objectName() == QLatin1String("actionRecentFile"))
            continue;
        if (action->menu() && !action->menu()->title().isEmpty())
            check(action, action->menu()->title());
        check(action, action->text());
        if (action->toolTip() != action->text().remove(QLatin1Char('&')))
            check(action, action->toolTip());
    }
    for (const QDockWidget *dock : window.findChildren<QDockWidget *>())
        check(dock, dock->windowTitle());
    for (const QTabWidget *tabs : window.findChildren<QTabWidget *>()) {
        for (int i = 0; i < tabs->count(); ++i) {
            if (!tabs->property("documentTabs").toBool())
                check(tabs, tabs->tabText(i));
        }
    }
    for (const QGroupBox *group : window.findChildren<QGroupBox *>())
        check(group, group->title());
    for (const QAbstractButton *button : window.findChildren<QAbstractButton *>()) {
        if (!qobject_cast<const QToolButton *>(button) || !button->text().isEmpty())
            check(button, button->text());
        check(button, button->toolTip());
    }
    for (const QLabel *label : window.findChildren<QLabel *>()) {
        if (!label->property("showsDocumentData").toBool())
            check(label, label->text());
    }
    for (const QLineEdit *edit : window.findChildren<QLineEdit *>())
        check(edit, edit->placeholderText());
    for (const QAbstractItemView *view : window.findChildren<QAbstractItemView *>()) {
        const QAbstractItemModel *model = view->model();
        if (!model)
            continue;
        for (int column = 0; column < model->columnCount(); ++column)
            check(view, model->headerData(column, Qt::Horizontal).toString());
    }
    english.removeDuplicates();
    QVERIFY2(english.isEmpty(),
             qPrintable(QStringLiteral("English in the Japanese GUI:\n") + english.join(QLatin1Char('\n'))));
}

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
