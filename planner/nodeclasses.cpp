// SPDX-License-Identifier: MIT
#include "nodeclasses.h"

#include <QMap>

#include <algorithm>
#include <numeric>

namespace Planner {

namespace {

/// What a node means to every unit: not allowed (-1), or the kinds of the packages it needs there.
QList<int> signature(const SolverInput &input, int node)
{
    QList<int> result;
    for (const SolverUnit &unit : input.units) {
        const int k = unit.nodes.indexOf(node);
        if (k < 0) {
            result << -1;
            continue;
        }
        QList<int> kinds;
        for (const int install : unit.installs.at(k))
            kinds << input.installKind.value(install, install);
        std::sort(kinds.begin(), kinds.end());
        result << int(kinds.size()) << kinds;
    }
    return result;
}

int findRoot(QList<int> &parent, int i)
{
    while (parent.at(i) != i)
        i = parent[i] = parent.at(parent.at(i));
    return i;
}

} // namespace

NodeClasses::NodeClasses(const SolverInput &input)
    : m_input(input)
{
    QMap<QList<int>, int> classOfSignature;
    for (int n = 0; n < input.capacityMilli.size(); ++n) {
        const QList<int> key = signature(input, n);
        auto it = classOfSignature.find(key);
        if (it == classOfSignature.end()) {
            it = classOfSignature.insert(key, int(m_members.size()));
            m_members.append(QList<int>());
        }
        m_classOf << it.value();
        m_members[it.value()] << n;
    }
}

bool NodeClasses::reduces() const
{
    return m_members.size() < m_classOf.size();
}

SolverInput NodeClasses::reducedInput() const
{
    SolverInput reduced = m_input;
    reduced.capacityMilli.clear();
    reduced.baseBalance.clear();
    for (const QList<int> &members : m_members) {
        reduced.capacityMilli << m_input.capacityMilli.at(members.first());
        reduced.baseBalance << m_input.baseBalance.at(members.first());
    }
    for (SolverUnit &unit : reduced.units) {
        const SolverUnit full = unit;
        unit.nodes.clear();
        unit.installs.clear();
        unit.balance.clear();
        for (int k = 0; k < full.nodes.size(); ++k) {
            const int cls = m_classOf.at(full.nodes.at(k));
            if (m_members.at(cls).first() != full.nodes.at(k))
                continue;
            unit.nodes << cls;
            unit.installs << full.installs.at(k);
            unit.balance << full.balance.at(k);
        }
    }
    return reduced;
}

QList<int> NodeClasses::unitsOnClass(const QList<int> &classOfUnit, int cls) const
{
    QList<int> units;
    for (int u = 0; u < classOfUnit.size(); ++u) {
        if (classOfUnit.at(u) == cls)
            units << u;
    }
    return units;
}

/// The units of @p units joined by connectors among themselves, each group in ascending order.
QList<QList<int>> NodeClasses::clusters(const QList<int> &units) const
{
    QList<int> parent(m_input.units.size());
    std::iota(parent.begin(), parent.end(), 0);
    QList<bool> here(m_input.units.size(), false);
    for (const int u : units)
        here[u] = true;
    for (const SolverLink &link : m_input.links) {
        if (here.at(link.a) && here.at(link.b))
            parent[findRoot(parent, link.a)] = findRoot(parent, link.b);
    }
    QMap<int, QList<int>> byRoot;
    for (const int u : units)
        byRoot[findRoot(parent, u)] << u;
    QList<QList<int>> result = byRoot.values();
    std::sort(result.begin(), result.end(),
              [](const QList<int> &a, const QList<int> &b) { return a.first() < b.first(); });
    return result;
}

bool NodeClasses::needsNoInstall(const QList<int> &cluster, int node) const
{
    return std::all_of(cluster.cbegin(), cluster.cend(), [&](int u) {
        const SolverUnit &unit = m_input.units.at(u);
        return unit.installs.at(unit.nodes.indexOf(node)).isEmpty();
    });
}

int NodeClasses::balanceOf(const QList<int> &cluster, int node) const
{
    int sum = 0;
    for (const int u : cluster)
        sum += m_input.units.at(u).balance.at(m_input.units.at(u).nodes.indexOf(node));
    return sum;
}

QList<int> NodeClasses::spread(const QList<int> &classOfUnit) const
{
    QList<int> nodeOfUnit;
    for (const int cls : classOfUnit)
        nodeOfUnit << m_members.at(cls).first();
    for (int cls = 0; cls < m_members.size(); ++cls) {
        const QList<int> &members = m_members.at(cls);
        if (members.size() < 2)
            continue;
        QList<int> load;
        for (const int n : members)
            load << m_input.baseBalance.at(n);
        QList<QList<int>> movable;
        for (const QList<int> &cluster : clusters(unitsOnClass(classOfUnit, cls))) {
            if (needsNoInstall(cluster, members.first()))
                movable << cluster;
            else
                load[0] += balanceOf(cluster, members.first());
        }
        // Largest first onto the least loaded: the classic greedy balance; stable, so the same
        // input always gives the same plan.
        std::stable_sort(movable.begin(), movable.end(),
                         [&](const QList<int> &a, const QList<int> &b) {
                             return balanceOf(a, members.first()) > balanceOf(b, members.first());
                         });
        for (const QList<int> &cluster : std::as_const(movable)) {
            int best = 0;
            for (int m = 1; m < members.size(); ++m) {
                if (load.at(m) + balanceOf(cluster, members.at(m))
                    < load.at(best) + balanceOf(cluster, members.at(best)))
                    best = m;
            }
            load[best] += balanceOf(cluster, members.at(best));
            for (const int u : cluster)
                nodeOfUnit[u] = members.at(best);
        }
    }
    return nodeOfUnit;
}

} // namespace Planner
