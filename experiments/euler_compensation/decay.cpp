// 000 Fig 2: explicit Euler on y' = -alpha y (14), in y and in ybar = Psi(y) of (15); and the field
// (16) as printed, checked against (15).
#include <string>

#include "geomint/analysis/variable_compensation.hpp"
#include "geomint/methods/registry.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/systems/exponential_decay.hpp"

namespace geomint::euler_compensation {
namespace {

void check_decay(const Scene& s) {
  for (const char* key : {"decay.alpha", "decay.printed_alpha"}) {
    const double h = s.real("decay.h"), alpha = s.real(key);
    if (h * alpha > method_info("explicit_euler").real_bound)
      s.reject("decay.h", std::string("explicit Euler on y' = -alpha y is unstable for h > 2/alpha = ") +
                              format_double(2.0 / alpha) + " (alpha = " + key + ")");
    // ybar = ln(y) / alpha (15) needs y > 0: Euler's y_{j+1} = (1 - h alpha) y_j stays positive for h alpha < 1
    if (!(h * alpha < 1))
      s.reject("decay.h", std::string("ybar = ln(y)/alpha of (15) needs y > 0, and explicit Euler's y_{j+1} = (1 - h alpha) y_j "
                                      "is positive only for h < 1/alpha = ") + format_double(1.0 / alpha) + " (alpha = " + key + ")");
  }
}

void run_decay(Context& ctx) {
  const Scene& s = ctx.scene;
  ctx.progress("Fig 2: explicit Euler in y and ybar");
  const ExponentialDecay decay{s.real("decay.alpha")};
  write_compensated_euler_figure(ctx, "fig2_decay", "decay", decay, DecayCompensation{decay.alpha}, s.real("decay.y0"),
                                 s.real("decay.h"), s.integer("decay.steps"));
  // (16) as printed, ybar' = -alpha, in place of the field of (15), at decay.printed_alpha (at the
  // alpha = 1 of Fig 2 the two coincide): the error of Euler in ybar mapped back by (15).
  const ExponentialDecay check{s.real("decay.printed_alpha")};
  ctx.summary["reproduced"]["decay_printed_field_max_rel_err"] =
      compensated_euler_figure(check, DecayCompensation{check.alpha}, DecayFieldAsPrinted16{check.alpha},
                               s.real("decay.y0"), s.real("decay.h"), s.integer("decay.steps"))
          .compensated_max_rel_err;
}

StudyPlan plan_decay(const Scene& s) {
  return compensated_euler_plan(static_cast<double>(s.integer("decay.steps")), 2);
}

}  // namespace

Study decay_study() {
  return {.name = "decay",
          .makes = {{"000", "Fig. 2"}},
          .about = "explicit Euler on y' = -alpha y, in y and in ybar = Psi(y) of (15)",
          .files = {"fig2_decay.csv", "fig2_decay_exact.csv"},
          .keys = Schema()
                      .real("decay.h", positive(), "step of explicit Euler (Fig 2); h alpha < 1 (ybar of (15) defined along the run)")
                      .integer("decay.steps", at_least(1), "number of steps shown in Fig 2")
                      .real("decay.printed_alpha", positive(),
                            "alpha at which the transformed field (16) as printed, ybar' = -alpha, is checked against (15) "
                            "(they coincide at alpha = 1); h alpha < 1"),
          .reads = {"decay"},
          .run = run_decay,
          .validate = check_decay,
          .plan = plan_decay};
}

}  // namespace geomint::euler_compensation
