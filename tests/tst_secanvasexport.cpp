// SPDX-License-Identifier: MIT
// Headless diagram export: PNG and SVG of the fixture and the bundled examples, failures.
#include "tst_secanvassupport.h"

#include "diagramexport.h"

#include <QFile>
#include <QImageReader>
#include <QTemporaryDir>

using namespace SystemEditor;

class TestSeCanvasExport : public QObject
{
    Q_OBJECT

private slots:
    void exportsPng();
    void exportsSvgWithInstanceNames_data();
    void exportsSvgWithInstanceNames();
    void renderedImageShowsComponents();
    void failures_data();
    void failures();
};

void TestSeCanvasExport::exportsPng()
{
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("system.png"));
    QString error;
    QVERIFY2(DiagramExport::exportSystemFile(SeCanvasTest::dataPath(QStringLiteral("system.xml")),
                                             out, &error),
             qPrintable(error));
    QImageReader reader(out);
    QCOMPARE(reader.format(), QByteArray("png"));
    const QSize size = reader.size();
    // Three components side by side: wider than tall, and not absurdly large.
    QVERIFY2(size.width() > 600 && size.width() < 2000, qPrintable(QString::number(size.width())));
    QVERIFY(size.height() > 80 && size.height() < 800);
}

void TestSeCanvasExport::exportsSvgWithInstanceNames_data()
{
    QTest::addColumn<QString>("system");
    QTest::addColumn<QStringList>("names");
    QTest::newRow("fixture") << SeCanvasTest::dataPath(QStringLiteral("system.xml"))
                             << QStringList {"Sensor0", "Filter0", "Sink0"};
    QTest::newRow("ConsoleInOut")
        << RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/ConsoleInOut/ConsoleInOut.xml")
        << QStringList {"ConsoleIn0", "ConsoleOut0"};
    QTest::newRow("SeqIO") << RTSTUDIO_SOURCE_DIR + QStringLiteral("/resources/examples/SeqIO/SeqIO.xml")
                           << QStringList {"SeqIn0", "SeqOut0"};
}

void TestSeCanvasExport::exportsSvgWithInstanceNames()
{
    QFETCH(QString, system);
    QFETCH(QStringList, names);
    QTemporaryDir dir;
    const QString out = dir.filePath(QStringLiteral("diagram.svg"));
    QString error;
    QVERIFY2(DiagramExport::exportSystemFile(system, out, &error), qPrintable(error));
    QFile file(out);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray svg = file.readAll();
    QVERIFY(svg.size() > 1000 && svg.size() < 2'000'000);
    QVERIFY(svg.contains("<svg"));
    for (const QString &name : names)
        QVERIFY2(svg.contains(name.toUtf8()), qPrintable(name));
}

void TestSeCanvasExport::renderedImageShowsComponents()
{
    std::unique_ptr<SystemModel> model = SeCanvasTest::loadModel();
    QVERIFY(model);
    const QImage image = DiagramExport::renderImage(*model);
    QVERIFY(!image.isNull());
    // Not blank: the bodies and ports put colour on the white page.
    int coloured = 0;
    for (int y = 0; y < image.height(); y += 4) {
        for (int x = 0; x < image.width(); x += 4)
            coloured += image.pixelColor(x, y) != QColor(Qt::white);
    }
    QVERIFY2(coloured > 200, qPrintable(QString::number(coloured)));
    const QImage doubled = DiagramExport::renderImage(*model, 2.0);
    QCOMPARE(doubled.size(), image.size() * 2);
}

void TestSeCanvasExport::failures_data()
{
    QTest::addColumn<QString>("system");
    QTest::addColumn<QString>("output");
    QTest::addColumn<QString>("message");
    const QString good = SeCanvasTest::dataPath(QStringLiteral("system.xml"));
    QTest::newRow("missing system") << SeCanvasTest::dataPath(QStringLiteral("absent.xml"))
                                    << QStringLiteral("out.png") << QStringLiteral("absent.xml");
    QTest::newRow("not a system") << SeCanvasTest::dataPath(QStringLiteral("RTCs/Sink0.xml"))
                                  << QStringLiteral("out.png") << QStringLiteral("Sink0.xml");
    QTest::newRow("unknown format") << good << QStringLiteral("out.doc")
                                    << QStringLiteral("doc");
    QTest::newRow("unwritable") << good << QStringLiteral("no/such/folder/out.png")
                                << QStringLiteral("out.png");
}

void TestSeCanvasExport::failures()
{
    QFETCH(QString, system);
    QFETCH(QString, output);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QString error;
    QVERIFY(!DiagramExport::exportSystemFile(system, dir.filePath(output), &error));
    QVERIFY2(error.contains(message), qPrintable(error));
    QVERIFY(!QFile::exists(dir.filePath(output)));
}

QTEST_MAIN(TestSeCanvasExport)
#include "tst_secanvasexport.moc"
