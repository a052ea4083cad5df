// SPDX-License-Identifier: MIT
// The documentation's pictures render: docscreenshots writes each picture in both languages, each
// a full window or dialog with something drawn in it, and every picture docs/images holds is one it
// makes.
#include <QDir>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

/// A picture docscreenshots makes and the least size that shows it whole.
struct Picture
{
    const char *name;
    QSize minimum;
};

const QSize window(800, 600);
// Dialogs open at the size their contents want; smaller ones would cut text off.
const Picture pictures[] = {
    {"builder", window},     {"generate", {300, 120}},    {"regenerate", {600, 400}},
    {"systemeditor", window}, {"connector", {400, 400}},  {"planview", window},
    {"restore", {800, 500}},  {"online", window},         {"portmonitor", {800, 300}},
    {"userguide", window},
};

QString fileName(const Picture &picture, const QString &language)
{
    return QStringLiteral("%1-%2.png").arg(QLatin1String(picture.name), language);
}

} // namespace

class TestScreenshots : public QObject
{
    Q_OBJECT

private slots:
    void render_data();
    void render();
    void committedPicturesAreRendered();
};

void TestScreenshots::render_data()
{
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("ja") << QStringLiteral("ja");
}

void TestScreenshots::render()
{
    QFETCH(QString, language);
    QTemporaryDir output;
    QVERIFY(output.isValid());
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(DOCSCREENSHOTS_PATH, {output.path(), language});
    QVERIFY(process.waitForFinished(120000));
    QVERIFY2(process.exitCode() == 0, process.readAll().constData());
    for (const Picture &picture : pictures) {
        const QString path = QDir(output.path()).filePath(fileName(picture, language));
        const QImage image(path);
        QVERIFY2(!image.isNull(), qPrintable(path));
        QVERIFY2(image.width() >= picture.minimum.width() && image.height() >= picture.minimum.height(),
                 qPrintable(path));
        // Not one flat colour: something was drawn.
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 17)
            for (int x = 0; x < image.width(); x += 13)
                colours.insert(image.pixel(x, y));
        QVERIFY2(colours.size() > 8, qPrintable(path));
    }
}

void TestScreenshots::committedPicturesAreRendered()
{
    const QDir images(RTSTUDIO_SOURCE_DIR + QStringLiteral("/docs/images"));
    QSet<QString> made;
    for (const Picture &picture : pictures)
        made << fileName(picture, QStringLiteral("en")) << fileName(picture, QStringLiteral("ja"));
    for (const QString &file : images.entryList(QDir::Files))
        QVERIFY2(made.contains(file), qPrintable(file + QStringLiteral(" in docs/images is made by nothing")));
}

QTEST_GUILESS_MAIN(TestScreenshots)
#include "tst_screenshots.moc"
