#pragma once
// The knowledge base's side of impeller programming: the rule library (impeller_route_step) and
// the tools its rules choose from (tool, tapered_ball_tool), fed to impeller::planRoute.
#include <aeronc/impeller/ProcessRoute.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <string>
#include <vector>

namespace aeronc::kb {

// The steps of `route` in position order; throws inputError when the route has none.
std::vector<impeller::RouteRule> impellerRouteRules(const KnowledgeBase& kb, const std::string& route = "impeller");
// Face mills, flat and ball end mills, drills and tapered balls.
std::vector<impeller::CuttingTool> impellerTools(const KnowledgeBase& kb);

impeller::ProcessRoute planImpellerRoute(const KnowledgeBase& kb, const impeller::ImpellerFeatures& features,
                                         const impeller::ImpellerDimensions& dimensions,
                                         const std::string& route = "impeller");

}  // namespace aeronc::kb
