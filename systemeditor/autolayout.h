// SPDX-License-Identifier: MIT
#pragma once

#include "systemmodel.h"

#include <QHash>
#include <QPointF>
#include <QSizeF>

class QUndoCommand;

namespace SystemEditor {

/// Spacing of the automatic layout, in scene units.
struct AutoLayoutOptions
{
    qreal rankSeparation = 80; ///< between columns (data flows left to right)
    qreal nodeSeparation = 40; ///< between components in one column
    QPointF origin {20, 20}; ///< the top-left of the laid-out system
    /// Sizes of the components as drawn (labels widen them), by instance name; componentSize()
    /// for those not listed.
    QHash<QString, QSizeF> sizes;
};

/**
 * New top-left positions for every component, computed by graphviz `dot` (rankdir=LR): data
 * flows from left to right along the connectors, nodes are sized like the drawn components
 * (componentSize()), so that none overlap. Empty when graphviz cannot lay the graph out.
 */
QHash<QString, QPointF> computeAutoLayout(const SystemModel &model,
                                          const AutoLayoutOptions &options = {});

/// One undoable step that moves every component to computeAutoLayout()'s positions (saved in
/// `rtsExt:Location`); null when there is nothing to lay out.
QUndoCommand *autoLayoutCommand(SystemModel *model, const AutoLayoutOptions &options = {});

} // namespace SystemEditor
