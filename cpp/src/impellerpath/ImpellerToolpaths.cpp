// Impeller toolpaths: the four strategies (Strategies.h) over every channel kind, on two threads,
// then turned about the axis to every channel and placed again there (see the header).
#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include "ChannelGeometry.h"
#include "PassChecks.h"
#include "StockEnvelope.h"
#include "Strategies.h"

#include <aeronc/core/Error.h>

#include <TopExp.hxx>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>

namespace aeronc::impellerpath {

double CutterShape::radiusAt(double h) const {
    return tipRadius + std::max(h, 0.0) * std::sin(taperDeg * kPi / 180);
}

ImpellerProgram impellerToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                                  const impeller::ImpellerDimensions& d, const CutterShape& rougher,
                                  const CutterShape& finisher, const PathOptions& opt) {
    return impellerToolpaths(part, f, d, RouteCutters{rougher, finisher, std::nullopt}, opt);
}

ImpellerProgram impellerToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                                  const impeller::ImpellerDimensions& d, const RouteCutters& cutters,
                                  const PathOptions& opt) {
    const CutterShape& rougher = cutters.rougher;
    const CutterShape& finisher = cutters.finisher;
    if (f.blades.size() < 2) throw inputError("impeller toolpaths: the part has fewer than two blades");
    std::vector<const CutterShape*> all{&rougher, &finisher};
    if (cutters.filletBall) all.push_back(&*cutters.filletBall);
    for (const auto* c : all)
        if (!(c->tipRadius > 0) || !(c->fluteLength > c->tipRadius) || !(c->reach >= c->fluteLength) ||
            !(c->shankRadius >= c->tipRadius) || c->taperDeg < 0 || c->taperDeg >= 15 || !(c->feed > 0) || !(c->rpm > 0))
            throw inputError("impeller toolpaths: cutter " + c->id + " has impossible dimensions or cutting data");
    // Where the channel is shallower than the ball, the passes leave it (the ball does not fit there).
    if (2 * rougher.tipRadius + 2 * opt.roughAllowance > d.channelWidth(rougher.tipRadius))
        throw inputError("impeller toolpaths: the roughing ball " + rougher.id + " with the allowance is wider than the "
                         "narrowest channel where it is as deep as the ball's radius (" +
                         std::to_string(d.channelWidth(rougher.tipRadius)) + " mm)");
    if (cutters.filletBall && !(d.filletRadius > 0))
        throw inputError("impeller toolpaths: fillet finishing asked for a part without root fillets");
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    const int n = static_cast<int>(f.blades.size());
    const int kinds = f.splitterCount > 0 ? 2 : 1;  // channel kinds repeating about the axis
    const double pitch = 2 * kPi / f.bladeCount;
    const int channels = opt.channels > 0 ? std::min(opt.channels, n) : n;

    ImpellerProgram prog;
    Operation rough{"rough_channels", rougher, {}}, blades{"finish_blades", finisher, {}}, hub{"finish_hub", finisher, {}};
    Operation fillets{"finish_fillets", cutters.filletBall.value_or(finisher), {}};
    // Base moves by kind; kind `kinds` is the inducer (with splitters only), once per main blade.
    const int bases = kinds + (kinds == 2 ? 1 : 0);
    std::vector<std::vector<Move>> baseRough(bases), baseBlades(bases), baseHub(bases), baseFillets(bases);
    const Frame frame(f);
    // Each operation of each channel kind is independent: two threads take the next in turn,
    // roughing (the most positions) first. Each measures with a channel of its own (the distance
    // queries keep state); results are merged in a fixed order, so they do not depend on timing.
    struct Task {
        int kind, op;
        CheckResult check;
        std::exception_ptr error;
    };
    std::vector<Task> tasks;
    for (int op = 0; op < 4; ++op)
        for (int k = 0; k < bases; ++k) {
            if (op == 2 && k == kinds) continue;  // the inducer's walls are the main blades', finished whole
            if (op == 3 && (!cutters.filletBall || k == kinds)) continue;
            tasks.push_back({k, op, {}, nullptr});
        }
    // The blank is meshed here, before the threads share the part.
    const StockEnvelope stock(impeller::outerProfile(part, f, opt.blankAllowance), frame);
    auto linksFor = [&](const CutterShape& c) { return Links{stock, stock.top() + c.tipRadius + opt.safeDistance, opt.rapidClearance}; };
    const Links roughLinks = linksFor(rougher), finishLinks = linksFor(finisher);
    const Links filletLinks = linksFor(fillets.cutter);
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t i; (i = next++) < tasks.size();) {
            Task& t = tasks[i];
            try {
                const Channel ch = t.kind == kinds ? Channel(faces, f, 0, 2) : Channel(faces, f, t.kind);
                if (t.op == 0) roughChannel(ch, rougher, opt, roughLinks, t.check, baseRough[t.kind]);
                if (t.op == 1) finishHub(ch, finisher, d.filletRadius, opt, finishLinks, t.check, baseHub[t.kind]);
                if (t.op == 2) {
                    finishWall(ch, false, finisher, opt, finishLinks, t.check, baseBlades[t.kind]);
                    finishWall(ch, true, finisher, opt, finishLinks, t.check, baseBlades[t.kind]);
                }
                if (t.op == 3) {
                    finishFillet(ch, false, fillets.cutter, d.filletRadius, opt, filletLinks, t.check, baseFillets[t.kind]);
                    finishFillet(ch, true, fillets.cutter, d.filletRadius, opt, filletLinks, t.check, baseFillets[t.kind]);
                }
            } catch (...) {
                t.error = std::current_exception();
            }
        }
    };
    std::thread second(work);
    work();
    second.join();
    for (const Task& t : tasks) {
        if (t.error) std::rethrow_exception(t.error);
        merge(prog.check, t.check);
    }
    // Every other channel: its kind's base turned by its pattern step, then placed again against
    // its own blades and hub, since exported blades are not exact copies (a turned position may
    // gouge or touch there): each (channel, operation, base) in turn on the two threads.
    std::vector<std::vector<Move>>* byOp[4] = {&baseRough, &baseHub, &baseBlades, &baseFillets};
    const CutterShape* cutterOf[4] = {&rougher, &finisher, &finisher, &fillets.cutter};
    const Links* linksOf[4] = {&roughLinks, &finishLinks, &finishLinks, &filletLinks};
    struct Turned {
        int channel, op, base;
        CheckResult check;
        std::vector<Move> moves;
        std::exception_ptr error;
    };
    std::vector<Turned> turned;
    for (int c = kinds; c < channels; ++c)
        for (int op = 0; op < 4; ++op)
            for (int b : {c % kinds, kinds})
                if ((b < kinds || (c % kinds == 0 && bases > kinds)) && !(*byOp[op])[b].empty())
                    turned.push_back({c, op, b, {}, {}, nullptr});
    next = 0;
    auto placeAgain = [&] {
        for (size_t i; (i = next++) < turned.size();) {
            Turned& t = turned[i];
            try {
                const Channel ch = t.base == kinds ? Channel(faces, f, t.channel, t.channel + 2) : Channel(faces, f, t.channel);
                Checker check{ch, *cutterOf[t.op], opt, t.check, t.op == 0 ? opt.roughAllowance : 0.0};
                placeTurned((*byOp[t.op])[t.base], (t.channel / kinds) * pitch, check, *linksOf[t.op], t.moves);
            } catch (...) {
                t.error = std::current_exception();
            }
        }
    };
    std::thread other(placeAgain);
    placeAgain();
    other.join();
    for (const Turned& t : turned) {
        if (t.error) std::rethrow_exception(t.error);
        merge(prog.check, t.check);
    }
    // The channels in angular order; the inducer ahead of a main blade's channel follows it.
    Operation* opOf[4] = {&rough, &hub, &blades, &fillets};
    for (int c = 0; c < channels; ++c)
        for (int op : {0, 2, 1, 3})
            for (int b : {c % kinds, kinds}) {
                if (b == kinds && !(c % kinds == 0 && bases > kinds)) continue;
                const std::vector<Move>* moves = &(*byOp[op])[b];
                if (c >= kinds) {
                    if (moves->empty()) continue;
                    // turned[] holds the tasks in (channel, op, base) order; assembly takes them
                    // in (channel, rough/blades/hub/fillets, base) order: find this one.
                    auto it = std::find_if(turned.begin(), turned.end(),
                                           [&](const Turned& t) { return t.channel == c && t.op == op && t.base == b; });
                    moves = &it->moves;
                }
                opOf[op]->moves.insert(opOf[op]->moves.end(), moves->begin(), moves->end());
            }
    prog.operations = {rough, blades, hub};
    if (cutters.filletBall) prog.operations.push_back(fillets);
    return prog;
}

}  // namespace aeronc::impellerpath
