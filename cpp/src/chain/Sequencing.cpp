#include <aeronc/chain/Sequencing.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <tuple>

namespace aeronc::chain {

namespace {

constexpr double kGain = 1e-7;  // mm: a move must shorten the path by more than this

double dist(const Point2& a, const Point2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

// The groups and precedences the rules give one setup's enabled units.
struct Ordering {
    std::vector<std::vector<int>> blocks;        // local indices, blocks in order
    std::vector<std::vector<int>> predecessors;  // local index -> local indices within its block
};

class SetupSequencer {
public:
    SetupSequencer(const MachiningChain& chain, std::vector<int> units) : chain_(chain), ids_(std::move(units)) {
        for (const ChainElement& e : chain.elements) elements_[e.id] = &e;
        keys_.assign(ids_.size(), {});
        for (std::size_t i = 0; i < ids_.size(); ++i) {
            const int r = chain.processTemplate.rank(unit(i).step);
            keys_[i].push_back(r < 0 ? 1e9 : r);
        }
    }

    // Applies the template's rules; returns the rules-only order and the optimised one.
    std::pair<std::vector<int>, std::vector<int>> run(bool optimise, std::optional<Point2>& rulesEnd,
                                                      std::optional<Point2>& optEnd) {
        if (ids_.empty()) return {};
        bool centreOut = false;
        for (const SequencingRule& r : chain_.processTemplate.rules) {
            switch (r.kind) {
                case RuleKind::ProcessOrder: processOrder(r.largerToolFirst); break;
                case RuleKind::OuterBeforeInner:
                    pushKey([&](const MachiningUnit& u) {
                        return std::find(r.featureTypes.begin(), r.featureTypes.end(), u.featureType) !=
                                       r.featureTypes.end()
                                   ? 0.0
                                   : 1.0;
                    });
                    break;
                case RuleKind::FeatureTypeOrder:
                    pushKey([&](const MachiningUnit& u) {
                        const auto it = std::find(r.featureTypes.begin(), r.featureTypes.end(), u.featureType);
                        return static_cast<double>(it - r.featureTypes.begin());
                    });
                    break;
                case RuleKind::HigherZFirst: parentEdges(); break;
                case RuleKind::CentreOut: centreOut = true; break;
            }
        }
        holdParentsFirst();
        const Ordering o = ordering();

        // Rule 5 (or the unit order when the template leaves it out) inside the groups.
        Point2 lo{1e300, 1e300}, hi{-1e300, -1e300};
        for (std::size_t i = 0; i < ids_.size(); ++i)
            for (int c = 0; c < 2; ++c) lo[c] = std::min(lo[c], unit(i).at[c]), hi[c] = std::max(hi[c], unit(i).at[c]);
        const Point2 centre{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
        auto tieKey = [&](int i) {
            const Point2& p = unit(static_cast<std::size_t>(i)).at;
            if (!centreOut) return std::make_tuple(0.0, 0.0, ids_[static_cast<std::size_t>(i)]);
            const double r = std::round(dist(p, centre) * 1e3);  // µm: mirrored units tie exactly
            return std::make_tuple(r, std::atan2(p[1] - centre[1], p[0] - centre[0]),
                                   ids_[static_cast<std::size_t>(i)]);
        };

        std::vector<int> rulesOnly, optimised;
        for (const auto& block : o.blocks) {
            std::map<int, int> local;  // setup index -> block index
            for (std::size_t k = 0; k < block.size(); ++k) local[block[k]] = static_cast<int>(k);
            PathProblem p;
            p.predecessors.resize(block.size());
            for (std::size_t k = 0; k < block.size(); ++k) {
                p.points.push_back(unit(static_cast<std::size_t>(block[k])).at);
                for (int pr : o.predecessors[static_cast<std::size_t>(block[k])]) p.predecessors[k].push_back(local[pr]);
            }
            // Kahn's order with the tie key.
            std::vector<int> waiting(block.size());
            std::vector<std::vector<int>> next(block.size());
            for (std::size_t k = 0; k < block.size(); ++k) {
                waiting[k] = static_cast<int>(p.predecessors[k].size());
                for (int pr : p.predecessors[k]) next[static_cast<std::size_t>(pr)].push_back(static_cast<int>(k));
            }
            using Entry = std::pair<std::tuple<double, double, int>, int>;
            std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> ready;
            for (std::size_t k = 0; k < block.size(); ++k)
                if (!waiting[k]) ready.push({tieKey(block[k]), static_cast<int>(k)});
            std::vector<int> byRules;
            while (!ready.empty()) {
                const int k = ready.top().second;
                ready.pop();
                byRules.push_back(k);
                for (int s : next[static_cast<std::size_t>(k)])
                    if (--waiting[static_cast<std::size_t>(s)] == 0) ready.push({tieKey(block[static_cast<std::size_t>(s)]), s});
            }

            for (int k : byRules) rulesOnly.push_back(block[static_cast<std::size_t>(k)]);
            if (!byRules.empty()) rulesEnd = p.points[static_cast<std::size_t>(byRules.back())];

            // Shorter travel: nearest neighbour, improved; it replaces the rules' own order when
            // shorter (from where the previous group ended).
            std::vector<int> best = byRules;
            if (optimise && block.size() > 1) {
                p.start = optEnd;
                std::vector<int> nn = nearestNeighbour(p, optEnd ? -1 : byRules.front());
                improvePath(p, nn);
                if (pathLength(p, nn) < pathLength(p, best)) best.swap(nn);
            }
            for (int k : best) optimised.push_back(block[static_cast<std::size_t>(k)]);
            if (!best.empty()) optEnd = p.points[static_cast<std::size_t>(best.back())];
        }
        for (int& i : rulesOnly) i = ids_[static_cast<std::size_t>(i)];
        for (int& i : optimised) i = ids_[static_cast<std::size_t>(i)];
        return {rulesOnly, optimised};
    }

private:
    const MachiningUnit& unit(std::size_t i) const { return chain_.units[static_cast<std::size_t>(ids_[i])]; }

    int depthOf(int element) const {
        int d = 0;
        for (auto it = elements_.find(element); it != elements_.end() && it->second->parent >= 0 && d < 1000;
             it = elements_.find(it->second->parent))
            ++d;
        return d;
    }

    // A key rule: a new key per unit; along a parent -> child edge whose units agree on every
    // key before it, the child's key is raised to the parent's so the edge still holds.
    template <class KeyOf>
    void pushKey(KeyOf keyOf) {
        for (std::size_t i = 0; i < ids_.size(); ++i) keys_[i].push_back(keyOf(unit(i)));
        const std::size_t k = keys_.front().size() - 1;
        for (const auto& [a, b] : edges_) {
            const auto& ka = keys_[static_cast<std::size_t>(a)];
            auto& kb = keys_[static_cast<std::size_t>(b)];
            if (std::equal(ka.begin(), ka.begin() + static_cast<long>(k), kb.begin())) kb[k] = std::max(kb[k], ka[k]);
        }
    }

    // Rule 1: the larger tool first (or the smaller); a tool's units stay together.
    void processOrder(bool largerFirst) {
        std::vector<const ChainTool*> tools;
        for (std::size_t i = 0; i < ids_.size(); ++i) {
            const ChainTool* t = chain_.tool(unit(i).tool);
            if (t && std::find(tools.begin(), tools.end(), t) == tools.end()) tools.push_back(t);
        }
        std::sort(tools.begin(), tools.end(), [&](const ChainTool* a, const ChainTool* b) {
            if (std::fabs(a->diameter - b->diameter) > 1e-9) return largerFirst ? a->diameter > b->diameter
                                                                                : a->diameter < b->diameter;
            if (std::fabs(a->cornerRadius - b->cornerRadius) > 1e-9) return a->cornerRadius > b->cornerRadius;
            return a->id < b->id;
        });
        pushKey([&](const MachiningUnit& u) {
            const ChainTool* t = chain_.tool(u.tool);
            const auto it = std::find(tools.begin(), tools.end(), t);
            return static_cast<double>(it - tools.begin());
        });
    }

    // Rule 3: the unit of the nearest ancestor machined in the same step goes first when higher.
    void parentEdges() {
        std::map<std::pair<int, StepCode>, int> byElement;
        for (std::size_t i = 0; i < ids_.size(); ++i)
            byElement.emplace(std::make_pair(unit(i).element, unit(i).step), static_cast<int>(i));
        std::vector<std::tuple<int, int, int>> found;  // depth of the parent, parent, child
        for (std::size_t i = 0; i < ids_.size(); ++i) {
            const MachiningUnit& u = unit(i);
            int guard = 0;
            for (auto e = elements_.find(u.element); e != elements_.end() && e->second->parent >= 0 && guard++ < 1000;) {
                const auto p = byElement.find({e->second->parent, u.step});
                if (p != byElement.end()) {
                    if (unit(static_cast<std::size_t>(p->second)).bottom > u.bottom + 1e-9)
                        found.emplace_back(depthOf(unit(static_cast<std::size_t>(p->second)).element), p->second,
                                           static_cast<int>(i));
                    break;
                }
                e = elements_.find(e->second->parent);
            }
        }
        // Parents first, so a raised key runs down a whole branch.
        std::sort(found.begin(), found.end());
        for (const auto& [d, a, b] : found) edges_.emplace_back(a, b);
    }

    // Rule 3 holds over every key rule: a child's unit starts below material only its parent's
    // unit removes, so a child that a key would send first (a larger tool under a narrow parent)
    // goes right after its parent's group instead, still ordered by its own keys there.
    // Appending the child's keys to the parent's sorts it after every unit keyed like the parent
    // and before every unit keyed higher.
    void holdParentsFirst() {
        // Edges run parents first and only raise keys, so a second pass finds nothing to do
        // unless a deeper edge came first.
        for (bool changed = true; changed;) {
            changed = false;
            for (const auto& [a, b] : edges_) {
                const auto& ka = keys_[static_cast<std::size_t>(a)];
                auto& kb = keys_[static_cast<std::size_t>(b)];
                if (!(kb < ka)) continue;
                std::vector<double> raised = ka;
                const auto own = std::mismatch(kb.begin(), kb.end(), ka.begin(), ka.end()).first;
                raised.insert(raised.end(), own, kb.end());
                kb.swap(raised);
                changed = true;
            }
        }
    }

    Ordering ordering() const {
        std::vector<int> idx(ids_.size());
        for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
        std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) {
            return keys_[static_cast<std::size_t>(a)] < keys_[static_cast<std::size_t>(b)];
        });
        Ordering o;
        std::vector<int> blockOf(ids_.size());
        for (std::size_t k = 0; k < idx.size(); ++k) {
            if (k == 0 || keys_[static_cast<std::size_t>(idx[k])] != keys_[static_cast<std::size_t>(idx[k - 1])])
                o.blocks.emplace_back();
            o.blocks.back().push_back(idx[k]);
            blockOf[static_cast<std::size_t>(idx[k])] = static_cast<int>(o.blocks.size()) - 1;
        }
        o.predecessors.resize(ids_.size());
        // An edge across groups already holds or was overruled by a rule of higher priority.
        for (const auto& [a, b] : edges_)
            if (blockOf[static_cast<std::size_t>(a)] == blockOf[static_cast<std::size_t>(b)])
                o.predecessors[static_cast<std::size_t>(b)].push_back(a);
        return o;
    }

    const MachiningChain& chain_;
    std::vector<int> ids_;
    std::map<int, const ChainElement*> elements_;
    std::vector<std::vector<double>> keys_;
    std::vector<std::pair<int, int>> edges_;
};

}  // namespace

double pathLength(const PathProblem& p, const std::vector<int>& path) {
    double len = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Point2& q = p.points[static_cast<std::size_t>(path[i])];
        if (i > 0) len += dist(p.points[static_cast<std::size_t>(path[i - 1])], q);
        else if (p.start) len += dist(*p.start, q);
    }
    return len;
}

