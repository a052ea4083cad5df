// SPDX-License-Identifier: MIT
#include "placementsolver.h"

#include "nodeclasses.h"

#include <QElapsedTimer>
#include <QSet>

#include <z3++.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace Planner {

namespace {

void addSoft(z3::optimize &opt, const z3::expr &e, int weight, const char *objective)
{
    Z3_optimize_assert_soft(opt.ctx(), opt, e, std::to_string(weight).c_str(),
                            Z3_mk_string_symbol(opt.ctx(), objective));
}

/// The balance figure's levels, as multiples of the even share, above which a node costs one.
constexpr double BalanceLevels[] = {1.1, 1.5, 2.0};

/**
 * The largest problem (units × nodes) whose balance the solver proves after the nodes alike were
 * solved as one. Beyond it, proving takes seconds and how far Z3 gets in a given time varies
 * from run to run: the greedy spread stands, so the same input always gives the same plan.
 */
constexpr long long ProvenBalanceSize = 1000;

/// The installs @p placement needs, each once.
QSet<int> installsUsed(const SolverInput &input, const QList<int> &placement)
{
    QSet<int> used;
    for (int u = 0; u < placement.size(); ++u) {
        const SolverUnit &unit = input.units.at(u);
        for (const int install : unit.installs.at(unit.nodes.indexOf(placement.at(u))))
            used.insert(install);
    }
    return used;
}

/// The weight of the links @p placement puts across nodes.
long long crossingWeight(const SolverInput &input, const QList<int> &placement)
{
    long long weight = 0;
    for (const SolverLink &link : input.links)
        weight += placement.at(link.a) != placement.at(link.b) ? link.weight : 0;
    return weight;
}

/// The Z3 variables of one problem: x[u][k] is "unit u runs on its k-th node".
class Encoding
{
public:
    Encoding(z3::context &ctx, const SolverInput &input)
        : m_ctx(ctx)
        , m_input(input)
        , m_installs(ctx)
    {
        for (int u = 0; u < input.units.size(); ++u) {
            z3::expr_vector x(ctx);
            for (int k = 0; k < input.units.at(u).nodes.size(); ++k)
                x.push_back(
                    ctx.bool_const(("x" + std::to_string(u) + "_" + std::to_string(k)).c_str()));
            m_x.push_back(x);
        }
        for (int i = 0; i < input.installCount; ++i)
            m_installs.push_back(ctx.bool_const(("i" + std::to_string(i)).c_str()));
    }

    /// Each unit on exactly one of its nodes; an install wherever a unit needs one.
    template<typename Sink> void addPlacement(Sink &sink) const
    {
        for (int u = 0; u < m_input.units.size(); ++u) {
            const SolverUnit &unit = m_input.units.at(u);
            sink.add(z3::mk_or(m_x[u]));
            if (unit.nodes.size() > 1)
                sink.add(z3::atmost(m_x[u], 1));
            for (int k = 0; k < unit.nodes.size(); ++k) {
                for (const int install : unit.installs.at(k))
                    sink.add(z3::implies(m_x[u][k], m_installs[install]));
            }
        }
    }

    /// The capacity constraint of each limited node, or nothing when no unit takes CPU there.
    std::vector<std::pair<int, z3::expr>> capacities() const
    {
        std::vector<std::pair<int, z3::expr>> result;
        for (int n = 0; n < m_input.capacityMilli.size(); ++n) {
            if (m_input.capacityMilli.at(n) < 0)
                continue;
            if (!limitCanBind(m_input, n))
                continue;
            z3::expr_vector terms(m_ctx);
            std::vector<int> coefficients;
            forEachOn(n, [&](int u, int k) {
                if (m_input.units.at(u).cpuMilli > 0) {
                    terms.push_back(m_x[u][k]);
                    coefficients.push_back(m_input.units.at(u).cpuMilli);
                }
            });
            result.emplace_back(n,
                                z3::pble(terms, coefficients.data(), m_input.capacityMilli.at(n)));
        }
        return result;
    }

    /// "Link l crosses hosts" for every link, implied by its ends on different nodes.
    z3::expr_vector addCrossings(z3::optimize &opt) const
    {
        z3::expr_vector crossings(m_ctx);
        for (int l = 0; l < m_input.links.size(); ++l) {
            const SolverLink &link = m_input.links.at(l);
            const z3::expr cross = m_ctx.bool_const(("c" + std::to_string(l)).c_str());
            const SolverUnit &a = m_input.units.at(link.a);
            for (int k = 0; k < a.nodes.size(); ++k) {
                const int kb = m_input.units.at(link.b).nodes.indexOf(a.nodes.at(k));
                opt.add(kb < 0 ? z3::implies(m_x[link.a][k], cross)
                               : z3::implies(m_x[link.a][k] && !m_x[link.b][kb], cross));
            }
            crossings.push_back(cross);
        }
        return crossings;
    }

