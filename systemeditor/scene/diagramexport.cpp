// SPDX-License-Identifier: MIT
#include "diagramexport.h"

#include "componentitem.h"
#include "systemfile.h"
#include "systemmodel.h"
#include "systemscene.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QImageWriter>
#include <QPainter>
#include <QSvgGenerator>

#include <algorithm>

namespace SystemEditor {

namespace {

/// The strings of this file, in one translation context.
struct Text
{
    Q_DECLARE_TR_FUNCTIONS(SystemEditor::DiagramExport)
};

/// The area to draw; an empty system still gives a small blank page.
QRectF sourceRect(const SystemScene &scene)
{
    const QRectF rect = scene.diagramRect();
    return rect.isEmpty() ? QRectF(0, 0, 200, 100) : rect;
}

void paintScene(SystemScene &scene, QPainter &painter, const QRectF &target)
{
    painter.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
    painter.fillRect(target, Qt::white);
    scene.render(&painter, target, sourceRect(scene));
}

bool writeSvg(SystemScene &scene, const QString &path, QString *error)
{
    const QRectF source = sourceRect(scene);
    QSvgGenerator generator;
    generator.setFileName(path);
    generator.setSize(source.size().toSize());
    generator.setViewBox(QRectF(QPointF(0, 0), source.size()));
    generator.setTitle(Text::tr("RT System diagram"));
    QPainter painter;
    if (!painter.begin(&generator)) {
        *error = Text::tr("Cannot write \"%1\".").arg(path);
        return false;
    }
    paintScene(scene, painter, QRectF(QPointF(0, 0), source.size()));
    painter.end();
    if (!QFileInfo::exists(path)) {
        *error = Text::tr("Cannot write \"%1\".").arg(path);
        return false;
    }
    return true;
}

} // namespace

QImage DiagramExport::renderImage(SystemModel &model, qreal scale)
{
    SystemScene scene(&model, nullptr);
    scene.setGridVisible(false);
    const QRectF source = sourceRect(scene);
    QImage image((source.size() * scale).toSize(), QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    paintScene(scene, painter, QRectF(QPointF(0, 0), source.size() * scale));
    painter.end();
    return image;
}

bool DiagramExport::exportToFile(SystemModel &model, const QString &outputPath, QString *error)
{
    QString ignored;
    QString &message = error ? *error : ignored;
    const QString suffix = QFileInfo(outputPath).suffix().toLower();
    if (suffix == QLatin1String("svg")) {
        SystemScene scene(&model, nullptr);
        scene.setGridVisible(false);
        return writeSvg(scene, outputPath, &message);
    }
    if (!QImageWriter::supportedImageFormats().contains(suffix.toLatin1())) {
        message = Text::tr("Unknown image format \"%1\": use .svg or .png.").arg(suffix);
        return false;
    }
    QImageWriter writer(outputPath, suffix.toLatin1());
    if (!writer.write(renderImage(model))) {
        message = Text::tr("Cannot write \"%1\": %2").arg(outputPath, writer.errorString());
        return false;
    }
    return true;
}

AutoLayoutOptions DiagramExport::drawnLayoutOptions(const SystemScene &scene)
{
    AutoLayoutOptions options;
    for (const QString &name : scene.model()->componentIds()) {
        if (const ComponentItem *item = scene.componentItem(name))
            options.sizes.insert(name, item->bodyRect().size());
    }
    return options;
}

bool DiagramExport::hasPositions(const SystemModel &model)
{
    const QList<Profile::RtsComponent> &components = model.profile().components;
    return std::any_of(components.cbegin(), components.cend(),
                       [](const Profile::RtsComponent &c) { return c.layout.has_value(); });
}

bool DiagramExport::exportLaidOut(SystemModel &model, const QString &outputPath, QString *error)
{
    if (hasPositions(model) || model.profile().components.isEmpty())
        return exportToFile(model, outputPath, error);
    SystemModel copy;
    copy.setProfile(model.profile(), model.rtcProfiles());
    AutoLayoutOptions options;
    {
        const SystemScene measuring(&copy, nullptr);
        options = drawnLayoutOptions(measuring);
    }
    const QHash<QString, QPointF> positions = computeAutoLayout(copy, options);
    for (auto it = positions.cbegin(); it != positions.cend(); ++it)
        copy.moveComponent(it.key(), it.value());
    return exportToFile(copy, outputPath, error);
}

bool DiagramExport::exportSystemFile(const QString &systemPath, const QString &outputPath,
                                     QString *error)
{
    Profile::Diagnostics diagnostics;
    std::optional<LoadedSystem> loaded = loadSystemFile(systemPath, &diagnostics);
    if (!loaded) {
        QStringList lines;
        for (const Profile::Diagnostic &diagnostic : std::as_const(diagnostics))
            lines << diagnostic.toString();
        if (error)
            *error = lines.isEmpty() ? Text::tr("Cannot read \"%1\".").arg(systemPath)
                                     : lines.join(QLatin1Char('\n'));
        return false;
    }
    SystemModel model;
    model.setProfile(loaded->profile, loaded->rtcProfiles);
    return exportLaidOut(model, outputPath, error);
}

} // namespace SystemEditor
