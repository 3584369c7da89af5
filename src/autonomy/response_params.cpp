// The onboard response's parameter table (include/evade/autonomy/response.hpp): the one
// declaration of each ResponderConfig field's unit, range and meaning (key prefix
// "node.autonomy."; the burn search's own rows are cam_options_params, under "cam.").
#include <string>

#include "evade/autonomy/response.hpp"

namespace evade::autonomy {
namespace {

using R = ResponderConfig;

const Param<R> kRows[] = {
    EVADE_PARAM_REAL(R, nav_mismatch_sigma, "-", 0.0, 1000.0, true,
                     "refuse an event whose own state is further than this from the node's nav, in sigma"),
    EVADE_PARAM_REAL(R, decision_lead_s, "s", 0.0, 86400.0, false,
                     "no onboard burn sooner than this after the event's veto deadline"),
};

}  // namespace

ParamTable<ResponderConfig> responder_params() noexcept { return make_param_table(kRows); }

std::string validate_responder_config(const ResponderConfig& c) {
  std::string bad = validate_params(responder_params(), c, "node.autonomy.");
  if (bad.empty()) bad = validate_params(cam_options_params(), c.cam, "node.autonomy.cam.");
  return bad;
}

}  // namespace evade::autonomy