    /**
     * Soft limits on each node's balance figure at levels above the even share (the average over
     * the nodes): every level a node exceeds costs one. Pseudo-Boolean, as all else, so that the
     * optimiser stays on its SAT engine (a minimised maximum would bring in arithmetic, far
     * slower).
     */
    void addBalance(z3::optimize &opt) const
    {
        const double even = evenShare();
        for (int n = 0; n < m_input.baseBalance.size(); ++n) {
            z3::expr_vector terms(m_ctx);
            std::vector<int> coefficients;
            forEachOn(n, [&](int u, int k) {
                terms.push_back(m_x[u][k]);
                coefficients.push_back(m_input.units.at(u).balance.at(k));
            });
            for (const double level : BalanceLevels) {
                const int room = int(std::ceil(even * level)) - m_input.baseBalance.at(n);
                if (room >= 0 && !terms.empty())
                    addSoft(opt, z3::pble(terms, coefficients.data(), room), 1, "balance");
            }
        }
    }

    /// What addBalance() charges @p placement: the levels its nodes rise above.
    int balanceCost(const QList<int> &placement) const
    {
        QList<long long> figure;
        for (const int base : m_input.baseBalance)
            figure << base;
        for (int u = 0; u < placement.size(); ++u) {
            const SolverUnit &unit = m_input.units.at(u);
            figure[placement.at(u)] += unit.balance.at(unit.nodes.indexOf(placement.at(u)));
        }
        const double even = evenShare();
        int cost = 0;
        for (int n = 0; n < figure.size(); ++n) {
            for (const double level : BalanceLevels) {
                const long long room = (long long)std::ceil(even * level);
                cost += room >= m_input.baseBalance.at(n) && figure.at(n) > room ? 1 : 0;
            }
        }
        return cost;
    }

    const z3::expr_vector &installs() const { return m_installs; }

    /// The node of every unit in @p model; empty when the model does not place them all.
    QList<int> placement(const z3::model &model) const
    {
        QList<int> nodes;
        for (int u = 0; u < m_input.units.size(); ++u) {
            int chosen = -1;
            for (int k = 0; k < int(m_x[u].size()); ++k) {
                if (model.eval(m_x[u][k], true).is_true())
                    chosen = m_input.units.at(u).nodes.at(k);
            }
            if (chosen < 0)
                return {};
            nodes << chosen;
        }
        return nodes;
    }

private:
    /// The balance figure every node would have if the units were spread evenly.
    double evenShare() const
    {
        double total = 0;
        for (const int base : m_input.baseBalance)
            total += base;
        for (const SolverUnit &unit : m_input.units)
            total += *std::min_element(unit.balance.cbegin(), unit.balance.cend());
        return total / qMax<qsizetype>(1, m_input.baseBalance.size());
    }

    template<typename Visit> void forEachOn(int node, Visit visit) const
    {
        for (int u = 0; u < m_input.units.size(); ++u) {
            const int k = m_input.units.at(u).nodes.indexOf(node);
            if (k >= 0)
                visit(u, k);
        }
    }

