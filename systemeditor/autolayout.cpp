// SPDX-License-Identifier: MIT
#include "autolayout.h"

#include "instancecommands.h"
#include "componentfactory.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

#include <QCoreApplication>

namespace SystemEditor {

namespace {

constexpr double PointsPerInch = 72.0;

/// Graphviz takes `char *` everywhere; these buffers live as long as the call needs them.
void setAttribute(void *object, const char *name, const QByteArray &value)
{
    QByteArray key(name);
    QByteArray text(value);
    QByteArray empty("");
    agsafeset(object, key.data(), text.data(), empty.data());
}

QByteArray inches(qreal units)
{
    return QByteArray::number(units / PointsPerInch, 'f', 4);
}

/// Owns a graphviz context and graph, and frees them in the right order.
class Layout
{
public:
    Layout()
        : m_context(gvContext())
    {
        QByteArray name("system");
        m_graph = agopen(name.data(), Agdirected, nullptr);
    }
    ~Layout()
    {
        if (m_laidOut)
            gvFreeLayout(m_context, m_graph);
        agclose(m_graph);
        gvFreeContext(m_context);
    }
    Layout(const Layout &) = delete;
    Layout &operator=(const Layout &) = delete;

    Agraph_t *graph() const { return m_graph; }
    bool run()
    {
        QByteArray engine("dot");
        m_laidOut = gvLayout(m_context, m_graph, engine.data()) == 0;
        return m_laidOut;
    }

private:
    GVC_t *m_context;
    Agraph_t *m_graph;
    bool m_laidOut = false;
};

template<typename Connectors>
void addEdges(Agraph_t *graph, const QHash<QString, Agnode_t *> &nodes,
              const Connectors &connectors, bool constrain)
{
    for (const auto &c : connectors) {
        Agnode_t *from = nodes.value(c.source.instanceName);
        Agnode_t *to = nodes.value(c.target.instanceName);
        if (!from || !to || from == to)
            continue;
        Agedge_t *edge = agedge(graph, from, to, nullptr, 1);
        // Service connections have no direction of flow; they must not decide the columns.
        if (!constrain)
            setAttribute(edge, "constraint", "false");
    }
}

} // namespace

QHash<QString, QPointF> computeAutoLayout(const SystemModel &model,
                                          const AutoLayoutOptions &options)
{
    QHash<QString, QPointF> result;
    const QStringList names = model.componentIds();
    if (names.isEmpty())
        return result;
    Layout layout;
    Agraph_t *graph = layout.graph();
    setAttribute(graph, "rankdir", "LR");
    setAttribute(graph, "ranksep", inches(options.rankSeparation));
    setAttribute(graph, "nodesep", inches(options.nodeSeparation));
    setAttribute(graph, "ordering", "out");
    QHash<QString, Agnode_t *> nodes;
    QHash<QString, QSizeF> sizes;
    for (const QString &name : names) {
        QByteArray id = name.toUtf8();
        Agnode_t *node = agnode(graph, id.data(), 1);
        const QSizeF size = options.sizes.contains(name) ? options.sizes.value(name)
                                                         : componentSize(model, name);
        setAttribute(node, "shape", "box");
        setAttribute(node, "fixedsize", "true");
        setAttribute(node, "width", inches(size.width()));
        setAttribute(node, "height", inches(size.height()));
        nodes.insert(name, node);
        sizes.insert(name, size);
    }
    addEdges(graph, nodes, model.profile().dataPortConnectors, true);
    addEdges(graph, nodes, model.profile().servicePortConnectors, false);
    if (!layout.run())
        return result;
    // Graphviz's y axis points up; the scene's points down.
    const double top = GD_bb(graph).UR.y;
    for (const QString &name : names) {
        const pointf centre = ND_coord(nodes.value(name));
        const QSizeF size = sizes.value(name);
        result.insert(name, QPointF(qRound(options.origin.x() + centre.x - size.width() / 2),
                                    qRound(options.origin.y() + top - centre.y
                                           - size.height() / 2)));
    }
    return result;
}

QUndoCommand *autoLayoutCommand(SystemModel *model, const AutoLayoutOptions &options)
{
    const QHash<QString, QPointF> positions = computeAutoLayout(*model, options);
    if (positions.isEmpty())
        return nullptr;
    return new MoveComponentsCommand(
        model, positions, QCoreApplication::translate("AutoLayout", "Auto Layout"));
}

} // namespace SystemEditor