bool respectsPrecedence(const PathProblem& p, const std::vector<int>& path) {
    std::vector<int> pos(p.points.size(), -1);
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] < 0 || static_cast<std::size_t>(path[i]) >= pos.size() || pos[static_cast<std::size_t>(path[i])] >= 0)
            return false;
        pos[static_cast<std::size_t>(path[i])] = static_cast<int>(i);
    }
    for (std::size_t i = 0; i < p.points.size(); ++i) {
        if (pos[i] < 0) return false;
        for (int pr : p.predecessors[i])
            if (pos[static_cast<std::size_t>(pr)] > pos[i]) return false;
    }
    return true;
}

std::vector<int> nearestNeighbour(const PathProblem& p, int first) {
    const std::size_t n = p.points.size();
    std::vector<int> waiting(n), path;
    std::vector<std::vector<int>> next(n);
    for (std::size_t i = 0; i < n; ++i) {
        waiting[i] = static_cast<int>(p.predecessors[i].size());
        for (int pr : p.predecessors[i]) next[static_cast<std::size_t>(pr)].push_back(static_cast<int>(i));
    }
    std::vector<int> ready;
    for (std::size_t i = 0; i < n; ++i)
        if (!waiting[i]) ready.push_back(static_cast<int>(i));
    std::optional<Point2> at = p.start;
    path.reserve(n);
    while (!ready.empty()) {
        std::size_t pick = 0;
        if (at) {
            double best = 1e300;
            for (std::size_t k = 0; k < ready.size(); ++k) {
                const double d = dist(*at, p.points[static_cast<std::size_t>(ready[k])]);
                if (d < best - 1e-12 || (d <= best + 1e-12 && ready[k] < ready[pick])) best = d, pick = k;
            }
        } else {
            const auto it = std::find(ready.begin(), ready.end(), first);
            pick = it != ready.end() ? static_cast<std::size_t>(it - ready.begin())
                                     : static_cast<std::size_t>(std::min_element(ready.begin(), ready.end()) - ready.begin());
        }
        const int i = ready[pick];
        ready[pick] = ready.back();
        ready.pop_back();
        path.push_back(i);
        at = p.points[static_cast<std::size_t>(i)];
        for (int s : next[static_cast<std::size_t>(i)])
            if (--waiting[static_cast<std::size_t>(s)] == 0) ready.push_back(s);
    }
    return path;
}