    z3::context &m_ctx;
    const SolverInput &m_input;
    std::vector<z3::expr_vector> m_x;
    z3::expr_vector m_installs;
};

void setTimeout(z3::context &ctx, z3::optimize &opt, int ms)
{
    z3::params p(ctx);
    p.set("timeout", unsigned(qMax(1, ms)));
    opt.set(p);
}

/// Which nodes' capacities together rule every placement out (an unsatisfiable core).
QList<int> capacityConflict(const SolverInput &input, int timeoutMs)
{
    z3::context ctx;
    z3::solver solver(ctx);
    z3::params p(ctx);
    p.set("timeout", unsigned(qMax(1, timeoutMs)));
    solver.set(p);
    const Encoding encoding(ctx, input);
    encoding.addPlacement(solver);
    z3::expr_vector guards(ctx);
    QList<int> guardedNodes;
    for (const auto &[node, capacity] : encoding.capacities()) {
        const z3::expr guard = ctx.bool_const(("cap" + std::to_string(node)).c_str());
        solver.add(z3::implies(guard, capacity));
        guards.push_back(guard);
        guardedNodes << node;
    }
    QList<int> conflict;
    if (solver.check(guards) != z3::unsat)
        return conflict;
    const z3::expr_vector core = solver.unsat_core();
    for (int g = 0; g < int(guards.size()); ++g) {
        for (int c = 0; c < int(core.size()); ++c) {
            if (z3::eq(core[c], guards[g]))
                conflict << guardedNodes.at(g);
        }
    }
    return conflict;
}

/**
 * Lexicographic optimisation in stages, one objective each: the best value of a stage becomes a
 * hard bound of the next. Every stage's model is a valid placement, so when time runs out the
 * last one found is returned, good in the objectives that came before.
 */
class StagedOptimiser
{
public:
    StagedOptimiser(const SolverInput &input, const QElapsedTimer &clock)
        : m_input(input)
        , m_clock(clock)
        , m_opt(m_ctx)
        , m_encoding(m_ctx, input)
        , m_crossings(m_ctx)
    {
        m_encoding.addPlacement(m_opt);
        for (const auto &capacity : m_encoding.capacities()) {
            m_opt.add(capacity.second);
            m_limited = true;
        }
    }

    /// All three objectives, or only installs and connectors when @p balance is false.
    SolverOutput run(bool balance = true)
    {
        SolverOutput output;
        // The first stage also finds out whether there is any placement at all.
        const Outcome installs = m_limited
            ? stage(
                0.4, [this] { installObjective(); }, [this] { boundInstalls(); })
            : leastInstallsAlone();
        if (installs == Outcome::Unsat) {
            output.status = SolverOutput::Status::Infeasible;
            output.conflictingNodes = capacityConflict(m_input, qMax(1000, remaining(1.0)));
            return output;
        }
        if (installs == Outcome::NoModel && !fallbackPlacement()) {
            output.message = m_reason;
            return output;
        }
        // What crosses hosts matters from here on; the first stage is smaller without it.
        m_crossings = m_encoding.addCrossings(m_opt);
        const Outcome links = linkStage();
        output.nodeOfUnit = m_best;
        output.status = installs == Outcome::Proven && links == Outcome::Proven
            ? SolverOutput::Status::Optimal
            : SolverOutput::Status::Feasible;
        if (balance)
            balanceStage(output);
        output.message = m_reason;
        return output;
    }

    /**
     * Balances @p output's placement without more installs or crossing connector weight than it
     * has: the solver's placement replaces it when proven best or, unless @p provenOnly, better
     * by the same measure.
     */
    void balanceStage(SolverOutput &output, bool provenOnly = false)
    {
        if (m_crossings.empty() && !m_input.links.isEmpty())
            m_crossings = m_encoding.addCrossings(m_opt);
        m_best = output.nodeOfUnit;
        boundInstalls();
        boundLinks();
        const int before = m_encoding.balanceCost(m_best);
        // Balance only breaks ties: it gets what is left, at most a quarter of the budget.
        const Outcome balance = stage(
            qMin(1.0, 0.25 * m_input.timeoutMs / qMax(1, remaining(1.0))),
            [this] { m_encoding.addBalance(m_opt); }, [] {});
        output.balanceProven = balance == Outcome::Proven;
        if (output.balanceProven || (!provenOnly && m_encoding.balanceCost(m_best) < before))
            output.nodeOfUnit = m_best;
    }

private:
    enum class Outcome { Proven, Improved, NoModel, Unsat };

    /// What is left of the time budget, scaled by @p part (the share this stage may take).
    int remaining(double part) const
    {
        return qMax(1, int((m_input.timeoutMs - m_clock.elapsed()) * part));
    }

    bool keep(const z3::model &model)
    {
        QList<int> placement = m_encoding.placement(model);
        if (placement.isEmpty())
            return false;
        m_best = std::move(placement);
        return true;
    }

    /**
     * A placement when the first stage found none in time: with no CPU limit that could bind,
     * every unit on the first of its nodes is one; otherwise the solver looks for any, without
     * objectives, in what is left of the time.
     */
    bool fallbackPlacement()
    {
        if (!m_limited) {
            for (const SolverUnit &unit : m_input.units)
                m_best << unit.nodes.first();
            return true;
        }
        setTimeout(m_ctx, m_opt, remaining(1.0));
        return m_opt.check() == z3::sat && keep(m_opt.get_model());
    }

