#pragma once
// The impeller process route (impeller paper §2): the rule library's steps that apply to the
// recognised part, each with the tool its rule chooses from the measured dimensions. No
// database here: kb/ImpellerRoute reads the rules and the tools.
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>

#include <optional>
#include <string>
#include <vector>

namespace aeronc::impeller {

// One row of the rule library (knowledge-base table impeller_route_step).
struct RouteRule {
    int position = 0;
    std::string operation;   // face, turn, drill, bore, rough_channels, finish_blades, finish_hub, finish_fillets
    std::string toolRule;    // face_mill, none, drill_in_bore, end_mill_in_bore, ball_in_channel,
                             // tapered_ball_in_channel, ball_in_fillet
    std::string strategy, description;
    double allowance = 0, clearance = 0;
};

// A tool the rules may choose: the knowledge base's face mills, flat, ball end mills and drills,
// and its tapered balls.
struct CuttingTool {
    std::string id, type;    // face, flat, bull, ball, drill, tapered_ball
    std::string material;
    double diameter = 0;     // tip (ball) diameter of a tapered ball
    double taperDeg = 0;     // half angle of a tapered ball
    double reach = 0, fluteLength = 0;
    double shankDiameter = 0;  // above the flutes (a plain end mill's is its diameter)
    int flutes = 0;
    // Diameter at height h above the ball's centre (a tapered ball widens, the others do not).
    double diameterAt(double h) const;
};

struct RouteStep {
    int position = 0;
    std::string operation, strategy, description, toolRule;
    double allowance = 0, clearance = 0;
    std::vector<int> faces;                // the faces it machines (none for the channels' volume)
    std::optional<CuttingTool> tool;       // none for a lathe step
    std::string toolReason;                // the limits the tool had to meet
};

struct ProcessRoute {
    std::vector<RouteStep> steps;
    std::vector<std::string> skipped;      // rules that do not apply to this part, and why
};

// The route: every rule whose features the part has, in position order, with its tool. Throws
// aeronc::inputError naming the step and the limits when no tool of `tools` fits, and for an
// unknown operation or tool rule.
ProcessRoute planRoute(const ImpellerFeatures& features, const ImpellerDimensions& dimensions,
                       std::vector<RouteRule> rules, const std::vector<CuttingTool>& tools);

std::string routeToJson(const ProcessRoute& route);

}  // namespace aeronc::impeller