void improvePath(const PathProblem& p, std::vector<int>& path) {
    const long N = static_cast<long>(path.size());
    if (N < 2) return;
    const std::size_t n = path.size();
    std::vector<std::vector<int>> succ(p.points.size());
    for (std::size_t i = 0; i < p.predecessors.size(); ++i)
        for (int pr : p.predecessors[i]) succ[static_cast<std::size_t>(pr)].push_back(static_cast<int>(i));

    // Candidate moves only towards each point's nearest neighbours (the usual neighbour-list
    // 2-opt and Or-opt): quadratic scans would take minutes on a thousand units.
    constexpr std::size_t kNeighbours = 10;
    std::vector<std::vector<int>> near(p.points.size());
    {
        std::vector<std::pair<double, int>> d;
        for (int a : path) {
            d.clear();
            for (int b : path)
                if (a != b) d.emplace_back(dist(p.points[static_cast<std::size_t>(a)], p.points[static_cast<std::size_t>(b)]), b);
            const std::size_t k = std::min(kNeighbours, d.size());
            std::partial_sort(d.begin(), d.begin() + static_cast<long>(k), d.end());
            for (std::size_t i = 0; i < k; ++i) near[static_cast<std::size_t>(a)].push_back(d[i].second);
        }
    }
    std::vector<long> pos(p.points.size());
    auto reindex = [&] {
        for (std::size_t i = 0; i < n; ++i) pos[static_cast<std::size_t>(path[i])] = static_cast<long>(i);
    };
    reindex();
    auto pt = [&](long i) -> const Point2& { return p.points[static_cast<std::size_t>(path[static_cast<std::size_t>(i)])]; };
    auto at = [&](long i) -> const Point2* {  // position i, or the start before the path
        if (i >= 0 && i < N) return &pt(i);
        return i == -1 && p.start ? &*p.start : nullptr;
    };

    // 2-opt: reverse path[i..j]; no precedence may lie inside the run.
    auto twoOpt = [&](long i, long j) {
        if (i < 0 || j <= i || j >= N) return false;
        const Point2* before = at(i - 1);
        const Point2* after = j + 1 < N ? &pt(j + 1) : nullptr;
        double delta = 0;
        if (before) delta += dist(*before, pt(j)) - dist(*before, pt(i));
        if (after) delta += dist(pt(i), *after) - dist(pt(j), *after);
        if (delta >= -kGain) return false;
        for (long k = i + 1; k <= j; ++k)
            for (int pr : p.predecessors[static_cast<std::size_t>(path[static_cast<std::size_t>(k)])])
                if (pos[static_cast<std::size_t>(pr)] >= i) return false;
        std::reverse(path.begin() + i, path.begin() + j + 1);
        reindex();
        return true;
    };

    // Or-opt: move path[i..e] (1 to 3 units) between positions k and k + 1, either way round.
    auto orOpt = [&](long i, long e, long k) {
        if (i < 0 || e >= N || e < i || k < -1 || k >= N || (k >= i - 1 && k <= e)) return false;
        const Point2* a = at(i - 1);
        const Point2* b = e + 1 < N ? &pt(e + 1) : nullptr;
        double removed = 0;
        if (a) removed += dist(*a, pt(i));
        if (b) removed += dist(pt(e), *b);
        if (a && b) removed -= dist(*a, *b);
        const Point2* x = at(k);
        const Point2* y = k + 1 < N ? &pt(k + 1) : nullptr;
        for (int reversed = 0; reversed < (e > i ? 2 : 1); ++reversed) {
            const Point2& first = reversed ? pt(e) : pt(i);
            const Point2& last = reversed ? pt(i) : pt(e);
            double added = 0;
            if (x) added += dist(*x, first);
            if (y) added += dist(last, *y);
            if (x && y) added -= dist(*x, *y);
            if (added - removed >= -kGain) continue;
            bool ok = true;
            for (long s = i; s <= e && ok; ++s) {
                const int u = path[static_cast<std::size_t>(s)];
                if (reversed)  // the run must not be tied inside itself
                    for (int pr : p.predecessors[static_cast<std::size_t>(u)])
                        if (pos[static_cast<std::size_t>(pr)] >= i && pos[static_cast<std::size_t>(pr)] <= e) ok = false;
                if (k > e) {  // moving later: nothing it jumps over may need it first
                    for (int sc : succ[static_cast<std::size_t>(u)])
                        if (pos[static_cast<std::size_t>(sc)] > e && pos[static_cast<std::size_t>(sc)] <= k) ok = false;
                } else {  // moving earlier: nothing it jumps over may be needed first
                    for (int pr : p.predecessors[static_cast<std::size_t>(u)])
                        if (pos[static_cast<std::size_t>(pr)] > k && pos[static_cast<std::size_t>(pr)] < i) ok = false;
                }
            }
            if (!ok) continue;
            std::vector<int> run(path.begin() + i, path.begin() + e + 1);
            if (reversed) std::reverse(run.begin(), run.end());
            std::vector<int> out;
            out.reserve(n);
            if (k == -1) out.insert(out.end(), run.begin(), run.end());
            for (long q = 0; q < N; ++q) {
                if (q >= i && q <= e) continue;
                out.push_back(path[static_cast<std::size_t>(q)]);
                if (q == k) out.insert(out.end(), run.begin(), run.end());
            }
            path.swap(out);
            reindex();
            return true;
        }
        return false;
    };

    for (int round = 0; round < 1000; ++round) {
        bool improved = false;
        for (long i = 0; i < N; ++i) {
            // New edge from the point before i to a neighbour of it, or from i to one after.
            if (i > 0) {
                for (int c : near[static_cast<std::size_t>(path[static_cast<std::size_t>(i - 1)])])
                    if (twoOpt(i, pos[static_cast<std::size_t>(c)])) improved = true;
            } else {
                for (long j = 1; j < N; ++j) improved |= twoOpt(0, j);
            }
            for (int c : near[static_cast<std::size_t>(path[static_cast<std::size_t>(i)])])
                improved |= twoOpt(i, pos[static_cast<std::size_t>(c)] - 1);
            improved |= twoOpt(i, N - 1);  // the tail reversed: the path's free end
        }
        for (long len = 1; len <= 3; ++len)
            for (long i = 0; i + len <= N; ++i) {
                const long e = i + len - 1;
                bool moved = false;
                for (long end : {i, e}) {
                    for (int c : near[static_cast<std::size_t>(path[static_cast<std::size_t>(end)])]) {
                        const long k = pos[static_cast<std::size_t>(c)];
                        if ((moved = orOpt(i, e, k) || orOpt(i, e, k - 1))) break;
                    }
                    if (moved) break;
                }
                if (!moved) moved = orOpt(i, e, -1) || orOpt(i, e, N - 1);  // to either end
                improved |= moved;
            }
        if (!improved) break;
    }
}