    template<typename Objective, typename Bound>
    Outcome stage(double part, Objective objective, Bound bound)
    {
        m_opt.push();
        objective();
        setTimeout(m_ctx, m_opt, remaining(part));
        const z3::check_result result = m_opt.check();
        bool kept = false;
        try {
            kept = result != z3::unsat && keep(m_opt.get_model());
        } catch (const z3::exception &) {
            // No model in time: the previous stage's stands.
        }
        if (result != z3::sat)
            m_reason = QString::fromUtf8(Z3_optimize_get_reason_unknown(m_ctx, m_opt));
        m_opt.pop();
        if (result == z3::unsat)
            return Outcome::Unsat;
        if (!kept)
            return Outcome::NoModel;
        bound();
        return result == z3::sat ? Outcome::Proven : Outcome::Improved;
    }

    /**
     * Connectors, starting from the installs of the best install plan: with them fixed, each
     * unit keeps only the nodes it needs nothing more on, and most connectors either surely
     * cross or surely need not — a far smaller problem. Its answer is the best when the solver
     * shows no placement with those installs' count crosses less; otherwise it bounds the full
     * search.
     */
    Outcome linkStage()
    {
        if (m_input.installCount > 0 && !m_best.isEmpty()) {
            const QList<int> start = linksWithInstallsFixed();
            if (!start.isEmpty()) {
                m_best = start;
                const bool least = nothingCrossesLess();
                boundLinks();
                if (least)
                    return Outcome::Proven;
            }
        }
        return stage(
            0.6, [this] { linkObjective(); }, [this] { boundLinks(); });
    }

    /// The least crossing placement that needs no install beyond those of the current one.
    QList<int> linksWithInstallsFixed() const
    {
        const QSet<int> used = installsUsed(m_input, m_best);
        SolverInput fixed = m_input;
        fixed.installCount = 0;
        fixed.installKind.clear();
        // The sub-problem ends when 30 % of what is left has passed on the same clock.
        fixed.timeoutMs = int(m_clock.elapsed()) + remaining(0.3);
        for (SolverUnit &unit : fixed.units) {
            const SolverUnit full = unit;
            unit = SolverUnit {{}, {}, {}, full.cpuMilli};
            for (int k = 0; k < full.nodes.size(); ++k) {
                const QList<int> &needs = full.installs.at(k);
                if (std::all_of(needs.cbegin(), needs.cend(),
                                [&](int i) { return used.contains(i); })) {
                    unit.nodes << full.nodes.at(k);
                    unit.installs << QList<int>();
                    unit.balance << full.balance.at(k);
                }
            }
        }
        // Connectors whose ends share no node cross whatever happens: left out of the search.
        fixed.links.removeIf([&](const SolverLink &link) {
            const QList<int> &b = fixed.units.at(link.b).nodes;
            const QList<int> &a = fixed.units.at(link.a).nodes;
            return std::none_of(a.cbegin(), a.cend(), [&](int n) { return b.contains(n); });
        });
        const SolverOutput output = StagedOptimiser(fixed, m_clock).run(false);
        return output.status == SolverOutput::Status::Optimal ? output.nodeOfUnit : QList<int>();
    }

    /// The solver shows that no placement within the installs' bound crosses less than m_best.
    bool nothingCrossesLess()
    {
        const long long weight = crossingWeight(m_input, m_best);
        if (weight == 0)
            return true;
        if (weight > std::numeric_limits<int>::max())
            return false;
        m_opt.push();
        m_opt.add(z3::pble(m_crossings, linkWeights().data(), int(weight - 1)));
        setTimeout(m_ctx, m_opt, remaining(0.5));
        const bool none = m_opt.check() == z3::unsat;
        m_opt.pop();
        return none;
    }

