// SPDX-License-Identifier: MIT
// The documentation's pictures render: docscreenshots writes each picture in both languages, each
// a full window with something drawn in it, and every picture docs/images holds is one it makes.
#include <QDir>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

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
    process.start(QStringLiteral(DOCSCREENSHOTS_PATH), {output.path(), language});
    QVERIFY(process.waitForFinished(60000));
    QVERIFY2(process.exitCode() == 0, process.readAll().constData());
    for (const char *name : {"builder", "systemeditor", "planview", "online", "userguide"}) {
        const QString path = QDir(output.path()).filePath(QStringLiteral("%1-%2.png").arg(QLatin1String(name), language));
        const QImage image(path);
        QVERIFY2(!image.isNull(), qPrintable(path));
        QVERIFY(image.width() >= 800 && image.height() >= 600);
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
    const QDir images(QStringLiteral(RTSTUDIO_SOURCE_DIR "/docs/images"));
    const QSet<QString> made{"builder-en.png", "builder-ja.png", "systemeditor-en.png", "systemeditor-ja.png",
                             "planview-en.png", "planview-ja.png", "online-en.png", "online-ja.png",
                             "userguide-en.png", "userguide-ja.png"};
    for (const QString &file : images.entryList(QDir::Files))
        QVERIFY2(made.contains(file), qPrintable(file + QStringLiteral(" in docs/images is made by nothing")));
}

QTEST_GUILESS_MAIN(TestScreenshots)
#include "tst_screenshots.moc"