double travelOf(const MachiningChain& chain, const std::vector<int>& order) {
    double t = 0;
    const MachiningUnit* prev = nullptr;
    for (int id : order) {
        if (id < 0 || static_cast<std::size_t>(id) >= chain.units.size()) continue;
        const MachiningUnit& u = chain.units[static_cast<std::size_t>(id)];
        if (!u.enabled) continue;
        if (prev && prev->setup == u.setup) t += dist(prev->at, u.at);
        prev = &u;
    }
    return t;
}

void sequence(MachiningChain& chain, bool optimise) {
    std::vector<int> rulesOnly, optimised;
    for (const ChainSetup& s : chain.setups) {
        std::vector<int> enabled, disabled;
        for (const MachiningUnit& u : chain.units) {
            if (u.setup != s.id) continue;
            (u.enabled ? enabled : disabled).push_back(u.id);
        }
        std::optional<Point2> rulesEnd, optEnd;
        SetupSequencer seq(chain, enabled);
        auto [r, o] = seq.run(optimise, rulesEnd, optEnd);
        rulesOnly.insert(rulesOnly.end(), r.begin(), r.end());
        rulesOnly.insert(rulesOnly.end(), disabled.begin(), disabled.end());
        optimised.insert(optimised.end(), o.begin(), o.end());
        optimised.insert(optimised.end(), disabled.begin(), disabled.end());
    }
    // Units of a setup the chain does not list still get a place.
    std::vector<char> placed(chain.units.size(), 0);
    for (int id : rulesOnly) placed[static_cast<std::size_t>(id)] = 1;
    for (const MachiningUnit& u : chain.units)
        if (!placed[static_cast<std::size_t>(u.id)]) rulesOnly.push_back(u.id), optimised.push_back(u.id);

    chain.travel.rulesOnly = travelOf(chain, rulesOnly);
    double opt = travelOf(chain, optimised);
    if (!optimise || opt > chain.travel.rulesOnly) {
        optimised = rulesOnly;
        opt = chain.travel.rulesOnly;
    }
    chain.travel.optimised = opt;
    chain.travel.savedPercent =
        chain.travel.rulesOnly > 0 ? 100.0 * (chain.travel.rulesOnly - opt) / chain.travel.rulesOnly : 0.0;
    chain.order = optimised;
    for (std::size_t i = 0; i < chain.order.size(); ++i)
        chain.units[static_cast<std::size_t>(chain.order[i])].order = static_cast<int>(i);
}

}  // namespace aeronc::chain