    /**
     * Without CPU limits, a unit that has a node where it needs no install never adds one: the
     * least installs are those of the other units alone, a far smaller problem. Its answer bounds
     * the installs of the whole and places every unit (the others on such a node).
     */
    Outcome leastInstallsAlone()
    {
        SolverInput reduced;
        reduced.installCount = m_input.installCount;
        QList<int> fullUnit;
        m_best = QList<int>(m_input.units.size(), -1);
        for (int u = 0; u < m_input.units.size(); ++u) {
            const SolverUnit &unit = m_input.units.at(u);
            const auto free
                = std::find_if(unit.installs.cbegin(), unit.installs.cend(),
                               [](const QList<int> &installs) { return installs.isEmpty(); });
            if (free != unit.installs.cend()) {
                m_best[u] = unit.nodes.at(int(free - unit.installs.cbegin()));
            } else {
                reduced.units << unit;
                fullUnit << u;
            }
        }
        z3::context ctx;
        z3::optimize opt(ctx);
        setTimeout(ctx, opt, remaining(0.4));
        const Encoding encoding(ctx, reduced);
        encoding.addPlacement(opt);
        for (int i = 0; i < int(encoding.installs().size()); ++i)
            addSoft(opt, !encoding.installs()[i], 1, "installs");
        const z3::check_result result = fullUnit.isEmpty() ? z3::sat : opt.check();
        QList<int> placement;
        try {
            placement = encoding.placement(opt.get_model());
        } catch (const z3::exception &) {
            // No model in time.
        }
        if (result != z3::sat)
            m_reason = QString::fromUtf8(Z3_optimize_get_reason_unknown(ctx, opt));
        if (placement.size() != fullUnit.size()) {
            m_best.clear();
            return result == z3::unsat ? Outcome::Unsat : Outcome::NoModel;
        }
        for (int r = 0; r < fullUnit.size(); ++r)
            m_best[fullUnit.at(r)] = placement.at(r);
        boundInstalls();
        return result == z3::sat ? Outcome::Proven : Outcome::Improved;
    }

    void installObjective()
    {
        for (int i = 0; i < int(m_encoding.installs().size()); ++i)
            addSoft(m_opt, !m_encoding.installs()[i], 1, "installs");
    }

    void linkObjective()
    {
        for (int l = 0; l < int(m_crossings.size()); ++l)
            addSoft(m_opt, !m_crossings[l], m_input.links.at(l).weight, "links");
    }

    std::vector<int> linkWeights() const
    {
        std::vector<int> weights;
        for (const SolverLink &link : m_input.links)
            weights.push_back(link.weight);
        return weights;
    }

    /// No more installs than the kept placement needs.
    void boundInstalls()
    {
        const z3::expr_vector &installs = m_encoding.installs();
        std::vector<int> ones(installs.size(), 1);
        if (!installs.empty())
            m_opt.add(z3::pble(installs, ones.data(), int(installsUsed(m_input, m_best).size())));
    }

    /// No more connector weight between hosts than the kept placement has.
    void boundLinks()
    {
        const long long crossing = crossingWeight(m_input, m_best);
        // A bound beyond what an int holds bounds nothing: left out.
        if (!m_crossings.empty() && crossing <= std::numeric_limits<int>::max())
            m_opt.add(z3::pble(m_crossings, linkWeights().data(), int(crossing)));
    }

    const SolverInput &m_input;
    const QElapsedTimer &m_clock;
    z3::context m_ctx;
    z3::optimize m_opt;
    Encoding m_encoding;
    z3::expr_vector m_crossings;
    bool m_limited = false; ///< some node's CPU limit could bind
    QList<int> m_best;
    QString m_reason;
};

/// Installs and connectors on one node per class, then spread and balanced on all nodes.
SolverOutput solveByClasses(const SolverInput &input, const NodeClasses &classes,
                            const QElapsedTimer &clock)
{
    const SolverInput reduced = classes.reducedInput();
    SolverOutput output = StagedOptimiser(reduced, clock).run(false);
    if (output.nodeOfUnit.isEmpty())
        return output;
    output.nodeOfUnit = classes.spread(output.nodeOfUnit);
    if (input.units.size() * input.capacityMilli.size() <= ProvenBalanceSize)
        StagedOptimiser(input, clock).balanceStage(output, true);
    return output;
}

} // namespace

bool limitCanBind(const SolverInput &input, int node)
{
    if (input.capacityMilli.at(node) < 0)
        return false;
    // A limit the units allowed there cannot reach even all together only costs solver time.
    long long total = 0;
    for (const SolverUnit &unit : input.units) {
        if (unit.cpuMilli > 0 && unit.nodes.contains(node))
            total += unit.cpuMilli;
    }
    return total > input.capacityMilli.at(node);
}

SolverOutput solvePlacement(const SolverInput &input)
{
    QElapsedTimer clock;
    clock.start();
    try {
        bool limited = false;
        for (int n = 0; n < input.capacityMilli.size(); ++n)
            limited = limited || limitCanBind(input, n);
        const NodeClasses classes(input);
        if (!limited && classes.reduces())
            return solveByClasses(input, classes, clock);
        return StagedOptimiser(input, clock).run();
    } catch (const z3::exception &e) {
        SolverOutput output;
        output.message = QString::fromUtf8(e.msg());
        return output;
    }
}

} // namespace Planner
