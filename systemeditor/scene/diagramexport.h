// SPDX-License-Identifier: MIT
#pragma once

#include <QImage>
#include <QString>

namespace SystemEditor {

class SystemModel;

/**
 * Renders a system's diagram without a window, as the canvas draws it (no grid, no selection).
 * Needs a QApplication (the canvas items are widgets-library items); the offscreen platform
 * is enough.
 */
class DiagramExport
{
public:
    /// The diagram as an image at `scale` (1 = one pixel per scene unit), white background.
    static QImage renderImage(SystemModel &model, qreal scale = 1.0);
    /**
     * Writes the diagram to `outputPath`: SVG when it ends in `.svg`, else an image in the
     * format its extension names (png, jpg, …). False with a message in `error` on failure.
     */
    static bool exportToFile(SystemModel &model, const QString &outputPath, QString *error);
    /// Loads a system file (XML or YAML, with its components' RTC profiles) and exports it.
    static bool exportSystemFile(const QString &systemPath, const QString &outputPath,
                                 QString *error);
};

} // namespace SystemEditor
