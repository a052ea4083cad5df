// SPDX-License-Identifier: MIT
#pragma once

#include "autolayout.h"

#include <QImage>
#include <QString>

namespace SystemEditor {

class SystemModel;
class SystemScene;

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
    /// The layout options for `scene`'s system with its components' drawn sizes, so that the
    /// laid-out components do not overlap however wide their labels make them.
    static AutoLayoutOptions drawnLayoutOptions(const SystemScene &scene);
    /// True when some component has a saved position (`rtsExt:Location`).
    static bool hasPositions(const SystemModel &model);
    /**
     * Like exportToFile(), but a system without any saved position is drawn auto-laid-out
     * (computeAutoLayout()) instead of with every component at the origin. `model` is never
     * changed: the layout is applied to a copy.
     */
    static bool exportLaidOut(SystemModel &model, const QString &outputPath, QString *error);
    /// Loads a system file (XML or YAML, with its components' RTC profiles) and exports it
    /// through exportLaidOut().
    static bool exportSystemFile(const QString &systemPath, const QString &outputPath,
                                 QString *error);
};

} // namespace SystemEditor
